// The differential harness: matching rules on hand-made records, exact time
// errors, and the floating-point kernels against the exact one on bundled
// scenes (agreement where nothing is stiff, divergence found where it is,
// recovery instead of a crash where rounding breaks a build).
#include <catch2/catch.hpp>
#include <functional>
#include <string>
#include <vector>

#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/kinetic/differential.hpp"
#include "kvd/scene/scene_io.hpp"

using namespace kvd;
using kinetic::Certificate_type;
using kinetic::Failure;

namespace {

scene::Scene load(const std::string& name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }

template <class Time>
void add(kinetic::Simulation<Time>& sim, Time t, std::vector<Failure> failing, std::string structure) {
  kinetic::Batch<Time> b;
  b.time = std::move(t);
  b.failing = std::move(failing);
  b.structure = std::move(structure);
  sim.batches.push_back(std::move(b));
}

using SV = symbolic::Symbolic_vertex;
using SP = symbolic::Symbolic_plane;
const Failure A{Certificate_type::VV, SV::endpoint(1), SP{SP::Kind::P, 2}};
const Failure B{Certificate_type::VE, SV::endpoint(2), SP{SP::Kind::E, 3}};
const Failure C{Certificate_type::IV, SV::intersection(1, 2), SP{SP::Kind::P, 4}};
const Failure D{Certificate_type::VT, SV::endpoint(5), SP{SP::Kind::T, 6}};
const Failure X{Certificate_type::ET, SV::intersection(7, 8), SP{SP::Kind::E, 8}};

Exact_time exact(long n, long d = 1) { return Exact_time(mpq_class(n, d)); }

}  // namespace

TEST_CASE("differential: matching by features and occurrence, order, structure, missed and spurious", "[differential]") {
  // Exact: {A} at 1, {B, C} at 2, {A} at 3, {D} at 4.
  kinetic::Simulation<Exact_time> x;
  add(x, exact(1), {A}, "s1");
  add(x, exact(2), {B, C}, "s2");
  add(x, exact(3), {A}, "s3");
  add(x, exact(4), {D}, "s4");
  // Inexact: A slightly late; B and C split into two batches (C is out of
  // order); a spurious X; the second A with another tree after it; D missed.
  kinetic::Simulation<double> y;
  add(y, 1.0 + 0x1p-40, {A}, "s1");
  add(y, 2.0, {B}, "s2");
  add(y, 2.0 + 0x1p-30, {C}, "s2");
  add(y, 2.5, {X}, "sX");
  add(y, 3.0, {A}, "other");
  const kinetic::Differential d = kinetic::compare_runs(x, y);
  REQUIRE(d.events.size() == 5);
  REQUIRE(d.inexact.size() == 5);
  CHECK(d.events[0].inexact_event == 0u);
  CHECK(d.events[1].inexact_event == 1u);
  CHECK(d.events[2].inexact_event == 2u);
  CHECK(d.events[3].inexact_event == 4u);  // the second A matches the second A
  CHECK_FALSE(d.events[4].inexact_event);
  CHECK(d.events[0].in_order);
  CHECK(d.events[1].in_order);
  CHECK_FALSE(d.events[2].in_order);  // together with B in the exact run, after it here
  CHECK(d.events[3].in_order);
  CHECK(d.events[0].structure_equal);
  CHECK_FALSE(d.events[3].structure_equal);
  CHECK_FALSE(d.inexact[3].exact_event);
  CHECK(d.order_mismatches == 1);
  CHECK(d.missed_events == 1);
  CHECK(d.spurious_events == 1);
  CHECK(d.structure_mismatches == 1);  // the second A; C has the tree "s2" after it in both runs
  CHECK(d.first_divergence_event == 2u);
  // Time errors are exact against rational times.
  CHECK(d.events[0].time_error == mpq_class(1, 1L << 40));
  CHECK(d.events[2].time_error == mpq_class(1, 1L << 30));
  CHECK(*d.events[2].relative_time_error == mpq_class(1, 1L << 31));
  CHECK(d.max_time_error == mpq_class(1, 1L << 30));
}

