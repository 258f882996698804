// PNG pictures through cairo, when the build found it (KVD_HAVE_CAIRO).
#include <stdexcept>

#include "kvd/query/render.hpp"

#ifdef KVD_HAVE_CAIRO
#include <cairo.h>
#endif

namespace kvd::query {

#ifdef KVD_HAVE_CAIRO
bool png_supported() { return true; }

namespace {

void set(cairo_t* cr, const Rgb& c) { cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0); }

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::string to_png(const std::vector<Painted_polygon>& picture, const Render_options& o, const Overlay& overlay) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, o.size, o.size);
  cairo_t* cr = cairo_create(surface);
  set(cr, {255, 255, 255});
  cairo_paint(cr);
  for (const auto& poly : picture) {
    cairo_new_path(cr);
    for (const auto& q : poly.points) cairo_line_to(cr, q[0], q[1]);
    cairo_close_path(cr);
    set(cr, poly.fill);
    cairo_fill_preserve(cr);
    set(cr, {0x55, 0x55, 0x55});
    cairo_set_line_width(cr, 0.5);
    if (o.cells) cairo_new_path(cr);
    else cairo_stroke(cr);
    if (!o.cells) continue;
    cairo_set_line_width(cr, 1.2);
    for (std::size_t k = 0; k < poly.points.size(); ++k) {
      const auto& a = poly.points[k];
      const auto& b = poly.points[(k + 1) % poly.points.size()];
      cairo_move_to(cr, a[0], a[1]);
      cairo_line_to(cr, b[0], b[1]);
      set(cr, poly.sides[k]);
      cairo_stroke(cr);
    }
  }
  set(cr, {0xd6, 0x27, 0x28});
  cairo_set_line_width(cr, 2.5);
  for (const auto& line : overlay.outlines) {
    cairo_new_path(cr);
    for (const auto& q : line) cairo_line_to(cr, q[0], q[1]);
    if (line.size() >= 3) cairo_close_path(cr);
    cairo_stroke(cr);
  }
  for (const auto& p : overlay.points) {
    cairo_new_path(cr);
    cairo_arc(cr, p[0], p[1], 4, 0, 6.283185307179586);
    cairo_fill(cr);
  }
  set(cr, {0, 0, 0});
  cairo_select_font_face(cr, "monospace", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 14);
  for (std::size_t k = 0; k < overlay.caption.size(); ++k) {
    cairo_move_to(cr, 8, 18 + 18 * static_cast<double>(k));
    cairo_show_text(cr, overlay.caption[k].c_str());
  }
  std::string bytes;
  const cairo_status_t status = cairo_surface_write_to_png_stream(surface, append, &bytes);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error(cairo_status_to_string(status));
  return bytes;
}
#else
bool png_supported() { return false; }

std::string to_png(const std::vector<Painted_polygon>&, const Render_options&, const Overlay&) {
  throw std::logic_error("this build of kvd has no PNG output (cairo was not found)");
}
#endif

}  // namespace kvd::query
