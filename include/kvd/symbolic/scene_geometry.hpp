// The geometry of symbolic features over a ring R: numbers at an instant,
// polynomials in t (motions), or polynomials in ε whose coefficients are
// polynomials in t (the symbolic perturbation of DESIGN.md section 4).
//
// Planes, with the orientation of plucker.hpp (dot(join(p,q,r), s) =
// det[p; q; r; s]):
//   SP(V) = x ∨ z ∨ v,   SP(E) = a ∨ b ∨ z for E = (a, b) as stored,
//   SP(T) = i ∨ j ∨ k for T = (i, j, k) as written.
// With the default directions the positive side of every P-plane is +y.
// Vertices are the meets their names say. Scene vertices (and Euclidean
// decomposition points) are scaled so that W > 0 at the start time; W does
// not vanish while the scene is valid, so it stays positive, and only derived
// vertices need the sign of W when sides are taken.
#pragma once

#include <utility>
#include <vector>

#include "kvd/geometry/plucker.hpp"
#include "kvd/kernel/poly.hpp"
#include "kvd/scene/scene.hpp"
#include "kvd/symbolic/symbolic.hpp"

namespace kvd::symbolic {

template <class R>
class Scene_geometry {
public:
  Scene_geometry(const scene::Scene& s, std::vector<Point4<R>> vertices, Point4<R> x, Point4<R> z)
      : scene_(&s), vertices_(std::move(vertices)), x_(std::move(x)), z_(std::move(z)) {}

  const scene::Scene& scene() const { return *scene_; }
  const Point4<R>& vertex(std::size_t v) const { return vertices_.at(v); }
  const std::vector<Point4<R>>& vertices() const { return vertices_; }
  const Point4<R>& x() const { return x_; }
  const Point4<R>& z() const { return z_; }

  Plane4<R> plane(const Symbolic_plane& p) const;
  Point4<R> point(const Symbolic_vertex& v) const;

  // For a geometry at an instant that evaluates only the vertices it needs
  // (the interval filter, at each new instant): replace positions in place.
  void set_vertex(std::size_t v, Point4<R> p) { vertices_.at(v) = std::move(p); }
  void set_directions(Point4<R> x, Point4<R> z) {
    x_ = std::move(x);
    z_ = std::move(z);
  }

private:
  const scene::Scene* scene_;
  std::vector<Point4<R>> vertices_;
  Point4<R> x_, z_;
};

// The scene's motion over FT: every vertex, x and z as polynomials in t,
// with W > 0 at the start. For the exact field each point is scaled by a
// positive rational to primitive integer coefficients (every sign the same).
template <class FT>
Scene_geometry<Poly<FT>> motion_geometry(const scene::Scene& s);
// The same geometry at the instant t.
template <class FT>
Scene_geometry<FT> at_instant(const Scene_geometry<Poly<FT>>& g, const FT& t);
// Vertex i moved by ε g_i, g_i = (i+1, (i+1)^2, (i+1)^3) on the moment curve
// (in Euclidean terms: X + ε g_x W, ...); x and z are not perturbed. The
// result's coefficients are polynomials in ε over polynomials in t.
template <class FT>
Scene_geometry<Poly<Poly<FT>>> perturbed(const Scene_geometry<Poly<FT>>& g);

}  // namespace kvd::symbolic
