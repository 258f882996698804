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

std::string svg_elements(const std::vector<Painted_polygon>& picture, const Render_options& o, const Overlay& overlay) {
  std::ostringstream svg;
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
  for (const auto& line : overlay.outlines) {
    svg << (line.size() >= 3 ? "<polygon" : "<polyline") << " points=\"";
    for (std::size_t k = 0; k < line.size(); ++k) svg << (k ? " " : "") << pair(line[k][0], line[k][1]);
    svg << "\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2.5\"/>\n";
  }
  for (const auto& p : overlay.points) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"4\" fill=\"#d62728\"/>\n", p[0], p[1]);
    svg << buf;
  }
  for (std::size_t k = 0; k < overlay.caption.size(); ++k) {
    std::string text;
    for (char ch : overlay.caption[k]) text += ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : ch == '&' ? "&amp;" : std::string(1, ch);
    svg << "<text x=\"8\" y=\"" << 18 + 18 * k << "\" font-family=\"monospace\" font-size=\"14\">" << text << "</text>\n";
  }
  return svg.str();
}

std::string to_svg(const std::vector<Painted_polygon>& picture, const Render_options& o, const Overlay& overlay) {
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.size << "\" height=\"" << o.size
      << "\" viewBox=\"0 0 " << o.size << " " << o.size << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << svg_elements(picture, o, overlay) << "</svg>\n";
  return svg.str();
}

}  // namespace kvd::query
