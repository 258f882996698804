// The exact kernel's own root isolator against CGAL's Algebraic_kernel_d_1 on
// 10,000 random integer polynomials: dense ones with coefficients up to 200
// bits, products with double and triple factors, clusters of roots 2^-110
// (< 1e-30) apart, and queries exactly at a root. For each polynomial the whole
// chain next_root(p, after), next_root(p, that root), ... must match CGAL's
// roots of odd multiplicity after `after`, root for root, decided exactly.
#include <catch2/catch.hpp>
#include <sstream>

#include "cgal_roots.hpp"
#include "kernels.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "random_poly.hpp"

namespace {

using kvd::Exact_time;
using kvd::oracle::Cgal_roots;
using kvd::zpoly::ZPoly;

const kvd::Exact_kernel k;

std::string show(const ZPoly& p) {
  std::ostringstream os;
  for (const auto& c : p) os << c.get_str() << " ";
  return os.str();
}

// CGAL's comparison of its root i with our instant t.
int cgal_compare(const Cgal_roots& cgal, std::size_t i, const Exact_time& t) {
  if (t.is_rational()) return cgal.compare(i, t.rational());
  return cgal.compare(i, t.polynomial(), t.lower(), t.upper());
}

// Walks the chain of sign-changing roots after `after`; returns a description
// of the first disagreement with CGAL, or "" and adds the roots checked.
std::string check_chain(const ZPoly& p, const mpq_class& after, long& roots_checked) {
  const Cgal_roots cgal(p);
  const kvd::Poly<mpq_class> poly = kvd::zpoly::to_poly(p);
  std::optional<std::size_t> expected = cgal.next_sign_change_after(after);
  Exact_time t(after);
  for (int step = 0;; ++step) {
    const std::optional<Exact_time> got = k.next_root(poly, t);
    if (!expected && !got) return "";
    std::ostringstream why;
    why << "p = [" << show(p) << "], after = " << after.get_str() << ", step " << step << ": ";
    if (!expected) return why.str() + "CGAL has no further root, we found " + got->to_string();
    if (!got) return why.str() + "we found no root, CGAL has one near " + std::to_string(cgal.to_double(*expected));
    if (cgal_compare(cgal, *expected, *got) != 0)
      return why.str() + "our root " + got->to_string() + " differs from CGAL's " +
             std::to_string(cgal.to_double(*expected));
    ++roots_checked;
    t = *got;
    expected = cgal.next_sign_change_after_root(*expected);
  }
}

}  // namespace

TEST_CASE("next_root agrees with CGAL's Algebraic_kernel_d_1 on 10,000 polynomials", "[roots][cgal]") {
  kvd::testing::Random_polys rnd(20261121);
  long roots_checked = 0, polys = 0;
  std::vector<std::string> failures;
  auto check = [&](const ZPoly& p, const mpq_class& after) {
    ++polys;
    const std::string f = check_chain(p, after, roots_checked);
    if (!f.empty() && failures.size() < 5) failures.push_back(f);
  };
  auto degree = [&](int lo, int hi) { return lo + static_cast<int>(rnd.below(static_cast<unsigned long>(hi - lo + 1))); };

  SECTION("dense, coefficients up to 200 bits") {
    for (int i = 0; i < 4000; ++i) check(rnd.dense(degree(1, 12), 1 + rnd.below(200)), rnd.rational(6));
  }
  SECTION("double and triple factors") {
    for (int i = 0; i < 2500; ++i) check(rnd.repeated_factors(degree(6, 12), 1 + rnd.below(40)), rnd.rational(6));
  }
  SECTION("clusters of roots 2^-110 apart") {
    for (int i = 0; i < 1500; ++i) {
      const ZPoly p = rnd.cluster(degree(2, 4), 110, degree(0, 6), 1 + rnd.below(64));
      // Query from below the cluster, and from the middle of the cluster.
      check(p, mpq_class(-1) << 200);
    }
  }
  SECTION("the query instant is itself a root") {
    for (int i = 0; i < 2000; ++i) {
      const mpq_class r = rnd.rational(1 + rnd.below(60));
      check(rnd.with_root(r, degree(1, 12), 1 + rnd.below(100)), r);
    }
  }
  WARN(polys << " polynomials, " << roots_checked << " roots checked against CGAL");
  for (const auto& f : failures) UNSCOPED_INFO(f);
  CHECK(failures.empty());
  CHECK(roots_checked > polys / 2);
}

