// Definitions of the templates of plucker.hpp; see there for the conventions.
#pragma once

#include "kvd/geometry/plucker.hpp"
#include "kvd/detail/kernel/determinant.hpp"

namespace kvd {

namespace detail {
// Table 4.1's plane formula on raw coordinates: the covector m with
// m·s = det[p; q; r; s] when l = p ∨ q and x = r.
template <class R>
std::array<R, 4> line_join_point(const Line<R>& l, const std::array<R, 4>& x) {
  return {-l[2] * x[3] + l[4] * x[2] - l[5] * x[1],  //
          l[1] * x[3] - l[3] * x[2] + l[5] * x[0],   //
          -l[0] * x[3] + l[3] * x[1] - l[4] * x[0],  //
          l[0] * x[2] - l[1] * x[1] + l[2] * x[0]};
}
template <class R>
Line<R> wedge(const std::array<R, 4>& p, const std::array<R, 4>& q) {
  return {{p[0] * q[1] - p[1] * q[0], p[0] * q[2] - p[2] * q[0], p[1] * q[2] - p[2] * q[1],
           p[0] * q[3] - p[3] * q[0], p[1] * q[3] - p[3] * q[1], p[2] * q[3] - p[3] * q[2]}};
}
}  // namespace detail

template <class R>
Line<R> join(const Point4<R>& p, const Point4<R>& q) {
  return detail::wedge(p.c, q.c);
}

template <class R>
Plane4<R> join(const Line<R>& l, const Point4<R>& p) {
  return {detail::line_join_point(l, p.c)};
}

template <class R>
Plane4<R> join(const Point4<R>& p, const Point4<R>& q, const Point4<R>& r) {
  return join(join(p, q), r);
}

template <class R>
Point4<R> meet(const Line<R>& l, const Plane4<R>& m) {
  return {{l[0] * m[1] + l[1] * m[2] + l[3] * m[3],  //
           -l[0] * m[0] + l[2] * m[2] + l[4] * m[3],  //
           -l[1] * m[0] - l[2] * m[1] + l[5] * m[3],  //
           -l[3] * m[0] - l[4] * m[1] - l[5] * m[2]}};
}

template <class R>
Point4<R> meet(const Plane4<R>& a, const Plane4<R>& b, const Plane4<R>& c) {
  return {detail::line_join_point(detail::wedge(a.c, b.c), c.c)};
}

template <class R>
R dot(const Plane4<R>& m, const Point4<R>& p) {
  return m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3] * p[3];
}

template <class R>
R coplanar(const Point4<R>& p, const Point4<R>& q, const Point4<R>& r, const Point4<R>& s) {
  return det4<R>({p.c, q.c, r.c, s.c});
}

}  // namespace kvd
