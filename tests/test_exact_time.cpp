// Exact instants: equality of algebraic numbers given by different
// polynomials, ordering of very close numbers, conversions.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "kernels.hpp"
#include "kvd/kernel/exact_kernel.hpp"

namespace {

using P = kvd::Poly<mpq_class>;
const kvd::Exact_kernel k;

std::vector<kvd::Exact_time> roots(const P& p) { return kvd::test::sign_changing_roots(p, -1000); }

const P t2m2{-2, 0, 1};  // t^2 - 2
const P t2m3{-3, 0, 1};  // t^2 - 3

}  // namespace

TEST_CASE("the same algebraic number from different polynomials compares equal", "[exact]") {
  const auto a = roots(t2m2);                       // -sqrt2, sqrt2
  const auto b = roots(t2m2 * t2m3);                // -sqrt3, -sqrt2, sqrt2, sqrt3
  const auto c = roots(P{-4, 0, 0, 0, 1});          // t^4 - 4 = (t^2-2)(t^2+2)
  const auto d = roots(t2m2 * t2m2 * P{-2, 0, 1});  // multiplicity 3: still sign changes
  REQUIRE(a.size() == 2);
  REQUIRE(b.size() == 4);
  REQUIRE(c.size() == 2);
  REQUIRE(d.size() == 2);
  CHECK(k.compare(a[1], b[2]) == 0);
  CHECK(k.compare(b[1], a[0]) == 0);
  CHECK(k.compare(c[1], a[1]) == 0);
  CHECK(k.compare(d[0], b[1]) == 0);
  CHECK(k.compare(a[1], b[3]) == -1);
  CHECK(k.compare(b[0], a[0]) == -1);
  CHECK(k.compare(b[3], c[1]) == 1);
}

TEST_CASE("a rational root of a high-degree polynomial is exactly that rational", "[exact]") {
  const auto r = roots(P{mpq_class(-1), mpq_class(3)} * t2m2);  // 1/3 and +-sqrt2
  REQUIRE(r.size() == 3);
  CHECK(k.compare(r[1], kvd::Exact_time(kvd::test::q(1, 3))) == 0);
  CHECK(k.compare(r[2], kvd::Exact_time(kvd::test::q(1, 3))) == 1);
}

TEST_CASE("numbers 2^-200 apart are told apart in the right order", "[exact]") {
  mpq_class eps(1);
  eps /= mpz_class(1) << 200;
  // (t - eps)^2 - 2 has the root sqrt2 + eps.
  const P shifted = P{-eps, 1} * P{-eps, 1} - P{2};
  const auto a = roots(t2m2);
  const auto b = roots(shifted);
  CHECK(k.compare(a[1], b[1]) == -1);
  CHECK(k.compare(b[1], a[1]) == 1);
  CHECK(k.compare(a[0], b[0]) == -1);
  // A rational between them.
  const kvd::Exact_time mid(eps / 2);
  CHECK(k.compare(kvd::Exact_time(mpq_class(0)), mid) == -1);
}

TEST_CASE("an algebraic number is never equal to a nearby rational", "[exact]") {
  const auto a = roots(t2m2);
  const kvd::Exact_time approx(mpq_class(std::sqrt(2.0)));
  CHECK(k.compare(a[1], approx) != 0);
  CHECK(k.compare(approx, a[1]) == -k.compare(a[1], approx));
}

TEST_CASE("exact instants convert to double and to text", "[exact]") {
  const auto a = roots(t2m2);
  CHECK(a[1].to_double() == std::sqrt(2.0));
  CHECK(a[0].to_double() == -std::sqrt(2.0));
  CHECK(kvd::Exact_time(kvd::test::q(-7, 3)).to_string() == "-7/3");
  CHECK(a[1].to_string().rfind("root of [-2, 0, 1] in (", 0) == 0);
}