TEST_CASE("compare agrees with CGAL on roots of polynomials with common factors", "[roots][cgal]") {
  kvd::testing::Random_polys rnd(7);
  int equal_pairs = 0, pairs = 0, mismatches = 0;
  for (int i = 0; i < 300; ++i) {
    const ZPoly f = rnd.dense(1 + static_cast<int>(rnd.below(4)), 30);
    const ZPoly p = kvd::zpoly::mul(f, rnd.dense(1 + static_cast<int>(rnd.below(4)), 30));
    const ZPoly q = kvd::zpoly::mul(f, rnd.dense(1 + static_cast<int>(rnd.below(4)), 30));
    const Cgal_roots cgal_p(p);
    const auto ours_p = kvd::test::sign_changing_roots(kvd::zpoly::to_poly(p), mpq_class(-1) << 300);
    const auto ours_q = kvd::test::sign_changing_roots(kvd::zpoly::to_poly(q), mpq_class(-1) << 300);
    // Map our roots of p to CGAL's sign-changing roots of p, in order.
    std::vector<std::size_t> cgal_index;
    for (std::size_t j = 0; j < cgal_p.size(); ++j)
      if (cgal_p.multiplicity(j) % 2 == 1) cgal_index.push_back(j);
    REQUIRE(cgal_index.size() == ours_p.size());
    for (std::size_t a = 0; a < ours_p.size(); ++a)
      for (const auto& b : ours_q) {
        ++pairs;
        const int cgal = cgal_compare(cgal_p, cgal_index[a], b);
        equal_pairs += cgal == 0;
        mismatches += k.compare(ours_p[a], b) != cgal;
      }
  }
  WARN(pairs << " pairs compared, " << equal_pairs << " equal");
  CHECK(mismatches == 0);
  CHECK(equal_pairs > 50);  // the common factor makes equal pairs frequent
}

TEST_CASE("sign_at an algebraic instant agrees with CGAL", "[roots][cgal]") {
  kvd::testing::Random_polys rnd(99);
  int zeros = 0, mismatches = 0, checks = 0;
  for (int i = 0; i < 300; ++i) {
    const ZPoly g = rnd.dense(1 + static_cast<int>(rnd.below(3)), 20);
    const ZPoly p = kvd::zpoly::mul(g, rnd.dense(1 + static_cast<int>(rnd.below(5)), 40));
    // f shares g with p half of the time, so it vanishes at some roots.
    const ZPoly f = rnd.below(2) ? kvd::zpoly::mul(g, rnd.dense(2, 40)) : rnd.dense(1 + static_cast<int>(rnd.below(6)), 40);
    const Cgal_roots cgal(p);
    Exact_time t(mpq_class(-1) << 300);
    std::optional<std::size_t> idx = cgal.next_sign_change_after(t.rational());
    for (; auto n = k.next_root(kvd::zpoly::to_poly(p), t); idx = cgal.next_sign_change_after_root(*idx)) {
      t = *n;
      REQUIRE(idx);
      const int expected = cgal.sign_at(*idx, f);
      zeros += expected == 0;
      mismatches += k.sign_at(kvd::zpoly::to_poly(f), t) != expected;
      ++checks;
    }
  }
  WARN(checks << " signs compared, " << zeros << " zero");
  CHECK(mismatches == 0);
  CHECK(zeros > 20);
}

