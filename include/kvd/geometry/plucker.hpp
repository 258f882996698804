// Projective geometry of P^3 in Plücker (Grassmann) coordinates, written once
// over a coefficient ring R: numbers give positions at an instant, time
// polynomials give motions.
//
// Conventions (W last everywhere, DESIGN.md section 3):
//  * Point4 (X, Y, Z, W) is the Euclidean point (X/W, Y/W, Z/W); W = 0 is a
//    direction (a point at infinity).
//  * Plane4 (a, b, c, d) is the plane aX + bY + cZ + dW = 0; dot(m, p) is
//    that left-hand side.
//  * Line: l = p ∨ q has the six coordinates l_ij = p_i q_j - p_j q_i in the
//    order (l01, l02, l12, l03, l13, l23), as in the thesis's Table 4.1. The
//    table writes W first; its formulas are determinant identities, so they
//    hold unchanged with W last once the index order is fixed.
//  * join(l, p) is Table 4.1's plane formula. With it,
//        dot(join(join(p, q), r), s) = det[p; q; r; s]        (rows)
//    so a point s is on the positive side of the plane through p, q, r when
//    det[p; q; r; s] > 0. For Euclidean points with W = 1 this is the side
//    *opposite* to the normal (q - p) x (r - p) of the right-hand rule.
//  * meet(l, m) for l = p ∨ q is the point (m·q) p - (m·p) q, that is
//        meet(l, m)_i = sum_j l_ij m_j   (l_ij antisymmetric);
//    it is the zero vector when the line lies in the plane.
//  * meet(a, b, c) is the point x with dot(y, x) = det[a; b; c; y] for all
//    covectors y: Table 4.1 applied to plane coordinates (duality), so
//    x lies on all three planes and is zero when they share a line.
//  * Orientation and W < 0: a homogeneous point and its negative are the same
//    Euclidean point but give opposite signs of dot(m, p). `side` therefore
//    returns sign(dot(m, p)) * sign(W): the side of the Euclidean point,
//    invariant under scaling p by any non-zero factor. For a direction
//    (W = 0), sign(W) is taken as +1: the side a point far along it lies on.
//    Derived points (meets) may well come out with W < 0.
//
// Templates are declared here and compiled once for the rings of every kernel
// (src/geometry/plucker_instances.cpp). For another ring, include
// plucker_impl.hpp.
#pragma once

#include <array>

namespace kvd {

template <class R>
struct Point4 {
  std::array<R, 4> c;  // X, Y, Z, W
  const R& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
  R& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  friend bool operator==(const Point4&, const Point4&) = default;
};

template <class R>
struct Plane4 {
  std::array<R, 4> c;  // aX + bY + cZ + dW = 0
  const R& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
  R& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  friend bool operator==(const Plane4&, const Plane4&) = default;
};

template <class R>
struct Line {
  std::array<R, 6> c;  // l01, l02, l12, l03, l13, l23
  const R& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
  R& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
  friend bool operator==(const Line&, const Line&) = default;
};

template <class R>
Line<R> join(const Point4<R>& p, const Point4<R>& q);
template <class R>
Plane4<R> join(const Line<R>& l, const Point4<R>& p);
template <class R>
Plane4<R> join(const Point4<R>& p, const Point4<R>& q, const Point4<R>& r);
template <class R>
Point4<R> meet(const Line<R>& l, const Plane4<R>& m);
template <class R>
Point4<R> meet(const Plane4<R>& a, const Plane4<R>& b, const Plane4<R>& c);
template <class R>
R dot(const Plane4<R>& m, const Point4<R>& p);
// The thesis's coplanar(p, q, r, s) (equation 6.3): det of the four rows.
template <class R>
R coplanar(const Point4<R>& p, const Point4<R>& q, const Point4<R>& r, const Point4<R>& s);

// The side of Euclidean point p with respect to plane m, decided by kernel k:
// k.sign(dot(m, p)) * sign(W) (see above).
template <class K>
int side(const K& k, const Point4<typename K::FT>& p, const Plane4<typename K::FT>& m) {
  const int w = k.sign(p[3]);
  return k.sign(dot(m, p)) * (w == 0 ? 1 : w);
}

}  // namespace kvd
