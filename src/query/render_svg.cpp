#include <cstdio>
#include <sstream>

#include "kvd/query/render.hpp"

namespace kvd::query {

namespace {
std::string hex(const Rgb& c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}
std::string pair(double x, double y) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f,%.2f", x, y);
  return buf;
}
}  // namespace

std::string to_svg(const std::vector<Painted_polygon>& picture, const Render_options& o) {
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.size << "\" height=\"" << o.size
      << "\" viewBox=\"0 0 " << o.size << " " << o.size << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const auto& poly : picture) {
    svg << "<polygon points=\"";
    for (std::size_t k = 0; k < poly.points.size(); ++k) svg << (k ? " " : "") << pair(poly.points[k][0], poly.points[k][1]);
    svg << "\" fill=\"" << hex(poly.fill) << "\" stroke=\"" << (o.cells ? "none" : "#555555") << "\" stroke-width=\"0.5\"/>\n";
    if (!o.cells) continue;
    for (std::size_t k = 0; k < poly.points.size(); ++k) {
      const auto& a = poly.points[k];
      const auto& b = poly.points[(k + 1) % poly.points.size()];
      char buf[160];
      std::snprintf(buf, sizeof buf, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"", a[0], a[1], b[0], b[1]);
      svg << buf << " stroke=\"" << hex(poly.sides[k]) << "\" stroke-width=\"1.2\"/>\n";
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace kvd::query