TEST_CASE("differential: the first divergence can be a spurious event, or come after the last exact event",
          "[differential]") {
  kinetic::Simulation<Exact_time> x;
  add(x, exact(1), {A}, "s1");
  add(x, exact(2), {B}, "s2");
  SECTION("spurious before a matched event") {
    kinetic::Simulation<double> y;
    add(y, 1.0, {A}, "s1");
    add(y, 1.5, {X}, "sX");
    add(y, 2.0, {B}, "s2");
    const auto d = kinetic::compare_runs(x, y);
    CHECK(d.first_divergence_event == 1u);
    CHECK(d.structure_mismatches == 0);
  }
  SECTION("spurious after the last exact event") {
    kinetic::Simulation<double> y;
    add(y, 1.0, {A}, "s1");
    add(y, 2.0, {B}, "s2");
    add(y, 2.5, {X}, "sX");
    const auto d = kinetic::compare_runs(x, y);
    CHECK(d.first_divergence_event == 2u);
  }
  SECTION("identical runs never diverge") {
    kinetic::Simulation<double> y;
    add(y, 1.0, {A}, "s1");
    add(y, 2.0, {B}, "s2");
    const auto d = kinetic::compare_runs(x, y);
    CHECK_FALSE(d.first_divergence_event);
    CHECK(d.max_time_error == 0);
  }
}

TEST_CASE("differential: the time error against an algebraic time has three correct digits", "[differential]") {
  // sqrt(2) against its double: the reported error e must satisfy
  // (t - e(1 + 2^-10))^2 < 2 < (t - e(1 - 2^-10))^2 where t > sqrt(2).
  const Exact_kernel k;
  const auto root = k.next_root(Poly<mpq_class>{-2, 0, 1}, Exact_time(mpq_class(0)));
  REQUIRE(root);
  const double t = 1.4142135623730951;  // above sqrt(2)
  kinetic::Simulation<Exact_time> x;
  add(x, *root, {A}, "s");
  kinetic::Simulation<double> y;
  add(y, t, {A}, "s");
  const auto d = kinetic::compare_runs(x, y);
  const mpq_class e = d.events[0].time_error;
  const mpq_class tq = to_rational(t);
  const mpq_class slack(1, 1024);
  CHECK(e > 0);
  const mpq_class low = tq - e * (1 + slack), high = tq - e * (1 - slack);
  CHECK(low * low < 2);
  CHECK(high * high > 2);
}

