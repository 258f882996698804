// Exact test of whether two closed triangles meet outside the features they
// share (the scene format's start-time intersection rule).
#pragma once

#include <gmpxx.h>

#include <array>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "kvd/scene/scene.hpp"

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

// The scene's triangles at the instant t, in Euclidean coordinates; every
// vertex's W must be non-zero at t.
std::vector<Triangle3> triangles_at(const Scene& s, const Q& t);

// The first pair (a, b), a < b, of the scene's triangles `tri` (as placed at
// some instant) that meet outside the vertices and edges they share: the
// scene format's intersection rule. None when no two meet.
std::optional<std::pair<std::size_t, std::size_t>> first_conflict(const Scene& s, const std::vector<Triangle3>& tri);

}  // namespace kvd::scene
