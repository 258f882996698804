// Pictures of the decomposition: the triangle fragments painted back to
// front (the painter's algorithm) in perspective from a viewpoint, written
// as SVG or PNG.
#pragma once

#include <array>
#include <optional>
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

// A perspective camera at `eye` looking at `target`, z up. Unframed, it
// maps a point to the image plane (right, down over depth); framed, to
// image coordinates ([0, size]^2 holding the framed bounds with a 5% margin).
struct Camera {
  using D3 = std::array<double, 3>;
  using D2 = std::array<double, 2>;
  D3 eye{}, forward{}, right{}, up{};
  int size = 800;
  bool framed = false;
  double cx = 0, cy = 0, span = 1;
  Camera() = default;
  Camera(const D3& eye, const D3& target, int size);
  // The point's place, none when it is not in front of the eye.
  std::optional<D2> project(const D3& p) const;
  // Frames the image-plane bounds [lo, hi] (points projected unframed).
  void frame(const D2& lo, const D2& hi);
  // An unframed projection in image coordinates of the framed camera.
  D2 to_image(const D2& q) const;
};

// The centroid of the scene's vertices at t, in double: where a picture looks.
Camera::D3 centroid(const scene::Scene& s, const mpq_class& t);

// The fragments of `tree` at t seen by the camera, back to front from
// `view` (the camera's eye, exactly); fragments
// with a vertex behind the eye are left out. Coordinates are exact until
// projection, which is done in double: a picture needs no more.
std::vector<Painted_polygon> paint(const predicates::Classifier<Exact_kernel>& classifier, const tree::Kvd_tree& tree,
                                   const Point4<mpq_class>& view, const Camera& camera, const mpq_class& t,
                                   const Render_options& options);

// The fragments seen from `view`, looking at the centroid of the vertices,
// framed to hold them all.
std::vector<Painted_polygon> paint(const predicates::Classifier<Exact_kernel>& classifier, const tree::Kvd_tree& tree,
                                   const Point4<mpq_class>& view, const mpq_class& t, const Render_options& options);

// Marks over a picture, in image coordinates: red dots, red polylines
// (closed from three points on) and lines of text at the top left.
struct Overlay {
  std::vector<std::array<double, 2>> points;
  std::vector<std::vector<std::array<double, 2>>> outlines;
  std::vector<std::string> caption;
};

std::string to_svg(const std::vector<Painted_polygon>& picture, const Render_options& options,
                   const Overlay& overlay = {});
// The picture's SVG elements alone, for a document of several pictures.
std::string svg_elements(const std::vector<Painted_polygon>& picture, const Render_options& options,
                         const Overlay& overlay = {});
// The PNG file's bytes (drawn with cairo).
std::string to_png(const std::vector<Painted_polygon>& picture, const Render_options& options,
                   const Overlay& overlay = {});
// Whether this build writes PNG (cairo is optional; SVG is always there).
bool png_supported();

}  // namespace kvd::query
