// Time polynomials: trimming, arithmetic, evaluation, derivative, over every
// kernel's field.
#include <catch2/catch.hpp>

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
