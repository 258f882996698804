#include "kvd/query/render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kvd/query/visibility.hpp"

namespace kvd::query {

namespace {

using D3 = std::array<double, 3>;

D3 sub(const D3& a, const D3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot3(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
D3 cross(const D3& a, const D3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
D3 unit(const D3& a) {
  const double n = std::sqrt(dot3(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

// A qualitative palette, one colour an object.
const Rgb palette[] = {{0x8d, 0xd3, 0xc7}, {0xff, 0xff, 0xb3}, {0xbe, 0xba, 0xda}, {0xfb, 0x80, 0x72},
                       {0x80, 0xb1, 0xd3}, {0xfd, 0xb4, 0x62}, {0xb3, 0xde, 0x69}, {0xfc, 0xcd, 0xe5},
                       {0xd9, 0xd9, 0xd9}, {0xbc, 0x80, 0xbd}, {0xcc, 0xeb, 0xc5}, {0xff, 0xed, 0x6f}};

Rgb side_colour(const symbolic::Symbolic_edge& e) {
  switch (e.kind) {
    case symbolic::Symbolic_edge::Kind::pt: return {0xd6, 0x27, 0x28};    // P-cut: red
    case symbolic::Symbolic_edge::Kind::et: return {0x2c, 0xa0, 0x2c};    // E-cut: green
    case symbolic::Symbolic_edge::Kind::edge: return {0x1f, 0x4f, 0xd8};  // the triangle's own edge: blue
  }
  return {0, 0, 0};
}

}  // namespace

Camera::Camera(const D3& e, const D3& target, int image_size) : eye(e), size(image_size) {
  forward = unit(sub(target, eye));
  right = cross(forward, D3{0, 0, 1});
  if (dot3(right, right) < 1e-12) right = cross(forward, D3{0, 1, 0});
  right = unit(right);
  up = cross(right, forward);
}

std::optional<Camera::D2> Camera::project(const D3& p) const {
  const D3 d = sub(p, eye);
  const double depth = dot3(d, forward);
  if (depth <= 0) return std::nullopt;
  const D2 q{dot3(d, right) / depth, -dot3(d, up) / depth};
  return framed ? to_image(q) : q;
}

Camera::D2 Camera::to_image(const D2& q) const {
  return {(q[0] - cx) / span * size + size / 2.0, (q[1] - cy) / span * size + size / 2.0};
}

void Camera::frame(const D2& lo, const D2& hi) {
  span = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-9}) * 1.05;
  cx = (lo[0] + hi[0]) / 2, cy = (lo[1] + hi[1]) / 2;
  framed = true;
}

std::vector<Painted_polygon> paint(const predicates::Classifier<Exact_kernel>& c, const tree::Kvd_tree& tree,
                                   const Point4<mpq_class>& view, const Camera& camera, const mpq_class& t,
                                   const Render_options&) {
  const scene::Scene& s = c.motion().scene();
  std::vector<Painted_polygon> out;
  for (int i : back_to_front(c, tree, view, t)) {
    const tree::Node& n = tree.nodes[static_cast<std::size_t>(i)];
    const auto& f = std::get<tree::Triangle_fragment>(n.fragment);
    Painted_polygon poly{{}, {}, palette[s.triangle_object[n.cut.id] % (sizeof palette / sizeof *palette)]};
    bool visible = true;
    for (std::size_t k = 0; k < f.corners.size(); ++k) {
      const auto p = corner_at(c, f.corners[k], t);
      const auto q = camera.project({p[0].get_d(), p[1].get_d(), p[2].get_d()});
      if (!q) visible = false;  // behind the eye: left out
      else poly.points.push_back(*q);
      poly.sides.push_back(side_colour(f.sides[k]));
    }
    if (visible) out.push_back(std::move(poly));
  }
  return out;
}

Camera::D3 centroid(const scene::Scene& s, const mpq_class& t) {
  D3 centre{0, 0, 0};
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const auto p = s.position_at(v, t);
    for (int j = 0; j < 3; ++j)
      centre[static_cast<std::size_t>(j)] += mpq_class(p[j] / p[3]).get_d() / static_cast<double>(s.rest.size());
  }
  return centre;
}

std::vector<Painted_polygon> paint(const predicates::Classifier<Exact_kernel>& c, const tree::Kvd_tree& tree,
                                   const Point4<mpq_class>& view, const mpq_class& t, const Render_options& o) {
  const scene::Scene& s = c.motion().scene();
  const D3 eye{mpq_class(view[0] / view[3]).get_d(), mpq_class(view[1] / view[3]).get_d(),
               mpq_class(view[2] / view[3]).get_d()};
  Camera camera(eye, centroid(s, t), o.size);
  std::vector<Painted_polygon> out = paint(c, tree, view, camera, t, o);
  // Framed to the projected bounds of what is drawn.
  Camera::D2 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()}, hi{-lo[0], -lo[1]};
  for (const auto& poly : out)
    for (const auto& q : poly.points) {
      lo[0] = std::min(lo[0], q[0]), hi[0] = std::max(hi[0], q[0]);
      lo[1] = std::min(lo[1], q[1]), hi[1] = std::max(hi[1], q[1]);
    }
  camera.frame(lo, hi);
  for (auto& poly : out)
    for (auto& q : poly.points) q = camera.to_image(q);
  return out;
}

}  // namespace kvd::query
