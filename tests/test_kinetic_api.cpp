// The stepping API (include/kvd/kvd.hpp), through the public header alone:
// stepping a Kinetic_kvd gives the same run as kinetic::simulate, batch for
// batch, and its queries between events agree with fresh builds.
#include <catch2/catch.hpp>
#include <map>
#include <string>

#include "kernels.hpp"
#include "kvd/kvd.hpp"

namespace {

kvd::scene::Scene bundled(const std::string& name) {
  return kvd::scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name);
}

template <class K>
void same_batch(const K& k, const kvd::kinetic::Batch<typename K::Time>& a, const kvd::kinetic::Batch<typename K::Time>& b) {
  CHECK(k.to_string(a.time) == k.to_string(b.time));
  CHECK(a.failing == b.failing);
  CHECK(a.changed == b.changed);
  CHECK(a.structure == b.structure);
  CHECK(a.certificates == b.certificates);
  CHECK(a.certificates_recomputed == b.certificates_recomputed);
}

}  // namespace

TEMPLATE_TEST_CASE("stepping a Kinetic_kvd gives the batches, trees and stops of simulate", "[api]", KVD_ALL_KERNELS) {
  const TestType k;
  for (const char* name : {"two-triangles.json", "boxes.json", "collisions.json", "uniform-scale-25.json", "viewpoint.json"}) {
    CAPTURE(name);
    const auto s = bundled(name);
    kvd::kinetic::Options o;
    o.max_events = 60;
    o.validate = kvd::kinetic::Validation::none;
    const auto whole = kvd::kinetic::simulate(k, s, o);
    kvd::Kinetic_kvd<TestType> stepped(k, s, o);
    std::size_t i = 0;
    while (const auto* b = stepped.advance()) {
      REQUIRE(i < whole.batches.size());
      same_batch(k, *b, whole.batches[i]);
      CHECK(stepped.structure_hash() == b->structure);
      // Kept along the changed paths: the hash of the whole tree.
      CHECK(stepped.structure_hash() == kvd::tree::structure_hash(stepped.tree()));
      ++i;
    }
    CHECK(i == whole.batches.size());
    CHECK(stepped.stopped());
    CHECK(!stepped.next_event_time());
    CHECK(stepped.advance() == nullptr);  // a stopped run stays stopped
    const auto& r = stepped.record();
    CHECK(r.stopped == whole.stopped);
    CHECK(r.failures == whole.failures);
    CHECK(r.motion_changes.size() == whole.motion_changes.size());
    CHECK(r.structure_hash == whole.structure_hash);
    CHECK(k.to_string(r.time_reached) == k.to_string(whole.time_reached));
  }
}

TEST_CASE("the structure hash kept along changed paths is the whole tree's after every batch", "[api]") {
  const kvd::Exact_kernel k;
  for (const char* name : {"random-20.json", "rotor.json", "cycle3.json", "collisions.json", "uniform-density-50.json",
                           "uniform-scale-100.json", "stiff/tangential.json", "stiff/simultaneous.json"}) {
    CAPTURE(name);
    const auto s = bundled(name);
    kvd::kinetic::Options o;
    o.max_events = 40;
    kvd::Kinetic_kvd<kvd::Exact_kernel> stepped(k, s, o);
    kvd::tree::Kvd_tree before = stepped.tree();
    std::size_t changes = 0;
    while (const auto* b = stepped.advance()) {
      CHECK(stepped.structure_hash() == kvd::tree::structure_hash(stepped.tree()));
      // Whether the batch changed the tree, node for node (a motion change
      // in the same step changes the tree before the batch).
      const std::size_t now_changes = stepped.record().motion_changes.size();
      if (now_changes == changes) CHECK(b->changed == kvd::tree::first_difference(before, stepped.tree()).has_value());
      changes = now_changes;
      before = stepped.tree();
    }
    CHECK(stepped.record().valid());
  }
}

TEST_CASE("advance_to stops at a time, and the queries between events agree with fresh builds", "[api]") {
  const kvd::Exact_kernel k;
  const auto s = bundled("uniform-scale-25.json");
  kvd::kinetic::Options o;
  o.max_events = 40;
  const auto whole = kvd::kinetic::simulate(k, s, o);
  REQUIRE(whole.batches.size() > 10);
  kvd::Kinetic_kvd<kvd::Exact_kernel> stepped(k, s, o);
  // Up to the 10th batch's time: exactly the first ten batches.
  const mpq_class t = kvd::kinetic::rational_between(whole.batches[9].time, whole.batches[10].time);
  CHECK(stepped.advance_to(t) == 10);
  CHECK(k.compare(stepped.now(), whole.batches[9].time) == 0);
  CHECK(k.compare(*stepped.next_event_time(), whole.batches[10].time) == 0);
  const kvd::Point4<mpq_class> view{{mpq_class(20), mpq_class(-60), mpq_class(140), mpq_class(1)}};
  for (int step = 0; step < 5; ++step) {
    // The tree in force, its certificates and its painter's order, against a
    // fresh build at an instant inside the interval.
    const mpq_class inside = kvd::kinetic::rational_between(stepped.now(), *stepped.next_event_time());
    const kvd::predicates::Classifier<kvd::Exact_kernel> c(k, s);
    const auto fresh = kvd::tree::build(c, kvd::Exact_time(inside));
    CHECK(kvd::tree::structure_hash(fresh) == stepped.structure_hash());
    // Node indices differ (the kinetic tree reuses slots), and fragments may
    // start at another corner: compare the canonical fragments.
    const auto named = [](const kvd::tree::Kvd_tree& t, const std::vector<int>& order) {
      std::vector<std::string> out;
      for (int i : order) out.push_back(kvd::tree::to_string(kvd::tree::canonical(t.nodes[static_cast<std::size_t>(i)].fragment)));
      return out;
    };
    CHECK(named(fresh, kvd::query::back_to_front(c, fresh, view, inside)) ==
          named(stepped.tree(), stepped.back_to_front(view)));
    CHECK(stepped.certificates().size() == whole.batches[10 + static_cast<std::size_t>(step)].certificates);
    REQUIRE(stepped.advance() != nullptr);
  }
}

