// The baseline: the static randomized auto-partition BSP of the BSP lecture
// notes (seeds/004), with free splits. Built at one instant on explicit exact
// polygons, it is the "BSP construction" that the thesis's Figure 8.8
// compares the KVD with.
//
// Triangles are taken in a random order (the scene's priority order). At each
// node the splitter is a free split if there is one — a fragment all of
// whose edges were made by earlier cuts, so that it spans its cell and cuts
// nothing — and otherwise the first fragment in priority order. Fragments
// lying in the splitter's plane are stored at the node; the others go to the
// side they lie on, or are split.
#pragma once

#include <gmpxx.h>

#include <array>
#include <vector>

#include "kvd/scene/scene.hpp"

namespace kvd::bsp {

using V3 = std::array<mpq_class, 3>;

struct Polygon {
  std::size_t triangle;
  std::vector<V3> points;    // convex, in the triangle's orientation
  std::vector<bool> marked;  // marked[i]: edge points[i] -> points[i+1] was made by a cut
};

struct Node {
  std::array<mpq_class, 4> plane;  // a x + b y + c z + d = 0, positive side right
  std::vector<Polygon> polygons;   // the fragments lying in the plane
  int left = -1, right = -1;
};

struct Tree {
  std::vector<Node> nodes;
  int root = -1;
  std::size_t fragments() const;
  std::size_t height() const;
};

// The BSP of the scene's triangles at the instant t.
Tree autopartition(const scene::Scene& s, const mpq_class& t);

// The fragments back to front as seen from `view`.
std::vector<const Polygon*> back_to_front(const Tree& tree, const V3& view);

}  // namespace kvd::bsp
