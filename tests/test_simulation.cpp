// The kinetic KVD with the full certificate set: exact event times, exact
// batching of simultaneous events, and validation against fresh builds
// between events.
#include <catch2/catch.hpp>
#include <cmath>

#include "kvd/kernel/kernel.hpp"

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kinetic/full_simulation.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/scene/scene_io.hpp"

using namespace kvd;

namespace {
scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }
const Exact_kernel k;

void check_increasing_and_valid(const kinetic::Full_simulation<Exact_time>& sim) {
  CHECK(sim.valid());
  if (!sim.valid()) UNSCOPED_INFO(sim.failure);
  for (std::size_t i = 1; i < sim.events.size(); ++i) CHECK(k.compare(sim.events[i - 1].time, sim.events[i].time) < 0);
}
}  // namespace

TEST_CASE("two triangles: events exactly where the mover's vertices cross the floor's E-plane", "[kinetic]") {
  // The mover's vertices (0,0), (1,0), (0,1) (in x, y) translate by t/2 along
  // x and cross the E-plane 2x + y = 4 of the floor edge (4,-4)-(0,4) at
  // t = 4, 2 and 3. The floor is static and of higher priority, so nothing of
  // it is ever classified against the mover's planes: no other event.
  const auto sim = kinetic::simulate_full(k, load("two-triangles.json"), {});
  check_increasing_and_valid(sim);
  REQUIRE(sim.events.size() == 3);
  const long expected[] = {2, 3, 4};
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(sim.events[i].time.is_rational());
    CHECK(k.compare(sim.events[i].time, Exact_time(mpq_class(expected[i]))) == 0);
    CHECK(sim.events[i].changed);
  }
}

TEST_CASE("rotor: simultaneous failures at one algebraic time form one batch", "[kinetic]") {
  const auto sim = kinetic::simulate_full(k, load("rotor.json"), {});
  check_increasing_and_valid(sim);
  REQUIRE(sim.events.size() >= 3);
  // The first event is sqrt(2) - 1, the positive root of t^2 + 2t - 1, given
  // by a degree-6 certificate polynomial: several certificates fail there,
  // their roots found equal exactly (by gcd, not by a tolerance).
  const auto& first = sim.events[0];
  CHECK_FALSE(first.time.is_rational());
  const auto r = k.next_root(Poly<mpq_class>{-1, 2, 1}, Exact_time(mpq_class(0)));
  REQUIRE(r);
  CHECK(k.compare(first.time, *r) == 0);
  CHECK(first.failing() >= 2);
}

TEST_CASE("simulations of moving scenes validate against fresh builds", "[kinetic]") {
  for (const char* name : {"viewpoint.json", "boxes.json", "random-20.json", "degenerate-vertical-edge.json"}) {
    INFO(name);
    kinetic::Full_options o;
    o.max_events = 25;
    const auto sim = kinetic::simulate_full(k, load(name), o);
    check_increasing_and_valid(sim);
    CHECK(!sim.events.empty());
  }
}

TEST_CASE("a rational strictly between two exact times", "[kinetic]") {
  const auto s2 = k.next_root(Poly<mpq_class>{-2, 0, 1}, Exact_time(mpq_class(0)));
  mpq_class eps(1);
  eps /= mpz_class(1) << 100;
  const auto close = k.next_root(Poly<mpq_class>{-eps, 1} * Poly<mpq_class>{-eps, 1} - Poly<mpq_class>{2}, Exact_time(mpq_class(0)));
  const mpq_class m = kinetic::rational_between(*s2, *close);  // sqrt2 < m < sqrt2 + 2^-100
  CHECK(k.compare(*s2, Exact_time(m)) < 0);
  CHECK(k.compare(Exact_time(m), *close) < 0);
  CHECK(kinetic::rational_between(Exact_time(mpq_class(1)), Exact_time(mpq_class(2))) == mpq_class(3, 2));
}

namespace {
kinetic::Full_simulation<Exact_time> run_text(const std::string& json) {
  return kinetic::simulate_full(k, scene::read_scene(json, "inline.json"), {});
}
}  // namespace

TEST_CASE("lockstep triangles give simultaneous failures in one batch", "[kinetic]") {
  // Two copies of the mover, stacked 5 apart in z, translate together: each
  // of their vertices crosses the floor's E-plane 2x + y = 4 at the same time
  // as its twin.
  const auto sim = run_text(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 10}, "objects": [
    {"vertices": [[-4,-4,0],[4,-4,0],[0,4,0]], "triangles": [[0,1,2]]},
    {"vertices": [[0,0,1],[1,0,1],[0,1,2]], "triangles": [[0,1,2]], "motion": {"translation": [[0,"1/2"],0,0]}},
    {"vertices": [[0,0,6],[1,0,6],[0,1,7]], "triangles": [[0,1,2]], "motion": {"translation": [[0,"1/2"],0,0]}}]})");
  check_increasing_and_valid(sim);
  REQUIRE(sim.events.size() >= 3);
  for (long t : {2L, 3L, 4L}) {
    bool found = false;
    for (const auto& e : sim.events)
      if (k.compare(e.time, Exact_time(mpq_class(t))) == 0) found = e.failing() >= 2;
    CHECK(found);
  }
  CHECK(sim.simultaneous_batches >= 3);
}

