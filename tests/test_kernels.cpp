// The kernel operations on hand-built polynomials, in all three kernels:
// next_root, sign_at, sign_after, compare.
#include <catch2/catch.hpp>

#include "kernels.hpp"

using kvd::test::at;
using kvd::test::poly;
using kvd::test::with_roots;

TEMPLATE_TEST_CASE("next_root finds sign-changing roots strictly after the query", "[kernel]",
                   KVD_ALL_KERNELS) {
  const TestType k;
  const auto p = with_roots<TestType>({1, 2, 3});
  auto r = k.next_root(p, at(k, 0));
  REQUIRE(r);
  CHECK(k.compare(*r, at(k, 1)) == 0);
  // The query instant itself is excluded, so iterating walks the roots.
  r = k.next_root(p, *r);
  REQUIRE(r);
  CHECK(k.compare(*r, at(k, 2)) == 0);
  r = k.next_root(p, *r);
  REQUIRE(r);
  CHECK(k.compare(*r, at(k, 3)) == 0);
  CHECK_FALSE(k.next_root(p, *r));
  CHECK_FALSE(k.next_root(p, at(k, 5)));
  // Negative roots are found after a negative query.
  r = k.next_root(with_roots<TestType>({-7, 4}), at(k, -100));
  REQUIRE(r);
  CHECK(k.compare(*r, at(k, -7)) == 0);
  // A root exactly at zero (floating-point bisection must still terminate).
  r = k.next_root(with_roots<TestType>({0, 3}), at(k, -5));
  REQUIRE(r);
  CHECK(k.compare(*r, at(k, 0)) == 0);
}

TEMPLATE_TEST_CASE("next_root skips roots of even multiplicity", "[kernel]", KVD_ALL_KERNELS) {
  const TestType k;
  // (t-1)^2 (t-2): the double root at 1 is not a sign change.
  auto r = k.next_root(with_roots<TestType>({1, 1, 2}), at(k, 0));
  REQUIRE(r);
  CHECK(k.compare(*r, at(k, 2)) == 0);
  // (t-1)^3 is a sign change.
  r = k.next_root(with_roots<TestType>({1, 1, 1}), at(k, 0));
  REQUIRE(r);
  CHECK(k.compare(*r, at(k, 1)) == 0);
  // (t-3)^2, a zero discriminant, t^2 + 1 and the constants have none.
  CHECK_FALSE(k.next_root(with_roots<TestType>({3, 3}), at(k, 0)));
  CHECK_FALSE(k.next_root(poly<TestType>({1, 0, 1}), at(k, -10)));
  CHECK_FALSE(k.next_root(poly<TestType>({3}), at(k, 0)));
  CHECK_FALSE(k.next_root(typename TestType::Poly(), at(k, 0)));
}

TEMPLATE_TEST_CASE("sign_after at a simple root flips the sign", "[kernel]", KVD_ALL_KERNELS) {
  const TestType k;
  const auto p = with_roots<TestType>({1, 3});  // + before 1, - on (1,3), + after 3
  CHECK(k.sign_at(p, at(k, 0)) == 1);
  CHECK(k.sign_at(p, at(k, 1)) == 0);
  CHECK(k.sign_after(p, at(k, 1)) == -1);
  CHECK(k.sign_after(p, at(k, 3)) == 1);
  CHECK(k.sign_after(p, at(k, 2)) == -1);  // not a root: the sign there
}

TEMPLATE_TEST_CASE("sign_after at an even-multiplicity root keeps the sign before it", "[kernel]",
                   KVD_ALL_KERNELS) {
  const TestType k;
  // -(t-2)^2 (t-5): positive before 2, zero at 2, positive after 2 (until 5).
  const auto p = -with_roots<TestType>({2, 2, 5});
  CHECK(k.sign_at(p, at(k, 1)) == 1);
  CHECK(k.sign_at(p, at(k, 2)) == 0);
  CHECK(k.sign_after(p, at(k, 2)) == 1);
  // (t-2)^4: positive on both sides.
  const auto q = with_roots<TestType>({2, 2, 2, 2});
  CHECK(k.sign_after(q, at(k, 2)) == 1);
  CHECK(k.sign_at(q, at(k, 1)) == 1);
  // (t-2)^3: negative before, positive after.
  CHECK(k.sign_after(with_roots<TestType>({2, 2, 2}), at(k, 2)) == 1);
  CHECK(k.sign_at(with_roots<TestType>({2, 2, 2}), at(k, 1)) == -1);
  CHECK(k.sign_after(typename TestType::Poly(), at(k, 2)) == 0);
}

TEMPLATE_TEST_CASE("compare orders instants", "[kernel]", KVD_ALL_KERNELS) {
  const TestType k;
  CHECK(k.compare(at(k, 1), at(k, 2)) == -1);
  CHECK(k.compare(at(k, 2), at(k, 1)) == 1);
  CHECK(k.compare(at(k, -3), at(k, -3)) == 0);
}

TEST_CASE("the double kernel's equality is the thesis's epsilon", "[kernel]") {
  const kvd::Double_kernel k(1e-6);
  CHECK(k.compare(1.0, 1.0 + 1e-7) == 0);
  CHECK(k.compare(1.0, 1.0 + 1e-5) == -1);
  CHECK(k.sign(5e-7) == 0);
  CHECK(k.sign(-2e-6) == -1);
  // Roots within epsilon of the query are not "strictly after" it.
  const kvd::Poly<double> p{-(1.0 + 5e-7), 1.0};
  CHECK_FALSE(k.next_root(p, 1.0));
}

TEST_CASE("the MPFR kernel computes at the precision it was given, in bits", "[kernel]") {
  const kvd::Mpfr_kernel wide(200);
  CHECK(wide.bits() == 200);
  kvd::Mpfr_number tiny = kvd::Mpfr_number(1) / kvd::Mpfr_number(1L << 30);
  tiny = tiny * tiny * tiny * tiny;  // 2^-120
  CHECK((kvd::Mpfr_number(1) + tiny) != kvd::Mpfr_number(1));
  CHECK((kvd::Mpfr_number(1) + tiny).precision() == 200);

  const kvd::Mpfr_kernel narrow(53);
  kvd::Mpfr_number tiny53 = kvd::Mpfr_number(1) / kvd::Mpfr_number(1L << 30);
  tiny53 = tiny53 * tiny53;  // 2^-60 is below half an ulp of 1 at 53 bits
  CHECK((kvd::Mpfr_number(1) + tiny53) == kvd::Mpfr_number(1));
  // Default epsilon 2^-(bits/2).
  CHECK(narrow.epsilon() == kvd::Mpfr_number(std::ldexp(1.0, -26)));
  // A root is located to the working precision.
  const kvd::Mpfr_kernel k(160);
  const kvd::Poly<kvd::Mpfr_number> p{kvd::Mpfr_number(-2), kvd::Mpfr_number(0), kvd::Mpfr_number(1)};
  const auto r = k.next_root(p, kvd::Mpfr_number(0));
  REQUIRE(r);
  const kvd::Mpfr_number err = abs((*r) * (*r) - kvd::Mpfr_number(2));
  kvd::Mpfr_number ulp = kvd::Mpfr_number(1);
  for (int i = 0; i < 150; ++i) ulp = ulp / kvd::Mpfr_number(2);
  CHECK(err < ulp);
}