TEST_CASE("to_double rounds to nearest, ties to even", "[exact]") {
  // IEEE square roots are correctly rounded; isolate from an arbitrary
  // rational so that interval ends are not on a power-of-two grid.
  int wrong = 0;
  for (long n = 2; n < 3000; ++n) {
    const auto r = k.next_root(P{mpq_class(-n), 0, 1}, kvd::Exact_time(kvd::test::q(1, 3)));
    wrong += r->to_double() != std::sqrt(static_cast<double>(n));
  }
  CHECK(wrong == 0);
  // Subnormals: 2^-1075 + 2^-1135 is just above half the smallest subnormal.
  mpq_class tiny = mpq_class(1) / (mpz_class(1) << 1075) + mpq_class(1) / (mpz_class(1) << 1135);
  CHECK(kvd::Exact_time(tiny).to_double() == std::numeric_limits<double>::denorm_min());
  // An exact tie, 1 + 2^-53, goes to the even neighbour 1.
  CHECK(kvd::Exact_time(mpq_class(1) + mpq_class(1) / (mpz_class(1) << 53)).to_double() == 1.0);
  CHECK(kvd::Exact_time(mpq_class(-1, 3)).to_double() == -1.0 / 3.0);
}

TEST_CASE("signs at algebraic instants are exact", "[exact]") {
  const auto a = roots(t2m2);
  const auto& s2 = a[1];
  CHECK(k.sign_at(t2m2 * P{5, 1}, s2) == 0);
  CHECK(k.sign_at(t2m3, s2) == -1);  // 2 - 3
  CHECK(k.sign_at(P{kvd::test::q(-99, 70), 1}, s2) == -1);  // sqrt2 < 99/70
  CHECK(k.sign_at(P{kvd::test::q(-140, 99), 1}, s2) == 1);   // sqrt2 > 140/99
  // t^2 - 2 vanishes at sqrt2; it is a simple root, increasing.
  CHECK(k.sign_after(t2m2, s2) == 1);
  CHECK(k.sign_after(t2m2, a[0]) == -1);
  // (t^2-2)^2 touches zero: positive after.
  CHECK(k.sign_after(t2m2 * t2m2, s2) == 1);
  CHECK(k.sign_after(t2m2 * t2m2 * P{0, -1}, s2) == -1);
}

TEST_CASE("a detached copy does not share refinement", "[exact]") {
  const auto a = roots(t2m2);
  const kvd::Exact_time copy = a[1].detached();
  const mpq_class width = copy.upper() - copy.lower();
  a[1].refine();
  CHECK(copy.upper() - copy.lower() == width);
  CHECK(a[1].upper() - a[1].lower() < width);
  CHECK(k.compare(copy, a[1]) == 0);
}

TEST_CASE("an algebraic value prints the same however far comparisons refined it", "[exact]") {
  // sqrt(2) next to sqrt(2) + 1/1000: roots of (t^2 - 2)((t - 1/1000)^2 - 2),
  // scaled to integers.
  const kvd::zpoly::ZPoly p = {mpz_class(-2), 0, 1};
  const kvd::zpoly::ZPoly shifted = {mpz_class(1 - 2000000), -2000, 1000000};
  kvd::zpoly::ZPoly product(p.size() + shifted.size() - 1);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < shifted.size(); ++j) product[i + j] += p[i] * shifted[j];
  const kvd::Exact_time a = kvd::Exact_time::algebraic(product, kvd::test::q(1413, 1000), kvd::test::q(14145, 10000));
  const kvd::Exact_time b = a.detached();
  for (int i = 0; i < 40; ++i) b.refine();
  CHECK(a.to_string() == b.to_string());
  const auto [lo, hi] = a.canonical_interval();
  // Dyadic, narrower than the gap to the other root, isolating, around the value.
  const mpq_class width = hi - lo;
  CHECK(width.get_num() == 1);
  CHECK((width.get_den() & (width.get_den() - 1)) == 0);
  CHECK(width < kvd::test::q(1, 1000));
  CHECK(kvd::zpoly::descartes_bound(product, lo, hi) == 1);
  CHECK(a.compare_refining(lo) == 1);
  CHECK(a.compare_refining(hi) == -1);
  CHECK(a.to_string() == "root of [" + product[0].get_str() + ", " + product[1].get_str() + ", " + product[2].get_str() +
                             ", " + product[3].get_str() + ", " + product[4].get_str() + "] in (" + lo.get_str() + ", " +
                             hi.get_str() + ")");
}
