// The exact kernel's interval filter decides a sign only when it is certain,
// and every answer is the same with the filter as without it: values exactly
// zero (which the filter must leave to exact arithmetic), within an ulp of
// zero, of about 1e-300 relative size, roots 2^-110 apart, and equal roots of
// different polynomials; and whole trees of the bundled scenes and of one
// that meets many more derived points than the filter's cache of them holds.
#include <catch2/catch.hpp>

#include <filesystem>

#include "kernels.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"

using namespace kvd;
using kvd::test::q;

namespace {

using P = Poly<mpq_class>;

P linear(const mpq_class& c0, const mpq_class& c1) { return P(std::vector<mpq_class>{c0, c1}); }
mpq_class two_to(int e) {
  mpq_class r(1);
  if (e >= 0) r <<= e;
  else r >>= -e;
  return r;
}
// The root of p after `from` (p must have one).
Exact_time root(const P& p, const mpq_class& from) { return *Exact_kernel().next_root(p, Exact_time(from)); }

// The sign of p at t with the filter on and off (fresh instants: refinement
// must not carry over), checked to agree; and whether the filter decided it.
struct Signs {
  int filtered, exact;
  bool by_filter;
};
template <class F>
Signs both(F&& f) {
  const Exact_kernel on(true), off(false);
  const long before = on.statistics().sign_at.filter + on.statistics().compare.filter;
  const int a = f(on), b = f(off);
  return {a, b, on.statistics().sign_at.filter + on.statistics().compare.filter > before};
}

}  // namespace

TEST_CASE("a value exactly zero at a rational instant is left to exact arithmetic", "[filter]") {
  const P p = linear(-1, 3) * linear(2, 1);  // (3t - 1)(t + 2)
  const auto s = both([&](const Exact_kernel& k) { return k.sign_at(p, Exact_time(q(1, 3))); });
  CHECK(s.filtered == 0);
  CHECK(s.exact == 0);
  CHECK_FALSE(s.by_filter);
  const auto after = both([&](const Exact_kernel& k) { return k.sign_after(p, Exact_time(q(1, 3))); });
  CHECK(after.filtered == 1);
  CHECK(after.exact == 1);
}

TEST_CASE("a value exactly zero at an algebraic instant is left to exact arithmetic", "[filter]") {
  const P two = linear(-2, 0) + P(std::vector<mpq_class>{0, 0, 1});  // t^2 - 2
  const P p = two * linear(5, 1);                                    // another polynomial with root sqrt(2)
  for (const P& f : {two, p}) {
    const auto s = both([&](const Exact_kernel& k) { return k.sign_at(f, root(two, 0)); });
    CHECK(s.filtered == 0);
    CHECK(s.exact == 0);
    CHECK_FALSE(s.by_filter);
    const auto after = both([&](const Exact_kernel& k) { return k.sign_after(f, root(two, 0)); });
    CHECK(after.filtered == 1);
    CHECK(after.exact == 1);
  }
}

TEST_CASE("values within an ulp of zero get their exact sign", "[filter]") {
  // p = t - d with d the double nearest 1/3: p(1/3) = 1/3 - d, about 1e-17,
  // inside the filter's interval around zero.
  const mpq_class d(1.0 / 3.0);
  for (const mpq_class& c : {d, mpq_class(std::nextafter(1.0 / 3.0, 1.0)), mpq_class(std::nextafter(1.0 / 3.0, 0.0))}) {
    const P p = linear(-c, 1);
    const int truth = sgn(q(1, 3) - c);
    const auto s = both([&](const Exact_kernel& k) { return k.sign_at(p, Exact_time(q(1, 3))); });
    CHECK(s.filtered == truth);
    CHECK(s.exact == truth);
  }
}

TEST_CASE("values of about 1e-300 relative size get their exact sign", "[filter]") {
  // p = 2^-1000 (t - 1/3) at 1/3 + 2^-k: the value is 2^-1000-k, positive.
  for (int k : {1, 30, 52, 60, 100}) {
    const P p = linear(-q(1, 3) * two_to(-1000), two_to(-1000));
    const Exact_time t(q(1, 3) + two_to(-k));
    const auto s = both([&](const Exact_kernel& kernel) { return kernel.sign_at(p, t.detached()); });
    CHECK(s.filtered == 1);
    CHECK(s.exact == 1);
    const auto below = both([&](const Exact_kernel& kernel) { return kernel.sign_at(p, Exact_time(q(1, 3) - two_to(-k))); });
    CHECK(below.filtered == -1);
    CHECK(below.exact == -1);
  }
}

