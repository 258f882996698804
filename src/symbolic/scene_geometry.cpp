#include "kvd/detail/symbolic/scene_geometry_impl.hpp"

#include "kvd/kernel/convert.hpp"
#include "kvd/detail/kernel/instantiate.hpp"

namespace kvd::symbolic {

namespace {

// The point as polynomials over FT, negated if its W is negative at `start`
// (a point with W identically zero, a direction, is kept as it is).
template <class FT>
Point4<Poly<FT>> normalized(const scene::Motion_point& p, const scene::Q& start) {
  const int sign_w = sgn(p[3](start));
  Point4<Poly<FT>> r;
  for (int k = 0; k < 4; ++k) r[k] = poly_from_rational<FT>(sign_w < 0 ? scene::QPoly(-p[k]) : p[k]);
  return r;
}

}  // namespace

template <class FT>
Scene_geometry<Poly<FT>> motion_geometry(const scene::Scene& s) {
  std::vector<Point4<Poly<FT>>> v;
  for (std::size_t i = 0; i < s.rest.size(); ++i) v.push_back(normalized<FT>(s.position(i), s.start));
  return Scene_geometry<Poly<FT>>(s, std::move(v), normalized<FT>(s.x, s.start), normalized<FT>(s.z, s.start));
}

template <class FT>
Scene_geometry<FT> at_instant(const Scene_geometry<Poly<FT>>& g, const FT& t) {
  auto eval = [&](const Point4<Poly<FT>>& p) -> Point4<FT> { return {{p[0](t), p[1](t), p[2](t), p[3](t)}}; };
  std::vector<Point4<FT>> v;
  for (const auto& p : g.vertices()) v.push_back(eval(p));
  return Scene_geometry<FT>(g.scene(), std::move(v), eval(g.x()), eval(g.z()));
}

template <class FT>
Scene_geometry<Poly<Poly<FT>>> perturbed(const Scene_geometry<Poly<FT>>& g) {
  using T = Poly<FT>;
  using E = Poly<T>;
  auto constant = [](const T& c) { return E(std::vector<T>{c}); };
  std::vector<Point4<E>> v;
  for (std::size_t i = 0; i < g.vertices().size(); ++i) {
    const Point4<T>& p = g.vertex(i);
    const long n = static_cast<long>(i) + 1;
    const long gi[3] = {n, n * n, n * n * n};
    Point4<E> q;
    for (int k = 0; k < 3; ++k) q[k] = E(std::vector<T>{p[k], p[3] * T(FT(gi[k]))});
    q[3] = constant(p[3]);
    v.push_back(q);
  }
  auto lift = [&](const Point4<T>& p) -> Point4<E> {
    return {{constant(p[0]), constant(p[1]), constant(p[2]), constant(p[3])}};
  };
  return Scene_geometry<E>(g.scene(), std::move(v), lift(g.x()), lift(g.z()));
}

#define KVD_INSTANTIATE_SCENE_GEOMETRY(FT)                                                   \
  template class Scene_geometry<FT>;                                                         \
  template class Scene_geometry<Poly<FT>>;                                                   \
  template class Scene_geometry<Poly<Poly<FT>>>;                                             \
  template Scene_geometry<Poly<FT>> motion_geometry<FT>(const scene::Scene&);                \
  template Scene_geometry<FT> at_instant<FT>(const Scene_geometry<Poly<FT>>&, const FT&);    \
  template Scene_geometry<Poly<Poly<FT>>> perturbed<FT>(const Scene_geometry<Poly<FT>>&);
KVD_FOR_EACH_FIELD(KVD_INSTANTIATE_SCENE_GEOMETRY)

}  // namespace kvd::symbolic
