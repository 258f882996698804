#include "kvd/detail/symbolic/scene_geometry_impl.hpp"

#include <type_traits>

#include "kvd/kernel/convert.hpp"
#include "kvd/detail/kernel/instantiate.hpp"

namespace kvd::symbolic {

namespace {

// The same point (a vertex, or the direction x or z) with integer
// coefficients, primitive: scaled by the lcm of
// its denominators over the gcd of its numerators. Every sign the kernel
// decides is invariant under scaling a point by a positive factor
// (kvd/geometry/plucker.hpp), and on integers GMP's rational arithmetic
// skips its gcds. Only for the exact field: the floating-point builds keep
// the scene's numbers, as the thesis does.
void make_integral(scene::Motion_point& p) {
  mpz_class l = 1, g = 0;
  for (int k = 0; k < 4; ++k)
    for (const mpq_class& c : p[k].coefficients()) {
      mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
      mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_num_mpz_t());
    }
  if (g == 0) return;  // the zero point: nothing to scale
  mpq_class f(l, g);
  f.canonicalize();
  for (int k = 0; k < 4; ++k) p[k] = p[k] * scene::QPoly(f);
}

// The point as polynomials over FT, negated if its W is negative at `start`
// (a point with W identically zero, a direction, is kept as it is).
template <class FT>
Point4<Poly<FT>> normalized(scene::Motion_point p, const scene::Q& start) {
  if (sgn(p[3](start)) < 0)
    for (int k = 0; k < 4; ++k) p[k] = -p[k];
  if constexpr (std::is_same_v<FT, mpq_class>) make_integral(p);
  Point4<Poly<FT>> r;
  for (int k = 0; k < 4; ++k) r[k] = poly_from_rational<FT>(p[k]);
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