// The exact kernel's integer coordinates give coefficients far beyond 2^64,
// which the filter brings back by an exact power of two: it still decides a
// sign far from zero, and still leaves one within an ulp of zero to exact
// arithmetic.
TEST_CASE("coefficients beyond 2^64 are filtered after an exact power-of-two scale", "[filter]") {
  for (int e : {70, 300, 2000}) {
    const P p = linear(-q(1, 3) * two_to(e), two_to(e)) + P(std::vector<mpq_class>{1});  // 2^e (t - 1/3) + 1
    const auto far = both([&](const Exact_kernel& k) { return k.sign_at(p, Exact_time(q(1, 2))); });
    CHECK(far.filtered == 1);
    CHECK(far.exact == 1);
    CHECK(far.by_filter);
    const auto below = both([&](const Exact_kernel& k) { return k.sign_at(p, Exact_time(q(1, 4))); });
    CHECK(below.filtered == -1);
    CHECK(below.exact == -1);
    CHECK(below.by_filter);
    // At 1/3 the value is 1, 2^-e of the terms' size: beyond the filter.
    const auto close = both([&](const Exact_kernel& k) { return k.sign_at(p, Exact_time(q(1, 3))); });
    CHECK(close.filtered == 1);
    CHECK(close.exact == 1);
    CHECK_FALSE(close.by_filter);
  }
}

// The filter encloses a coefficient without rational arithmetic where the
// double range allows (one ulp from mpq_get_d's truncation), and exactly
// near the ends of that range: at every magnitude, for integers that are
// doubles exactly, integers that are not, and rationals that are not
// dyadic, a value an ulp-sized step either side of a root gets its exact
// sign, and the root itself is left to exact arithmetic.
TEST_CASE("coefficients of every magnitude are enclosed soundly", "[filter]") {
  const mpq_class r = q(1, 3);
  for (int e : {-1000, -940, -899, -600, -60, 0, 52, 53, 54, 64, 500, 990, 1001}) {
    const std::vector<mpq_class> coefficients{two_to(e), two_to(e) + 1, two_to(e) * q(7, 3),
                                              two_to(e) * q((1 << 20) + 1, 1 << 20)};
    for (const mpq_class& c : coefficients) {
      const P p = linear(-c * r, c);  // c (t - 1/3)
      for (int k : {40, 52, 53, 60}) {
        const mpq_class step = two_to(-k) * r;
        const auto above = both([&](const Exact_kernel& kernel) { return kernel.sign_at(p, Exact_time(r + step)); });
        CHECK(above.filtered == 1);
        CHECK(above.exact == 1);
        const auto below = both([&](const Exact_kernel& kernel) { return kernel.sign_at(p, Exact_time(r - step)); });
        CHECK(below.filtered == -1);
        CHECK(below.exact == -1);
      }
      const auto at = both([&](const Exact_kernel& kernel) { return kernel.sign_at(p, Exact_time(r)); });
      CHECK(at.filtered == 0);
      CHECK_FALSE(at.by_filter);
    }
  }
}

TEST_CASE("roots 2^-110 apart are told apart, and signs between them are exact", "[filter]") {
  // (t^2 - 2) and (t^2 - 2 - 2^-110 t): two algebraic roots about 2^-112 apart.
  const P two = linear(-2, 0) + P(std::vector<mpq_class>{0, 0, 1});
  const P shifted = two - linear(0, two_to(-110));
  const auto order = both([&](const Exact_kernel& k) { return k.compare(root(two, 1), root(shifted, 1)); });
  CHECK(order.filtered == -1);
  CHECK(order.exact == -1);
  // The rational roots a and a + 2^-110 of (t - a)(t - a - 2^-110), a = 1/3.
  const mpq_class a = q(1, 3), b = a + two_to(-110);
  const P p = linear(-a, 1) * linear(-b, 1);
  CHECK(both([&](const Exact_kernel& k) { return k.compare(root(p, 0), root(p, b - two_to(-112))); }).filtered == -1);
  // p between its roots, and t - (a + 2^-111) at each of them.
  const auto mid = both([&](const Exact_kernel& k) { return k.sign_at(p, Exact_time(a + two_to(-111))); });
  CHECK(mid.filtered == -1);
  CHECK(mid.exact == -1);
  const P half = linear(-(a + two_to(-111)), 1);
  CHECK(both([&](const Exact_kernel& k) { return k.sign_at(half, Exact_time(a)); }).filtered == -1);
  CHECK(both([&](const Exact_kernel& k) { return k.sign_at(half, Exact_time(b)); }).filtered == 1);
  // t^2 - 2 - 2^-111 t is -2^-111 sqrt(2) at the first algebraic root and
  // +2^-111 t at the second.
  const P between = two - linear(0, two_to(-111));
  for (const auto& [r, want] : {std::pair{root(two, 1), -1}, std::pair{root(shifted, 1), 1}}) {
    const Exact_time at = r.detached();  // a lambda may not capture a structured binding in C++17
    const auto s = both([&](const Exact_kernel& k) { return k.sign_at(between, at); });
    CHECK(s.filtered == want);
    CHECK(s.exact == want);
  }
}

