#include "kvd/segments/segment_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

namespace kvd::segments {

namespace {

struct Pt {
  Q x, y;
};

// Homogeneous points and lines over polynomials in ε whose coefficients are
// polynomials in u, the time after t.
using U = QPoly;
using E = Poly<U>;
using H = std::array<E, 3>;

H wedge(const H& a, const H& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// p(t + u) as a polynomial in u.
U shifted(const QPoly& p, const Q& t) {
  std::vector<Q> c;
  Q factorial = 1;
  QPoly d = p;
  for (long k = 0; !d.is_zero(); ++k) {
    if (k > 0) factorial *= k;
    c.push_back(d(t) / factorial);
    d = d.derivative();
  }
  return U(std::move(c));
}

// Where the crossing of segments i and j is just after t: the meet of their
// lines at t; where that vanishes (the lines coincide at t), its limit as
// time grows; where the lines coincide through time, the limit of the meet
// of the lines the predicates perturb (segment_predicates.hpp: endpoint e
// moved by ε (λ_e, λ_e^2), ε -> 0 before time), which is where the tree
// has them cross.
Pt crossing(const Segment_scene& s, std::size_t i, std::size_t j, const Q& t) {
  const auto endpoint = [&](std::size_t e) {
    const Motion_point3 m = s.endpoint(e);
    const U w = shifted(m[2], t);
    const Q l(perturbation_lambda(e, s.segments.size()));
    return H{E({shifted(m[0], t), w * U(l)}), E({shifted(m[1], t), w * U(l * l)}), E(w)};
  };
  const H p = wedge(wedge(endpoint(2 * i), endpoint(2 * i + 1)), wedge(endpoint(2 * j), endpoint(2 * j + 1)));
  for (int k = 0; k <= std::max({p[0].degree(), p[1].degree(), p[2].degree()}); ++k) {
    const std::array<U, 3> c{p[0][k], p[1][k], p[2][k]};  // the coefficients of ε^k
    for (int m = 0; m <= std::max({c[0].degree(), c[1].degree(), c[2].degree()}); ++m) {
      if (c[0][m] == 0 && c[1][m] == 0 && c[2][m] == 0) continue;
      if (c[2][m] == 0) break;  // at infinity: not where two segments cross
      return {c[0][m] / c[2][m], c[1][m] / c[2][m]};
    }
  }
  throw std::logic_error("segment_svg: segments " + std::to_string(i) + " and " + std::to_string(j) +
                         " have no crossing to draw");
}

// The positions at t, exact.
class Geometry {
public:
  Geometry(const Segment_scene& s, const Q& t) : s_(s), t_(t) {
    for (std::size_t e = 0; e < s.endpoint_count(); ++e) {
      const Point3 p = s.endpoint_at(e, t);
      endpoints_.push_back({p[0] / p[2], p[1] / p[2]});
    }
  }
  const Pt& endpoint(std::size_t e) const { return endpoints_[e]; }
  const Pt& point(const Site_point& p) const {
    if (p.kind == Site_point::Kind::endpoint) return endpoints_[p.a];
    auto it = crossings_.find(p);
    if (it == crossings_.end()) it = crossings_.emplace(p, crossing(s_, p.a, p.b, t_)).first;
    return it->second;
  }
  // The y of the line of segment s at x. A vertical segment (at a flip's
  // instant) gives its top as a floor, since its cell lies above it, and its
  // bottom as a roof.
  Q y(std::uint32_t s, const Q& x, bool floor) const {
    const Pt &a = endpoints_[2 * s], &b = endpoints_[2 * s + 1];
    if (a.x == b.x) return floor == (a.y > b.y) ? a.y : b.y;
    return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
  }

private:
  const Segment_scene& s_;
  Q t_;
  std::vector<Pt> endpoints_;
  mutable std::map<Site_point, Pt> crossings_;
};

constexpr double pad = 8, line_height = 18, legend_height = 28;
constexpr double char_width = 8.4;  // of 14px monospace text

// Box coordinates to pixels, y up.
struct Pixels {
  View_box box;
  double scale, left, top;
  double x(const Q& v) const { return left + Q(v - box.x0).get_d() * scale; }
  double y(const Q& v) const { return top + Q(box.y1 - v).get_d() * scale; }
};

// A pixel coordinate: to a thousandth, so that rounding noise (1e-14) does
// not show, and 6 significant digits.
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", std::round(v * 1000) / 1000 + 0.0);  // + 0.0: no "-0"
  return buf;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

// `attributes`: more of them, each with its leading space.
void line(std::ostream& svg, const std::string& cls, double x1, double y1, double x2, double y2,
          const std::string& attributes = "") {
  svg << "<line class=\"" << cls << "\"" << attributes << " x1=\"" << num(x1) << "\" y1=\"" << num(y1) << "\" x2=\"" << num(x2)
      << "\" y2=\"" << num(y2) << "\"/>\n";
}

// t exactly when that is short, else to 6 digits.
std::string time_text(const Q& t) {
  const std::string exact = t.get_str();
  return exact.size() <= 20 ? "t = " + exact : "t ≈ " + num(t.get_d());
}

const char* const style_element =
    "<style>"
    "text{font:14px monospace;fill:#000}"
    ".view-box{fill:none;stroke:#c8c8c8}"
    ".cell{stroke:#b4b4b4;stroke-width:0.5}.c0{fill:#fbeecb}.c1{fill:#d9efd9}.c2{fill:#d6e4f5}.c3{fill:#f3dcec}"
    ".segment{stroke:#a0a0a0;stroke-width:1}"
    ".vertex-cut{stroke:#1f77b4;stroke-width:1.5;stroke-dasharray:6 4}"
    ".intersection-cut{stroke:#ff7f0e;stroke-width:1.5;stroke-dasharray:3 3}"
    ".edge-cut{stroke:#000;stroke-width:3;stroke-linecap:round}"
    ".endpoint{fill:#000}"
    ".crossing{stroke:#d62728;stroke-width:1.5;fill:none}"
    "</style>\n";

}  // namespace

std::string segment_svg_style() { return style_element; }

View_box view_box(const Segment_scene& s, const Q& t) {
  const Geometry g(s, t);
  View_box b{g.endpoint(0).x, g.endpoint(0).y, g.endpoint(0).x, g.endpoint(0).y};
  for (std::size_t e = 1; e < s.endpoint_count(); ++e) {
    const Pt& p = g.endpoint(e);
    b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
  }
  const Q side = std::max(Q(b.x1 - b.x0), Q(b.y1 - b.y0));
  const Q margin = side == 0 ? Q(1) : Q(side / 10);
  return {b.x0 - margin, b.y0 - margin, b.x1 + margin, b.y1 + margin};
}

View_box hull(const View_box& a, const View_box& b) {
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

namespace {

// Where the view box goes in pixels, below the caption's lines, and the
// picture's size with the legend under it.
struct Frame {
  View_box box;
  Pixels px;
  double width, height;  // of the box, in pixels
  Segment_picture size;
};

Frame frame(const Segment_scene& s, const Q& t, const Segment_svg_options& o) {
  const View_box box = o.box ? *o.box : view_box(s, t);
  const double width = Q(box.x1 - box.x0).get_d(), height = Q(box.y1 - box.y0).get_d();
  const double scale = std::min(o.size / width, o.size / height);
  const std::size_t lines = 2 + o.notes.size();
  const Pixels px{box, scale, (o.size - width * scale) / 2, pad + line_height * static_cast<double>(lines) + 4};
  const double bottom = px.top + height * scale;
  return {box, px, width * scale, height * scale, {o.size, static_cast<int>(std::ceil(bottom + legend_height)), {}}};
}

// The points of the intersection cuts, each once, in preorder.
std::vector<Site_point> cut_crossings(const Cylindrical_bsp& bsp, const std::vector<std::size_t>& preorder) {
  std::vector<Site_point> out;
  for (const std::size_t i : preorder)
    if (const Bsp_node& n = bsp.nodes[i];
        n.kind == Cut_kind::intersection && std::find(out.begin(), out.end(), n.point) == out.end())
      out.push_back(n.point);
  return out;
}

// The scene's name, t with the tree's size, then the notes.
std::vector<std::string> caption(const Segment_scene& s, const Bsp_counts& counts, const Q& t,
                                 const Segment_svg_options& o) {
  std::vector<std::string> lines{s.name.empty() ? "(unnamed scene)" : s.name,
                                 time_text(t) + ": " + std::to_string(counts.nodes) + " nodes (" +
                                     std::to_string(counts.leaves) + " leaves), height " +
                                     std::to_string(counts.height)};
  lines.insert(lines.end(), o.notes.begin(), o.notes.end());
  return lines;
}

// A pixel coordinate for a page that draws the picture itself: to a
// millionth, finer than the picture writes it, since the page interpolates
// the segments' lines between their endpoints (a steep one scales an error
// in x by its slope).
double rounded(double v) { return std::round(v * 1e6) / 1e6 + 0.0; }

}  // namespace

Segment_layout segment_layout(const Segment_scene& s, const Cylindrical_bsp& bsp, const Q& t,
                              const Segment_svg_options& o) {
  const Geometry g(s, t);
  const Frame f = frame(s, t, o);
  const auto at = [&](const Pt& p) { return std::array<double, 2>{rounded(f.px.x(p.x)), rounded(f.px.y(p.y))}; };
  Segment_layout out{f.size.width, f.size.height, rounded(f.px.left), rounded(f.px.top), rounded(f.width),
                     rounded(f.height), {}, {}, caption(s, bsp.counts(), t, o)};
  for (std::size_t e = 0; e < s.endpoint_count(); ++e) out.endpoints.push_back(at(g.endpoint(e)));
  for (const Site_point& c : cut_crossings(bsp, bsp.preorder())) out.crossings.emplace_back(c, at(g.point(c)));
  return out;
}

Segment_picture draw_segment_bsp(const Segment_scene& s, const Cylindrical_bsp& bsp, const Q& t,
                                 const Segment_svg_options& o) {
  const Geometry g(s, t);
  const Frame f = frame(s, t, o);
  const View_box& box = f.box;
  const Pixels& px = f.px;
  const double bottom = px.top + f.height;
  Segment_picture pic = f.size;

  std::ostringstream svg;
  svg << "<rect class=\"view-box\" x=\"" << num(px.left) << "\" y=\"" << num(px.top) << "\" width=\""
      << num(f.width) << "\" height=\"" << num(f.height) << "\"/>\n";
  // The cell's wall abscissae, and its floor's and roof's heights there.
  const auto wall = [&](const std::optional<Site_point>& p, const Q& none) { return p ? g.point(*p).x : none; };
  const auto floor_at = [&](const Cell& c, const Q& x) { return c.floor ? g.y(*c.floor, x, true) : box.y0; };
  const auto roof_at = [&](const Cell& c, const Q& x) { return c.roof ? g.y(*c.roof, x, false) : box.y1; };
  const std::vector<std::size_t> nodes = bsp.preorder();  // unused slots left out
  std::size_t leaves = 0;
  for (const std::size_t i : nodes) {
    const Bsp_node& n = bsp.nodes[i];
    if (n.kind != Cut_kind::leaf) continue;
    const Q l = wall(n.cell.left, box.x0), r = wall(n.cell.right, box.x1);
    const auto corner = [&](const Q& x, const Q& y) { return num(px.x(x)) + "," + num(px.y(y)); };
    svg << "<polygon class=\"cell c" << leaves++ % 4 << "\" points=\"" << corner(l, floor_at(n.cell, l)) << " "
        << corner(r, floor_at(n.cell, r)) << " " << corner(r, roof_at(n.cell, r)) << " " << corner(l, roof_at(n.cell, l))
        << "\"/>\n";
  }
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    const Pt &a = g.endpoint(2 * i), &b = g.endpoint(2 * i + 1);
    line(svg, "segment", px.x(a.x), px.y(a.y), px.x(b.x), px.y(b.y));
  }
  const Bsp_counts counts = bsp.counts();
  for (const Cut_kind kind : {Cut_kind::vertex, Cut_kind::intersection, Cut_kind::edge})
    for (const std::size_t i : nodes) {
      const Bsp_node& n = bsp.nodes[i];
      if (n.kind != kind) continue;
      if (kind == Cut_kind::edge) {
        const Pt &a = g.endpoint(2 * n.segment), &b = g.endpoint(2 * n.segment + 1);
        if (a.x == b.x) {  // vertical at t: all of it
          line(svg, "edge-cut", px.x(a.x), px.y(a.y), px.x(b.x), px.y(b.y));
          continue;
        }
        const Q l = g.point(*n.cell.left).x, r = g.point(*n.cell.right).x;
        line(svg, "edge-cut", px.x(l), px.y(g.y(n.segment, l, false)), px.x(r), px.y(g.y(n.segment, r, false)));
        continue;
      }
      const Q x = g.point(n.point).x;
      line(svg, kind == Cut_kind::vertex ? "vertex-cut" : "intersection-cut", px.x(x), px.y(floor_at(n.cell, x)),
           px.x(x), px.y(roof_at(n.cell, x)));
    }
  for (std::size_t e = 0; e < s.endpoint_count(); ++e) {
    const Pt& p = g.endpoint(e);
    svg << "<circle class=\"endpoint\" cx=\"" << num(px.x(p.x)) << "\" cy=\"" << num(px.y(p.y)) << "\" r=\"2.5\"/>\n";
  }
  for (const std::size_t i : o.marked) {
    const Pt &a = g.endpoint(2 * i), &b = g.endpoint(2 * i + 1);
    line(svg, "marked", px.x(a.x), px.y(a.y), px.x(b.x), px.y(b.y), " data-segment=\"" + std::to_string(i) + "\"");
  }
  for (const Site_point& c : cut_crossings(bsp, nodes)) {
    const double x = px.x(g.point(c).x), y = px.y(g.point(c).y);
    svg << "<path class=\"crossing\" d=\"M" << num(x - 4) << " " << num(y - 4) << "L" << num(x + 4) << " "
        << num(y + 4) << "M" << num(x - 4) << " " << num(y + 4) << "L" << num(x + 4) << " " << num(y - 4) << "\"/>\n";
  }

  const std::vector<std::string> lines = caption(s, counts, t, o);
  for (std::size_t k = 0; k < lines.size(); ++k)
    if (!lines[k].empty())
      svg << "<text x=\"" << num(pad) << "\" y=\"" << num(pad + 14 + line_height * static_cast<double>(k)) << "\">"
          << escaped(lines[k]) << "</text>\n";
  const std::pair<const char*, std::size_t> legend[] = {{"vertex", counts.vertex_cuts},
                                                        {"intersection", counts.intersection_cuts},
                                                        {"edge", counts.edge_cuts}};
  const double y = bottom + legend_height / 2 + 4;
  double x = pad;
  for (const auto& [kind, count] : legend) {
    const std::string text = std::string(kind) + " cuts: " + std::to_string(count);
    line(svg, std::string("legend ") + kind + "-cut", x, y - 5, x + 28, y - 5);
    svg << "<text x=\"" << num(x + 34) << "\" y=\"" << num(y) << "\">" << text << "</text>\n";
    x += 34 + char_width * static_cast<double>(text.size()) + 24;
  }
  pic.elements = svg.str();
  return pic;
}

std::string segment_svg(const Segment_scene& s, const Cylindrical_bsp& bsp, const Q& t,
                        const Segment_svg_options& o) {
  const Segment_picture pic = draw_segment_bsp(s, bsp, t, o);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << pic.width << "\" height=\"" << pic.height
      << "\" viewBox=\"0 0 " << pic.width << " " << pic.height
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << style_element << pic.elements << "</svg>\n";
  return svg.str();
}

}  // namespace kvd::segments
