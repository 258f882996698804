// Plücker joins and meets: incidence identities in every kernel, exact hand
// computations, the side convention for W < 0, and the same formulas over time
// polynomials.
#include <catch2/catch.hpp>
#include <random>

#include "kernels.hpp"
#include "kvd/geometry/plucker.hpp"

namespace {

template <class R>
kvd::Point4<R> pt(long x, long y, long z, long w) {
  return {{R(x), R(y), R(z), R(w)}};
}
template <class R>
kvd::Plane4<R> pl(long a, long b, long c, long d) {
  return {{R(a), R(b), R(c), R(d)}};
}

// Small random integers (below 2^6): every value below stays under 2^53, so
// it is exact in double and MPFR too and identities hold exactly in all three
// kernels.
template <class R>
kvd::Point4<R> random_point(std::mt19937& g) {
  std::uniform_int_distribution<long> c(-50, 50);
  return pt<R>(c(g), c(g), c(g), c(g));
}
template <class R>
kvd::Plane4<R> random_plane(std::mt19937& g) {
  std::uniform_int_distribution<long> c(-50, 50);
  return pl<R>(c(g), c(g), c(g), c(g));
}

}  // namespace

TEMPLATE_TEST_CASE("join(join(p,q),r) vanishes on p, q and r", "[plucker]", KVD_ALL_KERNELS) {
  using FT = typename TestType::FT;
  std::mt19937 g(42);
  for (int i = 0; i < 200; ++i) {
    const auto p = random_point<FT>(g), q = random_point<FT>(g), r = random_point<FT>(g), s = random_point<FT>(g);
    const auto m = kvd::join(kvd::join(p, q), r);
    CHECK(kvd::dot(m, p) == FT(0));
    CHECK(kvd::dot(m, q) == FT(0));
    CHECK(kvd::dot(m, r) == FT(0));
    // The documented identity: dot(join(p,q,r), s) = det[p; q; r; s].
    CHECK(kvd::dot(m, s) == kvd::coplanar(p, q, r, s));
    CHECK(kvd::join(p, q, r) == m);
  }
}

TEMPLATE_TEST_CASE("meet(line, plane) lies on both", "[plucker]", KVD_ALL_KERNELS) {
  using FT = typename TestType::FT;
  std::mt19937 g(7);
  const kvd::Plane4<FT> zero = pl<FT>(0, 0, 0, 0);
  for (int i = 0; i < 200; ++i) {
    const auto p = random_point<FT>(g), q = random_point<FT>(g);
    const auto m = random_plane<FT>(g);
    const auto l = kvd::join(p, q);
    const auto x = kvd::meet(l, m);
    CHECK(kvd::dot(m, x) == FT(0));
    CHECK(kvd::join(l, x) == zero);  // x on the line: the plane l ∨ x degenerates
    // The documented closed form (m·q) p - (m·p) q.
    for (int c = 0; c < 4; ++c) CHECK(x[c] == kvd::dot(m, q) * p[c] - kvd::dot(m, p) * q[c]);
  }
}

TEMPLATE_TEST_CASE("meet of three planes lies on all three", "[plucker]", KVD_ALL_KERNELS) {
  using FT = typename TestType::FT;
  std::mt19937 g(11);
  for (int i = 0; i < 200; ++i) {
    const auto a = random_plane<FT>(g), b = random_plane<FT>(g), c = random_plane<FT>(g);
    const auto x = kvd::meet(a, b, c);
    CHECK(kvd::dot(a, x) == FT(0));
    CHECK(kvd::dot(b, x) == FT(0));
    CHECK(kvd::dot(c, x) == FT(0));
  }
}

