// What a picture of the KVD at an instant needs beyond the tree: the box
// around the scene and the plane of every site the tree cuts with, in
// double. The page clips each cut to its cell and each fragment to its
// node's cell from these (web/viewer.js); exact until rounded for drawing.
#pragma once

#include <array>
#include <map>

#include "recorded_run.hpp"

namespace kvd::view {

using D3 = std::array<double, 3>;

struct Box {
  D3 lo, hi;
};

// The box around the scene's vertices at the instant, 10% larger each way.
Box bounds(const Instant& in);

// Each cut's plane a x + b y + c z + d = 0 as the tree keeps it just after
// the instant (Classifier::plane_after: where the motion plane vanishes, as
// the E-plane of an edge parallel to z does for good, its first order that
// does not), its negative side being the left subtree's (the
// classification's sign for a point of positive W).
std::map<symbolic::Symbolic_plane, std::array<double, 4>> site_planes(const Instant& in);

}  // namespace kvd::view
