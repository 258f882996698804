#include "kvd/symbolic/incidence.hpp"

#include <algorithm>
#include <optional>

namespace kvd::symbolic {

namespace {

using K = Symbolic_vertex::Kind;

// The scene edge a vertex lies on by construction, if any.
bool on_edge(const scene::Scene& s, const Symbolic_vertex& v, std::size_t e) {
  switch (v.kind) {
    case K::endpoint: return s.edges[e][0] == v.ids[0] || s.edges[e][1] == v.ids[0];
    case K::intersection:
    case K::thread: return v.ids[0] == e;
    default: return false;
  }
}

bool edge_of_triangle(const scene::Scene& s, std::size_t e, std::size_t t) {
  const auto& te = s.triangle_edges[t];
  return std::find(te.begin(), te.end(), e) != te.end();
}

// The scene vertex w such that v, an internal vertex, is built from two planes
// containing the line w ∨ z: an internal thread (w, E, T) with w an endpoint
// of E, or an internal intersection of the E-planes of two edges at w.
std::optional<std::size_t> on_line_to_z(const scene::Scene& s, const Symbolic_vertex& v) {
  const auto& i = v.ids;
  if (v.kind == K::internal_thread && (s.edges[i[1]][0] == i[0] || s.edges[i[1]][1] == i[0])) return i[0];
  if (v.kind == K::internal_intersection)
    for (std::size_t a : s.edges[i[0]])
      for (std::size_t b : s.edges[i[1]])
        if (a == b) return a;
  return std::nullopt;
}

}  // namespace

Symbolic_vertex canonical(const scene::Scene& s, const Symbolic_vertex& v) {
  if (v.kind == K::internal_thread && edge_of_triangle(s, v.ids[1], v.ids[2]))
    return Symbolic_vertex::thread(v.ids[1], v.ids[0]);
  if (v.kind == K::internal_intersection) {
    if (edge_of_triangle(s, v.ids[0], v.ids[2])) return Symbolic_vertex::intersection(v.ids[0], v.ids[1]);
    if (edge_of_triangle(s, v.ids[1], v.ids[2])) return Symbolic_vertex::intersection(v.ids[1], v.ids[0]);
  }
  if (const auto w = on_line_to_z(s, v)) return Symbolic_vertex::plumb(*w, v.ids[2]);
  return v;
}

bool on_by_construction(const scene::Scene& s, const Symbolic_vertex& given, const Symbolic_plane& p, bool z_euclidean) {
  const Symbolic_vertex v = canonical(s, given);
  if (v.kind == K::plumb) {
    // On the line w ∨ z, which lies in P(w) and in the E-plane of every edge at w.
    const std::size_t w = v.ids[0];
    if (p.kind == Symbolic_plane::Kind::P && p.id == w) return true;
    if (p.kind == Symbolic_plane::Kind::E && (s.edges[p.id][0] == w || s.edges[p.id][1] == w)) return true;
  }
  switch (p.kind) {
    case Symbolic_plane::Kind::P:
      switch (v.kind) {
        case K::endpoint: return v.ids[0] == p.id;
        case K::thread: return v.ids[1] == p.id;
        case K::internal_thread: return v.ids[0] == p.id;
        case K::axis: return z_euclidean;
        default: return false;
      }
    case Symbolic_plane::Kind::E:
      if (on_edge(s, v, p.id)) return true;
      switch (v.kind) {
        case K::intersection: return v.ids[1] == p.id;
        case K::internal_intersection: return v.ids[0] == p.id || v.ids[1] == p.id;
        case K::internal_thread: return v.ids[1] == p.id;
        default: return false;
      }
    case Symbolic_plane::Kind::T:
      switch (v.kind) {
        case K::endpoint: {
          const auto& tv = s.triangles[p.id];
          return std::find(tv.begin(), tv.end(), v.ids[0]) != tv.end();
        }
        case K::intersection:
        case K::thread: return edge_of_triangle(s, v.ids[0], p.id);
        case K::internal_intersection:
        case K::internal_thread: return v.ids[2] == p.id;
        case K::axis: return v.ids[0] == p.id;
        case K::plumb: return v.ids[1] == p.id;
      }
  }
  return false;
}

std::size_t object_of(const scene::Scene& s, const Symbolic_plane& p) {
  switch (p.kind) {
    case Symbolic_plane::Kind::T: return s.triangle_object[p.id];
    case Symbolic_plane::Kind::E: return s.edge_object[p.id];
    case Symbolic_plane::Kind::P: break;
  }
  return s.vertex_object[p.id];
}

}  // namespace kvd::symbolic
