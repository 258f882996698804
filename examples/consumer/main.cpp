// Builds a scene in code, runs the exact kinetic KVD over it, and prints the
// events and the back-to-front order at the end: the library through its
// installed headers and KVD::kvd alone.
#include <iostream>

#include "kvd/kinetic/simulation.hpp"
#include "kvd/query/visibility.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"

int main() {
  // A floor and a triangle sliding over it along x, both exact.
  const kvd::scene::Scene scene = kvd::scene::read_scene(R"({"format": "kvd-scene/1",
      "time": {"start": 0, "end": 10},
      "objects": [{"vertices": [[-4, -4, 0], [4, -4, 0], [0, 4, 0]], "triangles": [[0, 1, 2]]},
                  {"vertices": [[0, 0, 1], [1, 0, 1], [0, 1, 2]], "triangles": [[0, 1, 2]],
                   "motion": {"translation": [[0, "1/2"], 0, 0]}}]})",
                                                         "in-code scene");
  const kvd::Exact_kernel k;
  const auto sim = kvd::kinetic::simulate(k, scene, kvd::kinetic::Options{});
  for (const auto& batch : sim.batches)
    std::cout << "t = " << k.to_string(batch.time) << ": " << batch.failures() << " certificate(s) fail\n";
  // The tree at the end of the span, and its fragments back to front as seen from above.
  const mpq_class end(10);
  const kvd::predicates::Classifier<kvd::Exact_kernel> classifier(k, scene);
  const kvd::tree::Kvd_tree tree = kvd::tree::build(classifier, kvd::Exact_time(end));
  std::cout << "structure at t = 10: " << kvd::tree::structure_hash(tree) << "\nback to front from (0, 0, 50):";
  for (int n : kvd::query::back_to_front(classifier, tree, kvd::Point4<mpq_class>{{0, 0, 50, 1}}, end))
    std::cout << " T(" << tree.nodes[static_cast<std::size_t>(n)].cut.id << ")";
  std::cout << "\nvalidated against fresh builds: " << (sim.valid() ? "yes" : "no") << "\n";
  return sim.valid() ? 0 : 1;
}
