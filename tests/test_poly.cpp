// Time polynomials: trimming, arithmetic, evaluation, derivative, over every
// kernel's field.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "kernels.hpp"

using kvd::test::poly;

TEMPLATE_TEST_CASE("a polynomial's degree ignores leading zeros", "[poly]", KVD_ALL_KERNELS) {
  using P = typename TestType::Poly;
  CHECK(P().degree() == -1);
  CHECK(P().is_zero());
  CHECK(poly<TestType>({0, 0, 0}).degree() == -1);
  CHECK(poly<TestType>({5, 0, 0}).degree() == 0);
  CHECK(poly<TestType>({1, 2, 3, 0, 0}).degree() == 2);
  // Cancellation of the leading term lowers the degree.
  CHECK((poly<TestType>({1, 2, 3}) - poly<TestType>({0, 0, 3})).degree() == 1);
  CHECK((poly<TestType>({1, 2}) + poly<TestType>({-1, -2})).is_zero());
}

TEMPLATE_TEST_CASE("polynomial arithmetic matches hand computation", "[poly]", KVD_ALL_KERNELS) {
  using FT = typename TestType::FT;
  const auto p = poly<TestType>({1, -3, 2});  // (1 - t)(1 - 2t)
  const auto q = poly<TestType>({-1, 1});     // t - 1
  CHECK(p * q == poly<TestType>({-1, 4, -5, 2}));
  CHECK(p + q == poly<TestType>({0, -2, 2}));
  CHECK(-q == poly<TestType>({1, -1}));
  CHECK(p.derivative() == poly<TestType>({-3, 4}));
  CHECK(poly<TestType>({7}).derivative().is_zero());
  CHECK(p(FT(3)) == FT(10));
  CHECK(p(FT(1)) == FT(0));
  CHECK((p * q)(FT(-2)) == p(FT(-2)) * q(FT(-2)));
  CHECK(TestType::Poly::monomial(FT(4), 3) == poly<TestType>({0, 0, 0, 4}));
}

TEST_CASE("exact polynomial products evaluate as products of values", "[poly]") {
  using P = kvd::Poly<mpq_class>;
  const P a{mpq_class(1, 3), mpq_class(-2, 7), mpq_class(5)};
  const P b{mpq_class(-4), mpq_class(0), mpq_class(1, 9), mpq_class(2, 5)};
  for (int i = -5; i <= 5; ++i) {
    const mpq_class t = kvd::test::q(i, 3);
    CHECK((a * b)(t) == a(t) * b(t));
    CHECK((a - b)(t) == a(t) - b(t));
  }
  CHECK((a * b).degree() == 5);
}

// Integer coefficients take a path on the numerators alone
// (src/kernel/poly_integer.cpp); a rational scale of one operand takes the
// general path. Both must give the same polynomial, up to that scale.
TEST_CASE("integer and rational polynomial arithmetic agree", "[poly]") {
  using P = kvd::Poly<mpq_class>;
  gmp_randclass rnd(gmp_randinit_default);
  rnd.seed(20261126);
  const auto below = [&](unsigned long n) { return mpz_class(rnd.get_z_range(n)).get_ui(); };
  const auto random = [&](int degree, unsigned long bits) {
    std::vector<mpq_class> c;
    for (int i = 0; i <= degree; ++i) {
      mpz_class z = rnd.get_z_bits(bits);
      c.emplace_back(below(2) == 0 ? mpz_class(-z) : z);
    }
    return P(std::move(c));
  };
  const P half{mpq_class(1, 2)};
  int rational = 0;
  for (int i = 0; i < 500; ++i) {
    const P a = random(static_cast<int>(below(5)), 1 + below(150));
    const P b = random(static_cast<int>(below(5)), 1 + below(150));
    const P ah = a * half;  // rational unless a is even
    CHECK((a * b) * half == ah * b);
    CHECK((a + b) * half == ah + b * half);
    CHECK((a - b) * half == ah - b * half);
    CHECK((a - a).is_zero());
    rational += std::ranges::any_of(ah.coefficients(), [](const mpq_class& c) { return c.get_den() != 1; });
    const P product = a * b;
    for (int t = -3; t <= 3; ++t) CHECK(product(mpq_class(t)) == a(mpq_class(t)) * b(mpq_class(t)));
  }
  CHECK(rational > 300);  // the general path was taken on one side
}