TEMPLATE_TEST_CASE("differential: floating-point kernels agree event for event on unstressed scenes",
                   "[differential][float]", kvd::Double_kernel, kvd::Mpfr_kernel) {
  const TestType fk;
  for (const char* name : {"two-triangles.json", "random-20.json", "uniform-scale-25.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    const auto exact = kinetic::run_exact(s, 60);
    const auto d = kinetic::compare_with(exact, fk, s);
    CHECK(d.events.size() == exact.sim.failures);
    CHECK_FALSE(d.first_divergence_event);
    CHECK(d.missed_events + d.spurious_events + d.order_mismatches + d.structure_mismatches == 0);
    // Every time within the kernel's epsilon, or its grouping would be wrong.
    CHECK(d.max_time_error < to_rational(fk.epsilon()));
    CHECK(d.recovery.detected() == 0);
  }
}

TEST_CASE("differential: a second exact run is identical to the first", "[differential]") {
  const scene::Scene s = load("random-20.json");
  const auto exact = kinetic::run_exact(s, 60);
  const auto d = kinetic::compare_with(exact, Exact_kernel(), s);
  CHECK_FALSE(d.first_divergence_event);
  CHECK(d.max_time_error == 0);
  CHECK(d.events.size() == exact.sim.failures);
}

TEST_CASE("differential: double cannot separate events 1e-31 apart, and the harness says so", "[differential][stiff]") {
  const scene::Scene s = scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/stiff/close-events.json");
  const auto exact = kinetic::run_exact(s, 100);
  const auto d = kinetic::compare_with(exact, Double_kernel(), s);
  REQUIRE(d.first_divergence_event);
  CHECK(d.structure_mismatches > 0);
  CHECK(d.max_time_error > 0);
}

TEST_CASE("differential: a build broken by rounding is repaired, not fatal", "[differential][recovery]") {
  // At 24 bits with epsilon 2^-12 the build of this scene throws at some
  // events (a fragment put across a triangle's plane). The run rebuilds a
  // little later, counts it and goes on to the end of the exact span.
  const scene::Scene s = load("uniform-density-25.json");
  const auto exact = kinetic::run_exact(s, 300);
  const auto d = kinetic::compare_with(exact, Mpfr_kernel(24), s);
  CHECK(d.recovery.failed_builds > 0);
  CHECK(d.recovery.rebuilds >= d.recovery.failed_builds);
  CHECK(d.recovery.unrepaired == 0);
  CHECK(d.inexact.size() >= exact.sim.failures / 2);
}

namespace {

// Every floating-point kernel the accuracy benchmark charts.
std::vector<std::pair<std::string, std::function<kinetic::Differential(const kinetic::Exact_run&, const scene::Scene&)>>>
float_kernels() {
  std::vector<std::pair<std::string, std::function<kinetic::Differential(const kinetic::Exact_run&, const scene::Scene&)>>> ks;
  ks.emplace_back("double", [](const auto& x, const auto& s) { return kinetic::compare_with(x, Double_kernel(), s); });
  for (unsigned bits : {24u, 53u, 113u, 256u, 1024u})
    ks.emplace_back("mpfr:" + std::to_string(bits),
                    [bits](const auto& x, const auto& s) { return kinetic::compare_with(x, Mpfr_kernel(bits), s); });
  return ks;
}

}  // namespace

TEST_CASE("differential: every floating-point kernel advances through every stiff scene", "[differential][stiff][progress]") {
  // A run that repeats a batch without advancing used to end only at its
  // event cap (tangential at 256 bits: 396 batches at t = 2). Now every
  // run ends by the exact run's span, or says it is stuck.
  for (const char* name : {"close-events", "simultaneous", "tangential", "wide-range", "slow-fast", "high-degree",
                           "rational-rotation", "near-degenerate", "z-near-plane"}) {
    const scene::Scene s = load(std::string("stiff/") + name + ".json");
    const auto exact = kinetic::run_exact(s, 100);
    for (const auto& [kernel, compare] : float_kernels()) {
      INFO(name << " in " << kernel);
      const kinetic::Differential d = compare(exact, s);
      CHECK(d.inexact_stopped != kinetic::Stop::stuck);
      CHECK(d.inexact_stopped != kinetic::Stop::events);  // the cap of 2n + 100 failures was never reached
      CHECK(d.recovery.unrepaired == 0);
      CHECK(d.inexact.size() <= 2 * d.events.size() + 10);
    }
  }
}

TEST_CASE("differential: a refire inside a rounding zone is stepped past", "[differential][stiff][recovery]") {
  // tangential's (t - 2)^3 crossing: at 256 bits the rounded certificate
  // changes sign anywhere within about 2^-85 of t = 2, far beyond epsilon
  // (2^-128). The run steps past that zone once and goes on to t = 4.
  const scene::Scene s = load("stiff/tangential.json");
  const auto exact = kinetic::run_exact(s, 100);
  const kinetic::Differential d = kinetic::compare_with(exact, Mpfr_kernel(256), s);
  CHECK(d.recovery.zones_skipped >= 1);
  CHECK(d.recovery.refires <= 3);
  CHECK(d.missed_events == 0);
  CHECK(exact.sim.stopped == kinetic::Stop::limit);
  CHECK(d.inexact_stopped == kinetic::Stop::limit);  // to the scene's end, t = 4
}
