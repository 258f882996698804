// The kinetic KVD with the reduced and the full certificate sets: exact event
// times, exact batching of simultaneous events, and validation against fresh
// builds between events.
#include <catch2/catch.hpp>
#include <cmath>

#include "kvd/kernel/kernel.hpp"

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/scene/scene_io.hpp"

using namespace kvd;

namespace {
scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }
const Exact_kernel k;

kinetic::Options with(kinetic::Certificate_set set, std::size_t events = 100) {
  kinetic::Options o;
  o.certificates = set;
  o.max_events = events;
  return o;
}
const auto reduced = kinetic::Certificate_set::reduced;
const auto full = kinetic::Certificate_set::full;

void check_increasing_and_valid(const kinetic::Simulation<Exact_time>& sim) {
  CHECK(sim.valid());
  if (!sim.valid()) UNSCOPED_INFO(sim.failure);
  for (std::size_t i = 1; i < sim.batches.size(); ++i) CHECK(k.compare(sim.batches[i - 1].time, sim.batches[i].time) < 0);
}
}  // namespace

TEST_CASE("two triangles: events exactly where the mover's vertices cross the floor's E-plane", "[kinetic]") {
  // The mover's vertices (0,0), (1,0), (0,1) (in x, y) translate by t/2 along
  // x and cross the E-plane 2x + y = 4 of the floor edge (4,-4)-(0,4) at
  // t = 4, 2 and 3. The floor is static and of higher priority, so nothing of
  // it is ever classified against the mover's planes: no other event.
  const auto set = GENERATE(reduced, full);
  const auto sim = kinetic::simulate(k, load("two-triangles.json"), with(set));
  check_increasing_and_valid(sim);
  REQUIRE(sim.batches.size() == 3);
  const long expected[] = {2, 3, 4};
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(sim.batches[i].time.is_rational());
    CHECK(k.compare(sim.batches[i].time, Exact_time(mpq_class(expected[i]))) == 0);
    CHECK(sim.batches[i].changed);
  }
}

TEST_CASE("rotor: simultaneous failures at one algebraic time form one batch", "[kinetic]") {
  const auto set = GENERATE(reduced, full);
  const auto sim = kinetic::simulate(k, load("rotor.json"), with(set));
  check_increasing_and_valid(sim);
  REQUIRE(sim.batches.size() >= 3);
  // The first event is sqrt(2) - 1, the positive root of t^2 + 2t - 1, given
  // by a degree-6 certificate polynomial: several certificates fail there,
  // their roots found equal exactly (by gcd, not by a tolerance).
  const auto& first = sim.batches[0];
  CHECK_FALSE(first.time.is_rational());
  const auto r = k.next_root(Poly<mpq_class>{-1, 2, 1}, Exact_time(mpq_class(0)));
  REQUIRE(r);
  CHECK(k.compare(first.time, *r) == 0);
  CHECK(first.failures() >= 2);
}

TEST_CASE("simulations of moving scenes validate against fresh builds", "[kinetic]") {
  const auto set = GENERATE(reduced, full);
  for (const char* name : {"viewpoint.json", "boxes.json", "random-20.json", "degenerate-vertical-edge.json"}) {
    INFO(name);
    const auto sim = kinetic::simulate(k, load(name), with(set, 25));
    check_increasing_and_valid(sim);
    CHECK(!sim.batches.empty());
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
kinetic::Simulation<Exact_time> run_text(const std::string& json, kinetic::Certificate_set set) {
  return kinetic::simulate(k, scene::read_scene(json, "inline.json"), with(set));
}
}  // namespace

TEST_CASE("lockstep triangles give simultaneous failures in one batch", "[kinetic]") {
  // Two copies of the mover, stacked 5 apart in z, translate together: each
  // of their vertices crosses the floor's E-plane 2x + y = 4 at the same time
  // as its twin.
  const auto set = GENERATE(reduced, full);
  const auto sim = run_text(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 10}, "objects": [
    {"vertices": [[-4,-4,0],[4,-4,0],[0,4,0]], "triangles": [[0,1,2]]},
    {"vertices": [[0,0,1],[1,0,1],[0,1,2]], "triangles": [[0,1,2]], "motion": {"translation": [[0,"1/2"],0,0]}},
    {"vertices": [[0,0,6],[1,0,6],[0,1,7]], "triangles": [[0,1,2]], "motion": {"translation": [[0,"1/2"],0,0]}}]})", set);
  check_increasing_and_valid(sim);
  REQUIRE(sim.batches.size() >= 3);
  for (long t : {2L, 3L, 4L}) {
    bool found = false;
    for (const auto& e : sim.batches)
      if (k.compare(e.time, Exact_time(mpq_class(t))) == 0) found = e.failures() >= 2;
    CHECK(found);
  }
  CHECK(sim.simultaneous_batches >= 3);
}

