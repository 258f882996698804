// Triangle meshes from OBJ, OFF and ASCII PLY files, read exactly: every coordinate is
// the rational its decimal text spells (the scene format's number grammar,
// with a leading '+' also allowed), never rounded through double. Polygons
// are split into fans from their first corner; a fan that folds over itself
// is caught later, when the scene's triangles are checked for intersections.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "kvd/scene/scene.hpp"

namespace kvd::scene {

struct Mesh_object {
  std::string name;
  std::vector<QPoint> vertices;  // only those the triangles use, in first use
  std::vector<std::array<std::size_t, 3>> triangles;
};

// Reads `text` as OBJ (objects from `o` and `g` lines), OFF or ASCII PLY
// (one object each), chosen by `source`'s extension (.obj, .off, .ply). Scene_error "SOURCE: line N:
// what" for anything malformed: an unknown statement, a bad number or
// index, a face of fewer than three corners, a repeated corner.
std::vector<Mesh_object> read_mesh(const std::string& text, const std::string& source);

// The objects as a scene: static, or with the motions set afterwards.
Scene mesh_scene(const std::vector<Mesh_object>& objects, const std::string& name);

// The rational rotation of `o`'s vertices about the axis u through their
// centroid: by angle 2 atan(t |u|), the matrix motion of degree 2 with
// W = 1 + t^2 |u|^2 (the quaternion (1, t u)).
Motion rotation_about_centroid(const Scene& s, std::size_t object, const std::array<Q, 3>& u);

}  // namespace kvd::scene
