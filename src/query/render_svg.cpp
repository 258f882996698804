#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "kvd/query/render.hpp"
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
const char* const palette[] = {"#8dd3c7", "#ffffb3", "#bebada", "#fb8072", "#80b1d3", "#fdb462",
                               "#b3de69", "#fccde5", "#d9d9d9", "#bc80bd", "#ccebc5", "#ffed6f"};

const char* side_colour(const symbolic::Symbolic_edge& e) {
  switch (e.kind) {
    case symbolic::Symbolic_edge::Kind::pt: return "#d62728";  // P-cut: red
    case symbolic::Symbolic_edge::Kind::et: return "#2ca02c";  // E-cut: green
    case symbolic::Symbolic_edge::Kind::edge: return "#1f4fd8";  // the triangle's own edge: blue
  }
  return "#000000";
}

}  // namespace

std::string render_svg(const predicates::Classifier<Exact_kernel>& c, const tree::Kvd_tree& tree,
                       const Point4<mpq_class>& view, const mpq_class& t, const Render_options& o) {
  const scene::Scene& s = c.motion().scene();
  const D3 eye{mpq_class(view[0] / view[3]).get_d(), mpq_class(view[1] / view[3]).get_d(),
               mpq_class(view[2] / view[3]).get_d()};
  D3 centre{0, 0, 0};
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const auto p = s.position_at(v, t);
    for (int j = 0; j < 3; ++j) centre[static_cast<std::size_t>(j)] += mpq_class(p[j] / p[3]).get_d() / static_cast<double>(s.rest.size());
  }
  const D3 forward = unit(sub(centre, eye));
  D3 right = cross(forward, D3{0, 0, 1});
  if (dot3(right, right) < 1e-12) right = cross(forward, D3{0, 1, 0});
  right = unit(right);
  const D3 up = cross(right, forward);

  struct Polygon {
    std::vector<std::array<double, 2>> points;
    std::vector<const char*> sides;
    const char* fill;
  };
  std::vector<Polygon> polygons;
  double lo_x = std::numeric_limits<double>::max(), lo_y = lo_x, hi_x = -lo_x, hi_y = -lo_x;
  for (int i : back_to_front(c, tree, view, t)) {
    const tree::Node& n = tree.nodes[static_cast<std::size_t>(i)];
    const auto& f = std::get<tree::Triangle_fragment>(n.fragment);
    Polygon poly{{}, {}, palette[s.triangle_object[n.cut.id] % (sizeof palette / sizeof *palette)]};
    bool visible = true;
    for (std::size_t k = 0; k < f.corners.size(); ++k) {
      const auto p = c.position(f.corners[k]);
      const mpq_class w = p[3](t);
      const D3 x{mpq_class(p[0](t) / w).get_d(), mpq_class(p[1](t) / w).get_d(), mpq_class(p[2](t) / w).get_d()};
      const D3 d = sub(x, eye);
      const double depth = dot3(d, forward);
      if (depth <= 0) visible = false;  // behind the eye: left out
      const std::array<double, 2> q{dot3(d, right) / depth, -dot3(d, up) / depth};
      poly.points.push_back(q);
      poly.sides.push_back(side_colour(f.sides[k]));
    }
    if (!visible) continue;
    for (const auto& q : poly.points) {
      lo_x = std::min(lo_x, q[0]), hi_x = std::max(hi_x, q[0]);
      lo_y = std::min(lo_y, q[1]), hi_y = std::max(hi_y, q[1]);
    }
    polygons.push_back(std::move(poly));
  }
  const double span = std::max({hi_x - lo_x, hi_y - lo_y, 1e-9}) * 1.05;
  const double cx = (lo_x + hi_x) / 2, cy = (lo_y + hi_y) / 2;
  // Image coordinates: the projected bounds, centred, with a 5% margin.
  auto to_image = [&](const std::array<double, 2>& q) -> std::array<double, 2> {
    return {(q[0] - cx) / span * o.size + o.size / 2.0, (q[1] - cy) / span * o.size + o.size / 2.0};
  };
  auto format = [](const char* pattern, double a, double b, double c = 0, double d = 0) {
    char buf[128];
    std::snprintf(buf, sizeof buf, pattern, a, b, c, d);
    return std::string(buf);
  };
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.size << "\" height=\"" << o.size
      << "\" viewBox=\"0 0 " << o.size << " " << o.size << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const auto& poly : polygons) {
    svg << "<polygon points=\"";
    for (std::size_t k = 0; k < poly.points.size(); ++k) {
      const auto q = to_image(poly.points[k]);
      svg << (k ? " " : "") << format("%.2f,%.2f", q[0], q[1]);
    }
    svg << "\" fill=\"" << poly.fill << "\" stroke=\"" << (o.cells ? "none" : "#555555") << "\" stroke-width=\"0.5\"/>\n";
    if (!o.cells) continue;
    for (std::size_t k = 0; k < poly.points.size(); ++k) {
      const auto a = to_image(poly.points[k]), b = to_image(poly.points[(k + 1) % poly.points.size()]);
      svg << "<line " << format("x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"", a[0], a[1], b[0], b[1])
          << " stroke=\"" << poly.sides[k] << "\" stroke-width=\"1.2\"/>\n";
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace kvd::query
