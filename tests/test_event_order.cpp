// The event-order record of kvd certify, checked against CGAL's algebraic
// kernel: every event interval isolates exactly one root of its polynomial
// with the stated multiplicity, the claimed "<" and "=" hold, and the
// intervals line up with the batches of the simulation.
#include <catch2/catch.hpp>

#include <algorithm>

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