TEST_CASE("set_motion gives the tree and later events of the scene whose motion is split there", "[api]") {
  const kvd::Exact_kernel k;
  const auto s = bundled("uniform-scale-25.json");
  kvd::kinetic::Options o;
  o.max_events = 40;  // validated every batch (the default)
  const auto whole = kvd::kinetic::simulate(k, s, o);
  REQUIRE(whole.batches.size() > 12);
  const mpq_class t0 = kvd::kinetic::rational_between(whole.batches[5].time, whole.batches[6].time);
  // Object 3 turns back at t0 at twice its speed: the same place at t0.
  const std::size_t object = 3;
  kvd::scene::Motion turned = s.objects[object].motion;
  REQUIRE(turned.kind == kvd::scene::Motion::Kind::translation);
  for (auto& p : turned.translation) {
    const mpq_class v = p.derivative()(t0);
    p = kvd::Poly<mpq_class>(std::vector<mpq_class>{mpq_class(p(t0) + 2 * v * t0), mpq_class(-2 * v)});
  }
  kvd::Kinetic_kvd<kvd::Exact_kernel> changed(k, s, o);
  REQUIRE(changed.advance_to(t0) == 6);
  CHECK_THROWS_AS(changed.set_motion(99, turned, t0), std::invalid_argument);
  CHECK_THROWS_AS(changed.set_motion(object, turned, t0 + 1000), std::invalid_argument);  // past the next event
  changed.set_motion(object, turned, t0);
  // The piecewise scene, split at t0: it starts there with the new motion.
  kvd::scene::Scene split = s;
  split.start = t0;
  split.objects[object].motion = turned;
  kvd::kinetic::Options rest = o;
  rest.max_events = o.max_events - changed.record().failures;
  const auto after = kvd::kinetic::simulate(k, split, rest);
  REQUIRE(after.valid());
  const kvd::predicates::Classifier<kvd::Exact_kernel> c(k, split);
  const kvd::tree::Kvd_tree fresh = kvd::tree::build(c, kvd::Exact_time(t0));
  CHECK(changed.structure_hash() == kvd::tree::structure_hash(fresh));
  // Only the certificates naming the object's features were made again (and
  // the others of the nodes holding them), yet the set in force is the
  // fresh tree's: the rest kept their polynomials.
  std::map<kvd::kinetic::Certificate_key, std::vector<std::vector<mpq_class>>> in_force, made;
  for (const auto& cert : changed.certificates())
    for (const auto& q : cert.polys) in_force[cert.key].push_back(q.coefficients());
  for (const auto& cert : kvd::kinetic::reduced_certificates(c, fresh, kvd::Exact_time(t0)))
    for (const auto& q : cert.polys) made[cert.key].push_back(q.coefficients());
  CHECK(in_force == made);
  const auto& change = changed.record().motion_changes.at(0);
  CHECK(change.certificates == in_force.size());
  CHECK(change.certificates_recomputed > 0);
  CHECK(change.certificates_recomputed * 2 < change.certificates);
  std::size_t i = 0;
  while (const auto* b = changed.advance()) {
    REQUIRE(i < after.batches.size());
    same_batch(k, *b, after.batches[i]);
    ++i;
  }
  CHECK(i == after.batches.size());
  CHECK(i > 0);
  CHECK(changed.record().valid());
  CHECK(changed.record().structure_hash == after.structure_hash);
  REQUIRE(changed.record().motion_changes.size() == 1);
  CHECK(changed.record().motion_changes[0].contact == "flight-plan change");
  // Different motions, different events: the split run is not the unchanged one.
  bool differs = after.batches.size() != whole.batches.size() - 6;
  for (std::size_t j = 0; !differs && j < after.batches.size(); ++j)
    differs = after.batches[j].failing != whole.batches[6 + j].failing ||
              k.compare(after.batches[j].time, whole.batches[6 + j].time) != 0;
  CHECK(differs);
}
