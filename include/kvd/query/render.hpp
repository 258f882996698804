// Pictures of the decomposition: the triangle fragments painted back to
// front (the painter's algorithm) in perspective from a viewpoint, as SVG.
#pragma once

#include <string>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::query {

struct Render_options {
  bool cells = false;  // outline fragment sides by the cut that made them: P red, E green, T blue
  int size = 800;      // pixels, square
};

// The scene's fragments seen from `view` (looking at the centroid of the
// vertices, z up), each object in its own colour. Coordinates are exact until
// projection, which is done in double: a picture needs no more.
std::string render_svg(const predicates::Classifier<Exact_kernel>& classifier, const tree::Kvd_tree& tree,
                       const Point4<mpq_class>& view, const mpq_class& t, const Render_options& options);

}  // namespace kvd::query
