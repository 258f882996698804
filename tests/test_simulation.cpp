// The kinetic KVD with the full certificate set: exact event times, exact
// batching of simultaneous events, and validation against fresh builds
// between events.
#include <catch2/catch.hpp>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kinetic/full_simulation.hpp"
#include "kvd/scene/scene_io.hpp"

using namespace kvd;

namespace {
scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }
const Exact_kernel k;

void check_increasing_and_valid(const kinetic::Full_simulation& sim) {
  CHECK(sim.valid);
  if (!sim.valid) UNSCOPED_INFO(sim.failure);
  for (std::size_t i = 1; i < sim.events.size(); ++i) CHECK(k.compare(sim.events[i - 1].time, sim.events[i].time) < 0);
}
}  // namespace

TEST_CASE("two triangles: events exactly where the mover's vertices cross the floor's E-plane", "[kinetic]") {
  // The mover's vertices (0,0), (1,0), (0,1) (in x, y) translate by t/2 along
  // x and cross the E-plane 2x + y = 4 of the floor edge (4,-4)-(0,4) at
  // t = 4, 2 and 3. The floor is static and of higher priority, so nothing of
  // it is ever classified against the mover's planes: no other event.
  const auto sim = kinetic::simulate_full(load("two-triangles.json"), {});
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
  const auto sim = kinetic::simulate_full(load("rotor.json"), {});
  check_increasing_and_valid(sim);
  REQUIRE(sim.events.size() >= 3);
  // The first event is sqrt(2) - 1, the positive root of t^2 + 2t - 1, given
  // by a degree-6 certificate polynomial: three distinct polynomials fail
  // there, found equal exactly (by gcd, not by a tolerance).
  const auto& first = sim.events[0];
  CHECK_FALSE(first.time.is_rational());
  const auto r = k.next_root(Poly<mpq_class>{-1, 2, 1}, Exact_time(mpq_class(0)));
  REQUIRE(r);
  CHECK(k.compare(first.time, *r) == 0);
  CHECK(first.failing == 3);
}

TEST_CASE("simulations of moving scenes validate against fresh builds", "[kinetic]") {
  for (const char* name : {"viewpoint.json", "boxes.json", "random-20.json", "degenerate-vertical-edge.json"}) {
    INFO(name);
    kinetic::Full_options o;
    o.max_events = 15;
    const auto sim = kinetic::simulate_full(load(name), o);
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