TEST_CASE("a vertex touching a plane (a double root) is not an event", "[kinetic]") {
  // The far triangle's vertex (10, 0, 0) moves by (t-1)^2 in y: it touches the
  // P-plane y = 0 of the static vertex (0, 0, 0) at t = 1 without crossing it.
  const auto set = GENERATE(reduced, full);
  const auto sim = run_text(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 3}, "objects": [
    {"vertices": [[0,0,0],[4,1,0],[1,3,1]], "triangles": [[0,1,2]]},
    {"vertices": [[10,0,0],[12,"1/2",1],[11,"1/4",2]], "triangles": [[0,1,2]], "motion": {"translation": [0,[1,-2,1],0]}}]})", set);
  check_increasing_and_valid(sim);
  for (const auto& e : sim.batches) CHECK(k.compare(e.time, Exact_time(mpq_class(1))) != 0);
  CHECK(!sim.batches.empty());  // the vertices do cross y = 1 and y = 3 later
}

TEST_CASE("a moving Euclidean decomposition point", "[kinetic]") {
  const auto set = GENERATE(reduced, full);
  const auto sim = run_text(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 6},
    "decomposition": {"x": [1,0,0,0], "z": [[-3,1],0,10,1]}, "objects": [
    {"vertices": [[-1,-1,2],[1,-1,2],[0,1,2]], "triangles": [[0,1,2]]},
    {"vertices": [[-3,-3,-2],[3,-3,-2],[0,3,-2]], "triangles": [[0,1,2]]}]})", set);
  check_increasing_and_valid(sim);
  CHECK(sim.batches.size() >= 2);  // static triangles, yet the moving z makes events
}

TEST_CASE("with --collisions stop a collision stops the simulation at its exact time", "[kinetic]") {
  // The mover's lowest vertex (0, 0, 1) falls at speed 1 onto the floor z = 0.
  auto o = with(GENERATE(reduced, full));
  o.collisions = kinetic::Collisions::stop;
  const auto sim = kinetic::simulate(k, scene::read_scene(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 5}, "objects": [
    {"vertices": [[-4,-4,0],[4,-4,0],[0,4,0]], "triangles": [[0,1,2]]},
    {"vertices": [[0,0,1],[1,0,2],[0,1,3]], "triangles": [[0,1,2]], "motion": {"translation": [0,0,[0,-1]]}}]})",
                                                         "inline.json"), o);
  REQUIRE(sim.collision);
  CHECK(sim.stopped == kinetic::Stop::collision);
  CHECK(sim.motion_changes.empty());
  CHECK(k.compare(sim.time_reached, Exact_time(mpq_class(1))) == 0);
  CHECK(sim.collision->find("collision at t = 1") == 0);
}

namespace {
scene::Scene mixed_scene(std::uint64_t seed, std::size_t triangles, int degree = 2) {
  scene::Uniform_params p;
  p.triangles = triangles;
  p.moving = mpq_class(1, 2);
  p.degree = degree;
  p.seed = seed;
  return scene::read_scene(scene::write_scene(scene::uniform_density(p)), "generated");
}
}  // namespace

TEST_CASE("random mixed scenes validate at every batch", "[kinetic][property]") {
  // Static and moving triangles mixed, linear and quadratic motions, several seeds, the
  // reduced set: every batch is validated against fresh builds; lower bounds
  // on what happened keep a simulation that does nothing from passing.
  std::size_t failures = 0, batches = 0, simultaneous = 0, changed = 0;
  kinetic::Type_counts types{};
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const auto sim = kinetic::simulate(k, mixed_scene(seed, 12, 1 + static_cast<int>(seed % 2)), with(reduced, 120));
    INFO("seed " << seed);
    check_increasing_and_valid(sim);
    failures += sim.failures;
    batches += sim.batches.size();
    simultaneous += sim.simultaneous_batches;
    for (const auto& e : sim.batches) changed += e.changed;
    for (std::size_t i = 0; i < types.size(); ++i) types[i] += sim.failures_by_type[i];
  }
  WARN(failures << " certificate failures in " << batches << " batches (" << simultaneous << " simultaneous, "
                << changed << " changing the tree), all validated");
  CHECK(failures >= 400);
  CHECK(batches >= 100);
  CHECK(changed >= 100);
  CHECK(simultaneous >= 10);
  using T = kinetic::Certificate_type;
  for (T t : {T::VV, T::VE, T::IV, T::II}) {
    INFO(kinetic::to_string(t));
    CHECK(types[static_cast<std::size_t>(t)] >= 5);
  }
}

