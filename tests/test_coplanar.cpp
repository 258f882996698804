// The coplanarity determinant (thesis equation 6.3) over time polynomials:
// known factors on hand-built motions, agreement with the Leibniz formula,
// and with evaluation at instants.
#include <catch2/catch.hpp>
#include <random>

#include "kernels.hpp"
#include "kvd/geometry/plucker.hpp"
#include "kvd/detail/kernel/determinant.hpp"

namespace {

using P = kvd::Poly<mpq_class>;
using Pt = kvd::Point4<P>;

P lin(long c0, long c1) { return P{mpq_class(c0), mpq_class(c1)}; }
P cst(long c) { return P{mpq_class(c)}; }

// The Leibniz formula: 24 signed products, an independent reference.
template <class R>
R leibniz(const kvd::Matrix4<R>& m) {
  int perm[4] = {0, 1, 2, 3};
  R sum(0);
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
    R term(1);
    for (int i = 0; i < 4; ++i) term *= m[static_cast<std::size_t>(i)][static_cast<std::size_t>(perm[i])];
    if (inversions % 2) sum -= term;
    else sum += term;
  } while (std::next_permutation(perm, perm + 4));
  return sum;
}

}  // namespace

TEST_CASE("coplanar of hand-built linear motions equals the product of known factors", "[coplanar]") {
  // Origin and three points moving along the axes: coplanar exactly when one
  // of them passes through the origin.
  const Pt a{{lin(-1, 1), cst(0), cst(0), cst(1)}};
  const Pt b{{cst(0), lin(-2, 1), cst(0), cst(1)}};
  const Pt c{{cst(0), cst(0), lin(-3, 2), cst(1)}};
  const Pt o{{cst(0), cst(0), cst(0), cst(1)}};
  CHECK(kvd::coplanar(a, b, c, o) == lin(-1, 1) * lin(-2, 1) * lin(-3, 2));
  // Two points turning around the z axis: (t-1, 1) and (0, t-2) in the xy
  // plane are collinear with the axis when their cross product vanishes.
  const Pt p{{lin(-1, 1), cst(1), cst(0), cst(1)}};
  const Pt q{{cst(0), cst(0), cst(0), cst(1)}};
  const Pt r{{cst(0), cst(0), cst(1), cst(1)}};
  const Pt s{{cst(0), lin(-2, 1), cst(0), cst(1)}};
  CHECK(kvd::coplanar(p, q, r, s) == -(lin(-1, 1) * lin(-2, 1)));
  // The thesis's VV form coplanar(v1, v2, x, z) with x, z the axis directions:
  // the P-planes of v1 and v2 coincide when their y coordinates agree.
  const Pt v1{{cst(3), lin(0, 2), cst(1), cst(1)}};
  const Pt v2{{cst(-1), lin(5, 1), cst(4), cst(1)}};
  const Pt x{{cst(1), cst(0), cst(0), cst(0)}};
  const Pt z{{cst(0), cst(0), cst(1), cst(0)}};
  CHECK(kvd::coplanar(v1, v2, x, z) == lin(5, -1));  // y2 - y1 = 5 - t
  // The sign convention follows the rows: swapping two rows negates.
  CHECK(kvd::coplanar(v2, v1, x, z) == lin(-5, 1));
}

TEST_CASE("det4 agrees with the Leibniz formula", "[coplanar]") {
  std::mt19937 g(5);
  std::uniform_int_distribution<long> c(-1000, 1000);
  for (int i = 0; i < 300; ++i) {
    kvd::Matrix4<mpq_class> m;
    for (auto& row : m)
      for (auto& e : row) e = kvd::test::q(c(g), 1 + std::abs(c(g)));
    CHECK(kvd::det4(m) == leibniz(m));
  }
  for (int i = 0; i < 50; ++i) {
    kvd::Matrix4<P> m;
    for (auto& row : m)
      for (auto& e : row) e = P{mpq_class(c(g)), mpq_class(c(g)), mpq_class(c(g))};
    CHECK(kvd::det4(m) == leibniz(m));
  }
}

TEST_CASE("coplanar of moving points evaluates to coplanar of their positions", "[coplanar]") {
  std::mt19937 g(9);
  std::uniform_int_distribution<long> c(-30, 30);
  for (int i = 0; i < 100; ++i) {
    Pt pts[4];
    for (auto& p : pts) {
      for (int k = 0; k < 3; ++k) p[k] = lin(c(g), c(g));
      p[3] = cst(1);
    }
    const P d = kvd::coplanar(pts[0], pts[1], pts[2], pts[3]);
    CHECK(d.degree() <= 3);  // linear motion with W = 1: degree at most 3
    for (int j = -4; j <= 4; ++j) {
      const mpq_class t = kvd::test::q(j, 3);
      kvd::Point4<mpq_class> at[4];
      for (int a = 0; a < 4; ++a)
        for (int k = 0; k < 4; ++k) at[a][k] = pts[a][k](t);
      CHECK(d(t) == kvd::coplanar(at[0], at[1], at[2], at[3]));
    }
  }
}

TEMPLATE_TEST_CASE("the coplanarity time of a point crossing a plane is found by every kernel", "[coplanar]",
                   KVD_ALL_KERNELS) {
  using FT = typename TestType::FT;
  using Q = typename TestType::Poly;
  const TestType k;
  // A point falling through z = 0 at t = 3: z(t) = 6 - 2t.
  const kvd::Point4<Q> falling{{Q(FT(1)), Q(FT(1)), Q{FT(6), FT(-2)}, Q(FT(1))}};
  const kvd::Point4<Q> a{{Q(FT(0)), Q(FT(0)), Q(FT(0)), Q(FT(1))}};
  const kvd::Point4<Q> b{{Q(FT(4)), Q(FT(0)), Q(FT(0)), Q(FT(1))}};
  const kvd::Point4<Q> c{{Q(FT(0)), Q(FT(4)), Q(FT(0)), Q(FT(1))}};
  const Q d = kvd::coplanar(a, b, c, falling);
  const auto r = k.next_root(d, k.time(FT(0)));
  REQUIRE(r);
  CHECK(k.compare(*r, k.time(FT(3))) == 0);
  // det[a;b;c;s] is negative above the plane through a, b, c (counterclockwise
  // from above) and positive below: the falling point goes from - to +.
  CHECK(k.sign_at(d, k.time(FT(0))) == -1);
  CHECK(k.sign_after(d, *r) == 1);
}