TEST_CASE("a vertex touching a plane (a double root) is not an event", "[kinetic]") {
  // The far triangle's vertex (10, 0, 0) moves by (t-1)^2 in y: it touches the
  // P-plane y = 0 of the static vertex (0, 0, 0) at t = 1 without crossing it.
  const auto sim = run_text(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 3}, "objects": [
    {"vertices": [[0,0,0],[4,1,0],[1,3,1]], "triangles": [[0,1,2]]},
    {"vertices": [[10,0,0],[12,"1/2",1],[11,"1/4",2]], "triangles": [[0,1,2]], "motion": {"translation": [0,[1,-2,1],0]}}]})");
  check_increasing_and_valid(sim);
  for (const auto& e : sim.events) CHECK(k.compare(e.time, Exact_time(mpq_class(1))) != 0);
  CHECK(!sim.events.empty());  // the vertices do cross y = 1 and y = 3 later
}

TEST_CASE("a moving Euclidean decomposition point", "[kinetic]") {
  const auto sim = run_text(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 6},
    "decomposition": {"x": [1,0,0,0], "z": [[-3,1],0,10,1]}, "objects": [
    {"vertices": [[-1,-1,2],[1,-1,2],[0,1,2]], "triangles": [[0,1,2]]},
    {"vertices": [[-3,-3,-2],[3,-3,-2],[0,3,-2]], "triangles": [[0,1,2]]}]})");
  check_increasing_and_valid(sim);
  CHECK(sim.events.size() >= 2);  // static triangles, yet the moving z makes events
}

TEST_CASE("a collision stops the simulation at its exact time", "[kinetic]") {
  // The mover's lowest vertex (0, 0, 1) falls at speed 1 onto the floor z = 0.
  const auto sim = run_text(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 5}, "objects": [
    {"vertices": [[-4,-4,0],[4,-4,0],[0,4,0]], "triangles": [[0,1,2]]},
    {"vertices": [[0,0,1],[1,0,2],[0,1,3]], "triangles": [[0,1,2]], "motion": {"translation": [0,0,[0,-1]]}}]})");
  REQUIRE(sim.collision);
  CHECK(k.compare(sim.time_reached, Exact_time(mpq_class(1))) == 0);
  CHECK(sim.collision->find("collision at t = 1") == 0);
}

TEST_CASE("random mixed scenes validate at every batch", "[kinetic][property]") {
  // Static and moving triangles mixed, quadratic motions, several seeds: every
  // batch is validated against fresh builds; lower bounds on what happened
  // keep a simulation that does nothing from passing.
  std::size_t failures = 0, batches = 0, simultaneous = 0, changed = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    scene::Uniform_params p;
    p.triangles = 12;
    p.moving = mpq_class(1, 2);
    p.degree = 2;
    p.seed = seed;
    const scene::Scene s = scene::read_scene(scene::write_scene(scene::uniform_density(p)), "generated");
    kinetic::Full_options o;
    o.max_events = 120;
    const auto sim = kinetic::simulate_full(k, s, o);
    INFO("seed " << seed);
    check_increasing_and_valid(sim);
    failures += sim.failures;
    batches += sim.events.size();
    simultaneous += sim.simultaneous_batches;
    for (const auto& e : sim.events) changed += e.changed;
  }
  WARN(failures << " certificate failures in " << batches << " batches (" << simultaneous << " simultaneous, "
                << changed << " changing the tree), all validated");
  CHECK(failures >= 400);
  CHECK(batches >= 100);
  CHECK(changed >= 100);
  CHECK(simultaneous >= 10);
}

TEMPLATE_TEST_CASE("the floating-point kernels reproduce the exact simulation on unstressed scenes", "[kinetic][float]",
                   kvd::Double_kernel, kvd::Mpfr_kernel) {
  const TestType fk;
  for (const char* name : {"two-triangles.json", "rotor.json", "random-20.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    kinetic::Full_options o;
    o.max_events = 40;
    const auto exact = kinetic::simulate_full(k, s, o);
    const auto fp = kinetic::simulate_full(fk, s, o);
    CHECK(fp.valid());
    REQUIRE(fp.events.size() == exact.events.size());
    for (std::size_t i = 0; i < exact.events.size(); ++i) {
      CHECK(std::abs(fk.to_double(fp.events[i].time) - exact.events[i].time.to_double()) < 1e-9);
      CHECK(fp.events[i].failing() == exact.events[i].failing());
    }
    CHECK(fp.structure_hash == exact.structure_hash);
  }
}