namespace {
// The trees just after the structure-changing batches (their times are
// compared exactly by the caller).
std::vector<std::string> changes(const kinetic::Simulation<Exact_time>& sim) {
  std::vector<std::string> out;
  for (const auto& b : sim.batches)
    if (b.changed) out.push_back(b.structure);
  return out;
}
}  // namespace

TEST_CASE("the reduced and the full certificate sets see the same structural changes", "[kinetic][reduced]") {
  // Up to the same time, both sets must produce the same sequence of trees at
  // the same times (DESIGN.md section 5): the same structures in order, each
  // reached at an exactly equal time.
  std::vector<scene::Scene> scenes;
  for (std::uint64_t seed = 11; seed <= 14; ++seed) scenes.push_back(mixed_scene(seed, 10));
  for (const char* name : {"rotor.json", "viewpoint.json", "degenerate-vertical-edge.json", "boxes.json"})
    scenes.push_back(load(name));
  std::size_t compared = 0;
  for (const auto& s : scenes) {
    INFO(s.name);
    auto o = with(reduced, 1000);
    o.until = s.start + 6;
    o.validate = kinetic::Validation::none;
    const auto r = kinetic::simulate(k, s, o);
    o.certificates = full;
    const auto f = kinetic::simulate(k, s, o);
    REQUIRE(!r.collision);
    REQUIRE(changes(r) == changes(f));
    std::size_t j = 0;
    for (const auto& b : r.batches) {
      if (!b.changed) continue;
      while (!f.batches[j].changed) ++j;
      CHECK(k.compare(b.time, f.batches[j++].time) == 0);
    }
    compared += changes(r).size();
  }
  WARN(compared << " structural changes compared");
  CHECK(compared >= 50);
}

TEST_CASE("the tree queue and the heap give the same batches", "[kinetic][queue]") {
  for (const auto set : {reduced, full}) {
    auto o = with(set, 150);
    o.validate = kinetic::Validation::none;
    const auto s = mixed_scene(21, 12);
    const auto a = kinetic::simulate(k, s, o);
    o.queue = kinetic::Queue_kind::heap;
    const auto b = kinetic::simulate(k, s, o);
    REQUIRE(a.batches.size() == b.batches.size());
    CHECK(a.batches.size() >= 20);
    for (std::size_t i = 0; i < a.batches.size(); ++i) {
      CHECK(k.compare(a.batches[i].time, b.batches[i].time) == 0);
      CHECK(a.batches[i].failures() == b.batches[i].failures());
    }
    CHECK(a.structure_hash == b.structure_hash);
  }
}

TEMPLATE_TEST_CASE("the floating-point kernels reproduce the exact simulation on unstressed scenes", "[kinetic][float]",
                   kvd::Double_kernel, kvd::Mpfr_kernel) {
  const TestType fk;
  for (const char* name : {"two-triangles.json", "rotor.json", "random-20.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    kinetic::Options o;
    o.max_events = 40;
    const auto exact = kinetic::simulate(k, s, o);
    const auto fp = kinetic::simulate(fk, s, o);
    CHECK(fp.valid());
    REQUIRE(fp.batches.size() == exact.batches.size());
    for (std::size_t i = 0; i < exact.batches.size(); ++i) {
      CHECK(std::abs(fk.to_double(fp.batches[i].time) - exact.batches[i].time.to_double()) < 1e-9);
      CHECK(fp.batches[i].failures() == exact.batches[i].failures());
    }
    CHECK(fp.structure_hash == exact.structure_hash);
  }
}

TEST_CASE("a run that meets no more events has reached the end of its span", "[kinetic]") {
  const Exact_kernel k;
  // two-triangles (span [0, 10]) up to its last event, then nothing until 10.
  const auto all = kinetic::simulate(k, load("two-triangles.json"), with(reduced, 1000));
  CHECK((all.stopped == kinetic::Stop::limit || all.stopped == kinetic::Stop::exhausted));
  CHECK(k.compare(all.time_reached, Exact_time(mpq_class(10))) == 0);
  // Stopped by the event limit: the last batch's time, before the end.
  const auto first = kinetic::simulate(k, load("two-triangles.json"), with(reduced, 1));
  CHECK(first.stopped == kinetic::Stop::events);
  CHECK(k.compare(first.time_reached, first.batches.back().time) == 0);
  CHECK(k.compare(first.time_reached, Exact_time(mpq_class(10))) < 0);
  // --until: the limit itself.
  auto o = with(reduced, 1000);
  o.until = mpq_class(1, 2);
  const auto until = kinetic::simulate(k, load("two-triangles.json"), o);
  CHECK(k.compare(until.time_reached, Exact_time(mpq_class(1, 2))) == 0);
}