// Degrees 1 and 2 take closed forms, not bisection: rational roots from a
// square discriminant, irrational ones bracketed by an integer square root.
// Queried from rational and from algebraic instants, including an instant
// that is itself one of the roots, given by another polynomial.
TEST_CASE("closed forms for degrees 1 and 2 agree with CGAL, after rational and algebraic instants",
          "[roots][cgal]") {
  kvd::testing::Random_polys rnd(20261125);
  int checks = 0, rational_roots = 0, mismatches = 0, equal_to_after = 0;
  auto linear = [&](unsigned long bits) {
    ZPoly l{rnd.integer(bits), rnd.integer(bits)};
    while (l[1] == 0) l[1] = rnd.integer(bits);
    return l;
  };
  for (int i = 0; i < 3000; ++i) {
    const unsigned long bits = 1 + rnd.below(80);
    const int kind = static_cast<int>(rnd.below(3));
    // A product of two linear factors (square discriminant), a random
    // quadratic, or a linear polynomial.
    const ZPoly f = linear(bits);
    const ZPoly p = kind == 0 ? kvd::zpoly::mul(f, linear(bits)) : kind == 1 ? rnd.dense(2, bits) : f;
    // The instants: a rational, and the roots of another polynomial, which a
    // quarter of the time shares a root with p (f, or p itself times a factor).
    ZPoly g = rnd.dense(2, 1 + rnd.below(40));
    if (rnd.below(4) == 0) g = kvd::zpoly::mul(kind == 1 ? p : f, linear(1 + rnd.below(40)));
    const auto starts = kvd::test::sign_changing_roots(kvd::zpoly::to_poly(g), mpq_class(-1) << 300);
    std::vector<Exact_time> afters{Exact_time(rnd.rational(1 + rnd.below(40)))};
    for (const auto& s : starts) afters.push_back(s);
    const Cgal_roots cgal(p);
    // Half the time a rational multiple of p, of either sign: the same roots,
    // asked through coefficients with denominators.
    kvd::Poly<mpq_class> asked = kvd::zpoly::to_poly(p);
    if (rnd.below(2)) {
      mpq_class c = rnd.rational(1 + rnd.below(40));
      if (c == 0) c = -1;
      asked = asked * kvd::Poly<mpq_class>{c};
    }
    for (const Exact_time& after : afters) {
      const Exact_time fresh = after.detached();  // wide as found, not refined by an earlier query
      const std::optional<Exact_time> got = k.next_root(asked, fresh);
      std::optional<std::size_t> expected;
      for (std::size_t j = 0; j < cgal.size() && !expected; ++j) {
        if (cgal.multiplicity(j) % 2 == 0) continue;
        const int c = cgal_compare(cgal, j, after);
        equal_to_after += c == 0;
        if (c > 0) expected = j;
      }
      ++checks;
      if (got) rational_roots += got->is_rational();
      const bool same = got && expected ? cgal_compare(cgal, *expected, *got) == 0 : !got && !expected;
      if (!same && mismatches++ < 3) UNSCOPED_INFO("p = [" << show(p) << "], after " << after.to_string());
    }
  }
  WARN(checks << " queries, " << rational_roots << " rational roots, " << equal_to_after << " roots equal to the instant");
  CHECK(mismatches == 0);
  CHECK(rational_roots > 500);
  CHECK(equal_to_after > 50);
}

// The modular test may answer "not known" for a square-free polynomial, but
// never "square-free" for one with a repeated root.
TEST_CASE("the modular square-freeness test never accepts a repeated root", "[roots][cgal]") {
  kvd::testing::Random_polys rnd(11);
  int accepted = 0, square_free = 0;
  for (int i = 0; i < 2000; ++i) {
    const ZPoly p = rnd.below(2) ? rnd.repeated_factors(2 + static_cast<int>(rnd.below(11)), 1 + rnd.below(60))
                                 : rnd.dense(2 + static_cast<int>(rnd.below(11)), 1 + rnd.below(60));
    const Cgal_roots cgal(p);
    bool repeated = false;
    for (std::size_t j = 0; j < cgal.size(); ++j) repeated |= cgal.multiplicity(j) > 1;
    // CGAL sees real roots only: a repeated complex pair shows as gcd(p, p') != 1.
    repeated |= kvd::zpoly::degree(kvd::zpoly::gcd(p, kvd::zpoly::derivative(p))) > 0;
    const bool says = kvd::zpoly::certainly_square_free(p);
    square_free += !repeated;
    accepted += says;
    if (says && repeated) FAIL("certainly_square_free accepted [" << show(p) << "]");
  }
  WARN(square_free << " square-free of 2000, " << accepted << " accepted");
  CHECK(accepted > square_free * 9 / 10);
}
