#include "kvd/predicates/in_triangle.hpp"

#include <optional>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/geometry/plucker.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::predicates {

namespace {

// A coordinate axis not parallel to the plane of `triangle` at t, as a
// direction (the first of x, y, z); none when the triangle is degenerate at t.
template <class K>
std::optional<Point4<typename K::Poly>> axis_off(const Classifier<K>& c, std::size_t triangle,
                                                 const typename K::Time& t) {
  using P = typename K::Poly;
  const Plane4<P>& plane = c.plane_poly(symbolic::Symbolic_plane{symbolic::Symbolic_plane::Kind::T, triangle});
  for (int axis = 0; axis < 3; ++axis) {
    Point4<P> w{{P(), P(), P(), P()}};
    w[axis] = P(typename K::FT(1));
    if (c.kernel().sign_at(dot(plane, w), t) != 0) return w;
  }
  return std::nullopt;
}

}  // namespace

template <class K>
bool in_closed_triangle(const Classifier<K>& c, const symbolic::Symbolic_vertex& vertex, std::size_t triangle,
                        const typename K::Time& t) {
  using P = typename K::Poly;
  const K& k = c.kernel();
  const Point4<P> v = c.position(vertex);
  const int w_sign = k.sign_at(v[3], t);
  if (w_sign == 0) return false;  // a point at infinity touches nothing
  const auto& tri = c.motion().scene().triangles[triangle];
  const std::optional<Point4<P>> w = axis_off(c, triangle, t);
  if (!w) return false;  // the triangle is degenerate at t
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& a = c.motion().vertex(tri[i]);
    const auto& b = c.motion().vertex(tri[(i + 1) % 3]);
    const auto& opposite = c.motion().vertex(tri[(i + 2) % 3]);
    const Plane4<P> side = join(a, b, *w);
    // Scene vertices have W > 0; the vertex's sign of W corrects its side.
    if (w_sign * k.sign_at(dot(side, v), t) * k.sign_at(dot(side, opposite), t) < 0) return false;
  }
  return true;
}

template <class K>
bool coplanar_triangles_meet(const Classifier<K>& c, std::size_t a, std::size_t b, const typename K::Time& t) {
  using P = typename K::Poly;
  using SV = symbolic::Symbolic_vertex;
  const K& k = c.kernel();
  const auto& tri = c.motion().scene().triangles;
  for (std::size_t i = 0; i < 3; ++i)
    if (in_closed_triangle(c, SV::endpoint(tri[a][i]), b, t) || in_closed_triangle(c, SV::endpoint(tri[b][i]), a, t))
      return true;
  const std::optional<Point4<P>> w = axis_off(c, b, t);
  if (!w) return false;  // degenerate at t
  // Which side of the line through p and q a point of the plane is on.
  const auto side = [&](const Point4<P>& p, const Point4<P>& q, const Point4<P>& x) {
    return k.sign_at(dot(join(p, q, *w), x), t);  // scene vertices have W > 0
  };
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& p = c.motion().vertex(tri[a][i]);
    const auto& q = c.motion().vertex(tri[a][(i + 1) % 3]);
    for (std::size_t j = 0; j < 3; ++j) {
      const auto& r = c.motion().vertex(tri[b][j]);
      const auto& u = c.motion().vertex(tri[b][(j + 1) % 3]);
      const int r_side = side(p, q, r), u_side = side(p, q, u);
      if (r_side == 0 && u_side == 0) continue;  // on one line: a corner is in the other, tested above
      if (r_side * u_side <= 0 && side(r, u, p) * side(r, u, q) <= 0) return true;
    }
  }
  return false;
}

#define KVD_INSTANTIATE_IN_CLOSED_TRIANGLE(K)                                                               \
  template bool in_closed_triangle<K>(const Classifier<K>&, const symbolic::Symbolic_vertex&, std::size_t, \
                                      const K::Time&);                                    \
  template bool coplanar_triangles_meet<K>(const Classifier<K>&, std::size_t, std::size_t, const K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_IN_CLOSED_TRIANGLE)

}  // namespace kvd::predicates
