// Pictures of the decomposition: the triangle fragments painted back to
// front (the painter's algorithm) in perspective from a viewpoint, written
// as SVG or PNG.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::query {

struct Render_options {
  bool cells = false;  // outline fragment sides by the cut that made them: P red, E green, T blue
  int size = 800;      // pixels, square
};

struct Rgb {
  int r, g, b;
};

// One fragment in image coordinates ([0, size]^2, y down), with the colour
// of its object and of each side (side i runs from point i to point i+1).
struct Painted_polygon {
  std::vector<std::array<double, 2>> points;
  std::vector<Rgb> sides;
  Rgb fill;
};

// The fragments seen from `view` (looking at the centroid of the vertices, z
// up), back to front; fragments with a vertex behind the eye are left out.
// Coordinates are exact until projection, which is done in double: a
// picture needs no more.
std::vector<Painted_polygon> paint(const predicates::Classifier<Exact_kernel>& classifier, const tree::Kvd_tree& tree,
                                   const Point4<mpq_class>& view, const mpq_class& t, const Render_options& options);

std::string to_svg(const std::vector<Painted_polygon>& picture, const Render_options& options);
// The PNG file's bytes (drawn with cairo).
std::string to_png(const std::vector<Painted_polygon>& picture, const Render_options& options);
// Whether this build writes PNG (cairo is optional; SVG is always there).
bool png_supported();

}  // namespace kvd::query
