// Builds a scene in code, steps the exact kinetic KVD event by event, turns
// an object back between two events (a flight-plan change) and prints the
// painter's order: the library through its installed headers and KVD::kvd.
#include <iostream>

#include "kvd/kvd.hpp"

int main() {
  // A floor and a triangle sliding over it along x, both exact.
  const kvd::scene::Scene scene = kvd::scene::read_scene(R"({"format": "kvd-scene/1",
      "time": {"start": 0, "end": 10},
      "objects": [{"vertices": [[-4, -4, 0], [4, -4, 0], [0, 4, 0]], "triangles": [[0, 1, 2]]},
                  {"vertices": [[0, 0, 1], [1, 0, 1], [0, 1, 2]], "triangles": [[0, 1, 2]],
                   "motion": {"translation": [[0, "1/2"], 0, 0]}}]})", "in-code scene");
  const kvd::Exact_kernel k;
  kvd::Kinetic_kvd<kvd::Exact_kernel> kds(k, scene);
  const auto print = [&](const auto& batch) {
    std::cout << "t = " << k.to_string(batch.time) << ": " << batch.failures() << " certificate(s) fail\n";
  };
  kds.advance_to(mpq_class(5));
  for (const auto& batch : kds.record().batches) print(batch);
  // At t = 5 the triangle (at x + 5/2) turns back: x(t) = 5 - t/2 from then on.
  kvd::scene::Motion back;
  back.kind = kvd::scene::Motion::Kind::translation;
  back.translation = {kvd::scene::QPoly({mpq_class(5), mpq_class(-1, 2)}), kvd::scene::QPoly(), kvd::scene::QPoly()};
  kds.set_motion(1, back, mpq_class(5));
  while (const auto* batch = kds.advance()) print(*batch);
  std::cout << "structure at the end: " << kds.structure_hash() << "\nback to front from (0, 0, 50):";
  for (int n : kds.back_to_front(kvd::Point4<mpq_class>{{0, 0, 50, 1}}))
    std::cout << " T(" << kds.tree().nodes[static_cast<std::size_t>(n)].cut.id << ")";
  std::cout << "\nvalidated against fresh builds: " << (kds.record().valid() ? "yes" : "no") << "\n";
  return kds.record().valid() ? 0 : 1;
}