TEMPLATE_TEST_CASE("joins and meets equal hand computations", "[plucker]", KVD_ALL_KERNELS) {
  using FT = typename TestType::FT;
  // The line through the origin and (1,0,0): only l03 = 0*1 - 1*1 = -1.
  const auto l = kvd::join(pt<FT>(0, 0, 0, 1), pt<FT>(1, 0, 0, 1));
  CHECK(l == kvd::Line<FT>{{FT(0), FT(0), FT(0), FT(-1), FT(0), FT(0)}});
  // With (0,1,0): the plane z = 0, as -Z = 0 by Table 4.1.
  CHECK(kvd::join(l, pt<FT>(0, 1, 0, 1)) == pl<FT>(0, 0, -1, 0));
  // The z axis meets the plane z = 2 (Z - 2W = 0) at (0,0,2).
  const auto axis = kvd::join(pt<FT>(0, 0, 0, 1), pt<FT>(0, 0, 1, 1));
  CHECK(kvd::meet(axis, pl<FT>(0, 0, 1, -2)) == pt<FT>(0, 0, 2, 1));
  // A line inside the plane meets it in the zero vector.
  CHECK(kvd::meet(axis, pl<FT>(1, 0, 0, 0)) == pt<FT>(0, 0, 0, 0));
  // x = 1, y = 2, z = 3 meet at (1,2,3).
  CHECK(kvd::meet(pl<FT>(1, 0, 0, -1), pl<FT>(0, 1, 0, -2), pl<FT>(0, 0, 1, -3)) == pt<FT>(1, 2, 3, 1));
  // Directions: the plane through the origin spanned by x and z is y = 0;
  // its Y coefficient is det[e3; e0; e2; e1] = +1 (an even permutation).
  CHECK(kvd::join(pt<FT>(0, 0, 0, 1), pt<FT>(1, 0, 0, 0), pt<FT>(0, 0, 1, 0)) == pl<FT>(0, 1, 0, 0));
}

TEMPLATE_TEST_CASE("side is the side of the Euclidean point, whatever the sign of W", "[plucker]",
                   KVD_ALL_KERNELS) {
  using FT = typename TestType::FT;
  const TestType k;
  // Through (0,0,0), (1,0,0), (0,1,0): positive side opposite to the
  // right-hand normal +z (documented in plucker.hpp).
  const auto m = kvd::join(pt<FT>(0, 0, 0, 1), pt<FT>(1, 0, 0, 1), pt<FT>(0, 1, 0, 1));
  CHECK(kvd::side(k, pt<FT>(0, 0, 1, 1), m) == -1);
  CHECK(kvd::side(k, pt<FT>(0, 0, -1, 1), m) == 1);
  CHECK(kvd::side(k, pt<FT>(5, 7, 0, 1), m) == 0);
  // (0,0,-2,-2) is the Euclidean point (0,0,1).
  CHECK(kvd::side(k, pt<FT>(0, 0, -2, -2), m) == -1);
  CHECK(kvd::side(k, pt<FT>(0, 0, 3, -1), m) == 1);
  // A direction: +z lies on the negative side.
  CHECK(kvd::side(k, pt<FT>(0, 0, 1, 0), m) == -1);
}

TEST_CASE("the formulas commute with evaluation over time polynomials", "[plucker]") {
  using P = kvd::Poly<mpq_class>;
  std::mt19937 g(3);
  std::uniform_int_distribution<long> c(-20, 20);
  auto moving = [&] {
    kvd::Point4<P> p;
    for (int i = 0; i < 4; ++i) p[i] = P{mpq_class(c(g)), kvd::test::q(c(g), 3)};
    return p;
  };
  auto at = [](const kvd::Point4<P>& p, const mpq_class& t) {
    return kvd::Point4<mpq_class>{{p[0](t), p[1](t), p[2](t), p[3](t)}};
  };
  for (int i = 0; i < 50; ++i) {
    const auto p = moving(), q = moving(), r = moving(), s = moving();
    const auto m = kvd::join(p, q, r);
    const auto x = kvd::meet(kvd::join(p, q), kvd::join(r, s, moving()));
    CHECK(m[0].degree() <= 3);
    for (int j = -3; j <= 3; ++j) {
      const mpq_class t = kvd::test::q(j, 2);
      const auto mt = kvd::join(at(p, t), at(q, t), at(r, t));
      for (int a = 0; a < 4; ++a) CHECK(m[a](t) == mt[a]);
      CHECK(kvd::dot(m, s)(t) == kvd::dot(mt, at(s, t)));
      CHECK(kvd::dot(kvd::join(r, s, p), x)(t) == kvd::dot(kvd::join(at(r, t), at(s, t), at(p, t)), at(x, t)));
    }
  }
}