TEST_CASE("equal roots of different polynomials compare equal", "[filter]") {
  const P two = linear(-2, 0) + P(std::vector<mpq_class>{0, 0, 1});
  const P p = two * linear(-3, 1), r = two * linear(1, 1) * linear(-7, 2);
  const auto s = both([&](const Exact_kernel& k) { return k.compare(root(p, 0), root(r, 0)); });
  CHECK(s.filtered == 0);
  CHECK(s.exact == 0);
  CHECK_FALSE(s.by_filter);
}

TEST_CASE("every bundled scene builds the same tree with and without the filter", "[filter]") {
  for (const char* folder : {"/data", "/data/stiff"}) {
    for (const auto& f : std::filesystem::directory_iterator(std::string(KVD_SOURCE_DIR) + folder)) {
      if (f.path().extension() != ".json") continue;
      const scene::Scene s = scene::load_scene(f.path().string());
      if (s.triangles.size() > 200) continue;  // the large ones: kvd build in the README's measurements
      INFO(f.path().filename().string());
      const Exact_kernel on(true), off(false);
      const predicates::Classifier<Exact_kernel> a(on, s), b(off, s);
      const tree::Kvd_tree x = tree::build(a, Exact_time(s.start)), y = tree::build(b, Exact_time(s.start));
      CHECK(x.describe() == y.describe());
      // The filter decides only rule 2; rules 3 and 4 are counted alike.
      CHECK(on.statistics().classify.after == off.statistics().classify.after);
      CHECK(on.statistics().classify.perturbation == off.statistics().classify.perturbation);
      CHECK(on.statistics().classify.filter + on.statistics().classify.exact == off.statistics().classify.exact);
    }
  }
}

TEST_CASE("a build that meets more derived points than the filter caches builds the same tree without it",
          "[filter][slow]") {
  // The filter keeps the derived points of an instant in a direct-mapped
  // cache of 2^15 entries; the build of 1600 generated triangles meets more
  // than 2^16 of them (a count made when the cache was a table), so entries
  // are taken over by other points many times.
  scene::Uniform_params p;
  p.triangles = 1600;
  p.seed = 1;
  const scene::Scene s = scene::uniform_scale(p);
  const Exact_kernel on(true), off(false);
  const predicates::Classifier<Exact_kernel> a(on, s), b(off, s);
  const tree::Kvd_tree x = tree::build(a, Exact_time(s.start)), y = tree::build(b, Exact_time(s.start));
  CHECK(tree::structure_hash(x) == tree::structure_hash(y));
  CHECK(!tree::first_difference(x, y));
  CHECK(on.statistics().classify.filter > 0);
}

TEST_CASE("the certificate walks are decided by the filter where it is on, with the same run", "[filter]") {
  const scene::Scene s = scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/uniform-scale-25.json");
  kinetic::Options o;
  o.max_events = 100;
  o.validate = kinetic::Validation::none;
  const Exact_kernel on(true), off(false);
  const auto a = kinetic::simulate(on, s, o), b = kinetic::simulate(off, s, o);
  CHECK(a.structure_hash == b.structure_hash);
  REQUIRE(a.batches.size() == b.batches.size());
  CHECK(a.failures_by_type == b.failures_by_type);
  for (std::size_t i = 0; i < a.batches.size(); ++i)
    CHECK(a.batches[i].certificates_recomputed == b.batches[i].certificates_recomputed);
  // On: the walks' signs are mostly the filter's; off: no walk is filtered.
  CHECK(on.statistics().walk.filter > 10 * on.statistics().walk.exact);
  CHECK(off.statistics().walk.filter + off.statistics().walk.exact == 0);
}
