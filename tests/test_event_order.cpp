// The event-order record of kvd certify, checked against CGAL's algebraic
// kernel: every event interval isolates exactly one root of its polynomial
// with the stated multiplicity, the claimed "<" and "=" hold, and the
// intervals line up with the batches of the simulation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>

#include "kvd/kinetic/event_order.hpp"
#include "kvd/scene/scene_io.hpp"
#include "cgal_roots.hpp"

using namespace kvd;

namespace {

scene::Scene load(const std::string& name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }

// The CGAL root of p inside the closed [lo, hi], which must be the only one.
std::size_t only_root(const oracle::Cgal_roots& r, const mpq_class& lo, const mpq_class& hi) {
  std::vector<std::size_t> inside;
  for (std::size_t i = 0; i < r.size(); ++i)
    if (r.compare(i, lo) >= 0 && r.compare(i, hi) <= 0) inside.push_back(i);
  REQUIRE(inside.size() == 1);
  return inside.front();
}

}  // namespace

TEST_CASE("event order: isolating intervals, multiplicities and order agree with CGAL", "[certify]") {
  const std::string name = GENERATE(as<std::string>{}, "two-triangles.json", "rotor.json", "viewpoint.json",
                                    "boxes.json", "random-20.json", "degenerate-vertical-edge.json");
  INFO(name);
  kinetic::Options o;
  o.max_events = 60;
  o.validate = kinetic::Validation::none;
  kinetic::Event_order_recorder recorder;
  const auto sim = kinetic::simulate(Exact_kernel(), load(name), o, &recorder);
  const kinetic::Event_order order = recorder.take();

  REQUIRE(order.events.size() == sim.failures);
  // One interval from the start and one after every batch.
  CHECK(order.intervals.size() == sim.batches.size() + 1);
  std::size_t batch = 0;
  const zpoly::ZPoly* previous = nullptr;
  mpq_class previous_lo, previous_hi;
  for (const auto& e : order.events) {
    const auto& p = order.certificates.at(e.certificate).polynomial;
    const oracle::Cgal_roots roots(p);
    const std::size_t i = only_root(roots, e.lo, e.hi);
    CHECK(roots.multiplicity(i) == e.multiplicity);
    CHECK(e.multiplicity % 2 == 1);
    if (!e.equal_to_previous && previous) ++batch;
    // The failing certificate was in force on the interval ending here.
    const auto& active = order.intervals.at(batch);
    CHECK(std::find(active.begin(), active.end(), e.certificate) != active.end());
    if (previous) {
      // Compare with the previous event's time through its square-free part.
      const zpoly::ZPoly q = zpoly::square_free(*previous);
      const int c = previous_lo == previous_hi ? roots.compare(i, previous_lo) : roots.compare(i, q, previous_lo, previous_hi);
      CHECK(c == (e.equal_to_previous ? 0 : 1));
    }
    previous = &p;
    previous_lo = e.lo;
    previous_hi = e.hi;
  }
  if (!order.events.empty()) CHECK(batch + 1 == sim.batches.size());
}

TEST_CASE("event order through collisions: each motion change fails where CGAL says, after its reversal",
          "[certify][collision]") {
  // data/collisions.json: contacts at exactly 2, 3, 4 and 6 (proofs/collision_response.md).
  kinetic::Options o;
  o.max_events = 200;
  o.validate = kinetic::Validation::none;
  kinetic::Event_order_recorder recorder;
  const auto sim = kinetic::simulate(Exact_kernel(), load("collisions.json"), o, &recorder);
  const kinetic::Event_order order = recorder.take();

  REQUIRE(order.motion_changes.size() == sim.motion_changes.size());
  // One interval from the start, one after every batch and every motion change.
  CHECK(order.intervals.size() == 1 + sim.batches.size() + sim.motion_changes.size());
  const std::vector<int> contacts{2, 3, 4, 6};
  for (std::size_t i = 0; i < order.motion_changes.size(); ++i) {
    const auto& c = order.motion_changes[i];
    const auto& s = sim.motion_changes[i];
    INFO("motion change " << i);
    CHECK(c.time == s.time);
    CHECK(c.objects == s.objects);
    CHECK(c.motions == s.motions);
    CHECK(c.after_events == std::accumulate(sim.batches.begin(), sim.batches.begin() + s.batches_before, std::size_t{0},
                                            [](std::size_t n, const auto& b) { return n + b.failures(); }));
    REQUIRE(!c.failing.empty());
    for (const auto& f : c.failing) {
      const auto& p = order.certificates.at(f.certificate).polynomial;
      const oracle::Cgal_roots roots(p);
      const std::size_t r = only_root(roots, f.lo, f.hi);
      CHECK(roots.multiplicity(r) == f.multiplicity);
      CHECK(roots.compare(r, mpq_class(contacts[i])) == 0);  // the contact
      CHECK(roots.compare(r, c.time) > 0);                  // after the reversal
      // Made of the motions before the change, and in force up to it.
      CHECK(order.certificates[f.certificate].motions == i);
    }
    // The reversal comes after the last event before it.
    if (c.after_events > 0) {
      const auto& e = order.events[c.after_events - 1];
      const oracle::Cgal_roots roots(order.certificates[e.certificate].polynomial);
      CHECK(roots.compare(only_root(roots, e.lo, e.hi), c.time) < 0);
    }
  }
  // Every certificate in force after change i is made of the motions after it.
  std::size_t interval = 0;
  kinetic::in_run_order(
      sim, [&](std::size_t c) {
        ++interval;
        for (std::size_t id : order.intervals[interval]) CHECK(order.certificates[id].motions == c + 1);
      },
      [&](std::size_t) { ++interval; });
}
