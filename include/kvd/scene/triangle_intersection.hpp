// Exact test of whether two closed triangles meet outside the features they
// share (the scene format's start-time intersection rule).
#pragma once

#include <gmpxx.h>

#include <array>
#include <functional>
#include <vector>

namespace kvd::scene {

using Vec3 = std::array<mpq_class, 3>;
using Triangle3 = std::array<Vec3, 3>;

// True when the closed triangles a and b (non-degenerate) have a common point
// that is not in the convex hull of `shared` (the positions of the vertices
// the two triangles share: none, one vertex, or the two ends of a shared
// edge). Three shared vertices (a repeated triangle) always conflict.
//
// A ∩ B is convex, and so is the allowed set, so A ∩ B lies in it exactly when
// the extreme points of A ∩ B do. These are computed exactly: if the planes
// differ, from the segment where B meets A's plane, clipped by A; if the
// triangles are coplanar, by clipping A by B. Both clip in the coordinate
// plane that A projects onto without degenerating.
bool triangles_conflict(const Triangle3& a, const Triangle3& b, const std::vector<Vec3>& shared);

// Visits every pair (i, j), i < j, of triangles whose closed bounding boxes
// meet, by sorting the boxes along the axis on which they overlap least and
// sweeping; stops when `visit` returns true. Pairs that cannot touch are
// never visited, so a scene of spread-out triangles costs O(n log n) plus the
// number of close pairs instead of n^2.
void for_each_close_pair(const std::vector<Triangle3>& triangles,
                         const std::function<bool(std::size_t, std::size_t)>& visit);

}  // namespace kvd::scene
