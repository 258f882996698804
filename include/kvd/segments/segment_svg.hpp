// Pictures of the cylindrical BSP of segments (kvd/segments/cylindrical_bsp.hpp)
// at a rational instant, as SVG.
//
// Every position is exact until it is drawn: endpoints at t, crossings as the
// meet of two lines, the ends of each cut where it meets its cell's floor or
// roof; only pixel coordinates are doubles, written with 6 significant digits,
// so the same input gives the same bytes. Each cut is clipped to its node's
// cell: a point cut is the vertical segment through its point from the floor
// to the roof, an edge cut the part of its segment from the left wall to the
// right one; a side the cell does not have is the view box's. Leaves' cells
// are filled in pale colours. Elements carry a class naming what they draw:
// "cell", "segment", "vertex-cut", "intersection-cut", "edge-cut",
// "endpoint", "crossing", and "view-box" for the frame of the drawn region.
// The y axis points up.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

// The rectangle [x0, x1] x [y0, y1] of the plane.
struct View_box {
  Q x0, y0, x1, y1;
};

// The bounding box of the endpoints at t, grown on every side by a tenth of
// its larger side (by 1 when the endpoints are one point).
View_box view_box(const Segment_scene& s, const Q& t);
// The smallest box holding a and b.
View_box hull(const View_box& a, const View_box& b);

struct Segment_svg_options {
  int size = 800;                  // the picture's width in pixels
  std::optional<View_box> box;     // the region drawn; view_box(scene, t) by default
  std::vector<std::string> notes;  // caption lines after the scene's name and the counts; "" keeps a line free
  // Segments drawn once more on top, with the class "marked" (which
  // segment_svg_style() leaves to the document to style) and their number
  // as data-segment.
  std::vector<std::size_t> marked;
};

// The elements of a picture, without the <svg> element around them, and the
// size in pixels they fill (the same for every instant of one box, size and
// number of notes).
struct Segment_picture {
  int width = 0, height = 0;
  std::string elements;
};

// The picture of `bsp`, the cylindrical BSP of `s` just after t, with a
// caption (the scene's name, t, the number of nodes, the height, then
// `notes`) and a legend counting the cuts of each kind.
Segment_picture draw_segment_bsp(const Segment_scene& s, const Cylindrical_bsp& bsp, const Q& t,
                                 const Segment_svg_options& options = {});
// Where the parts of that picture go, in pixels, for a page that draws it
// itself from the tree's text (web/segments.js, which follows
// draw_segment_bsp): the picture's size, the view box's frame, every
// endpoint, every crossing the tree cuts through (in the preorder of its
// first intersection cut), and the caption's lines. Each number is rounded
// to a millionth of a pixel.
struct Segment_layout {
  int width = 0, height = 0;
  double left = 0, top = 0, box_width = 0, box_height = 0;  // the view box's frame
  std::vector<std::array<double, 2>> endpoints;               // endpoint e at e
  std::vector<std::pair<Site_point, std::array<double, 2>>> crossings;
  std::vector<std::string> caption;
};
Segment_layout segment_layout(const Segment_scene& s, const Cylindrical_bsp& bsp, const Q& t,
                              const Segment_svg_options& options = {});
// The <style> element that gives the classes their look, once per document.
std::string segment_svg_style();
// The same picture as an SVG document on a white background.
std::string segment_svg(const Segment_scene& s, const Cylindrical_bsp& bsp, const Q& t,
                        const Segment_svg_options& options = {});

}  // namespace kvd::segments
