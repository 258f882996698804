// The scene model: objects, vertices, edges, triangles with their incidence,
// motions, decomposition directions and the priority order (the scene format
// page, "Derived structure" and "Priority order").
//
// Ids of vertices, edges and triangles are global, in file order of objects.
// Everything is exact (rational coefficients).
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kvd/geometry/plucker.hpp"
#include "kvd/kernel/poly.hpp"

namespace kvd::scene {

using Q = mpq_class;
using QPoly = Poly<Q>;
using QPoint = Point4<Q>;
using Motion_point = Point4<QPoly>;
using Motion_matrix = std::array<std::array<QPoly, 4>, 4>;

// A motion as the file gives it; `translation` is kept as such so that a scene
// writes back as it was read.
struct Motion {
  enum class Kind { none, translation, matrix, vertices };
  Kind kind = Kind::none;
  std::array<QPoly, 3> translation;
  Motion_matrix matrix;                // for `matrix`
  std::vector<Motion_point> vertices;  // for `vertices`, one per vertex of the object
  friend bool operator==(const Motion&, const Motion&) = default;
};

struct Object {
  std::string name;  // may be empty
  std::size_t first_vertex = 0, vertex_count = 0;
  std::size_t first_triangle = 0, triangle_count = 0;
  Motion motion;
  friend bool operator==(const Object&, const Object&) = default;
};

// The priority source of the file: a seed, or an explicit list.
struct Priority_spec {
  std::uint64_t seed = 0;
  std::optional<std::vector<std::size_t>> order;  // global triangle ids, highest first
  friend bool operator==(const Priority_spec&, const Priority_spec&) = default;
};

class Scene {
public:
  std::string name;
  Q start = 0;
  std::optional<Q> end;
  Motion_point x, z;  // decomposition directions (or Euclidean points)
  Priority_spec priority_spec;
  std::vector<Object> objects;

  // Rest positions (homogeneous constants), one per global vertex.
  std::vector<QPoint> rest;
  // Triangles as global vertex ids in file order (orientation i, j, k).
  std::vector<std::array<std::size_t, 3>> triangles;

  // Derived by `derive()`: incidence and priorities.
  std::vector<std::size_t> vertex_object, triangle_object, edge_object;
  std::vector<std::array<std::size_t, 2>> edges;           // global vertex ids, as first seen
  std::vector<std::array<std::size_t, 3>> triangle_edges;  // edges (i,j), (j,k), (k,i)
  std::vector<std::vector<std::size_t>> vertex_edges, edge_triangles;
  std::vector<std::size_t> priority_order;  // triangle ids, highest priority first
  std::vector<std::size_t> triangle_priority;  // TPO of each triangle (0 = highest)
  std::vector<std::size_t> vertex_cut_priority, edge_cut_priority, triangle_cut_priority;

  // Recomputes every derived member from the primary ones above.
  void derive();

  // Whether an object's vertices depend on time. An object without motion is
  // static, and so is one whose motion polynomials are all constant.
  bool is_moving(std::size_t object) const;
  std::size_t moving_triangle_count() const;
  // The largest degree in t among all motion polynomials (0 for a static scene).
  int max_motion_degree() const;

  // The homogeneous position of a vertex as polynomials in t.
  Motion_point position(std::size_t vertex) const;
  // The homogeneous position at the instant t.
  QPoint position_at(std::size_t vertex, const Q& t) const;

  friend bool operator==(const Scene& a, const Scene& b) {
    return a.name == b.name && a.start == b.start && a.end == b.end && a.x == b.x && a.z == b.z &&
           a.priority_spec == b.priority_spec && a.objects == b.objects && a.rest == b.rest &&
           a.triangles == b.triangles;
  }
};

// Evaluates each coordinate at t.
QPoint evaluate(const Motion_point& p, const Q& t);

// p(t + shift) (a Taylor shift).
QPoly shifted(const QPoly& p, const Q& shift);
// The same scene with time re-measured from `shift`: every motion polynomial
// p(t) becomes p(t + shift), and the time span moves by -shift, so the scene
// at t equals the original at t + shift.
Scene retimed(const Scene& s, const Q& shift);
// The motion reversed at r (X-collide, thesis 7.3.3): every polynomial p(t)
// becomes p(2r - t), so the object is where it was at r and every velocity
// changes sign there.
Motion reversed(const Motion& m, const Q& r);

}  // namespace kvd::scene
