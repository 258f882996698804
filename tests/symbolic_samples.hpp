// Symbolic vertices and planes of a scene for the symbolic-layer tests: all
// endpoints, and well-formed derived vertices (no vertex built from a plane
// through one of its own defining features), capped in number.
#pragma once

#include <algorithm>
#include <vector>

#include "kvd/scene/scene.hpp"
#include "kvd/symbolic/symbolic.hpp"

namespace kvd::test {

inline bool shares_vertex(const scene::Scene& s, std::size_t e, std::size_t f) {
  const auto& a = s.edges[e];
  const auto& b = s.edges[f];
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

inline bool endpoint_of(const scene::Scene& s, std::size_t v, std::size_t e) {
  return s.edges[e][0] == v || s.edges[e][1] == v;
}

inline std::vector<symbolic::Symbolic_vertex> sample_vertices(const scene::Scene& s, bool with_axis, std::size_t cap = 4) {
  using SV = symbolic::Symbolic_vertex;
  std::vector<SV> out;
  const std::size_t nv = s.rest.size(), ne = s.edges.size(), nt = s.triangles.size();
  for (std::size_t v = 0; v < nv; ++v) out.push_back(SV::endpoint(v));
  for (std::size_t e = 0; e < ne; e += 1 + ne / cap)
    for (std::size_t v = 0; v < nv; v += 1 + nv / cap)
      if (!endpoint_of(s, v, e)) out.push_back(SV::thread(e, v));
  for (std::size_t e = 0; e < ne; e += 1 + ne / cap)
    for (std::size_t f = 0; f < ne; f += 1 + ne / cap)
      if (!shares_vertex(s, e, f)) out.push_back(SV::intersection(e, f));
  for (std::size_t t = 0; t < nt; t += 1 + nt / cap) {
    const auto& te = s.triangle_edges[t];
    for (std::size_t e = 0; e < ne; e += 1 + ne / cap)
      if (!shares_vertex(s, te[0], e)) out.push_back(SV::internal_intersection(te[0], e, t));
    for (std::size_t v = 0; v < nv; v += 1 + nv / cap)
      if (!endpoint_of(s, v, te[1])) out.push_back(SV::internal_thread(v, te[1], t));
    // Vertices on the line w ∨ z, for a vertex w off the triangle: an internal
    // thread whose P-vertex is an endpoint of its edge, and the E-planes of
    // two edges meeting at w.
    const auto& tv = s.triangles[t];
    for (std::size_t w = 0; w < nv; w += 1 + nv / cap) {
      if (std::find(tv.begin(), tv.end(), w) != tv.end()) continue;
      const auto& at_w = s.vertex_edges[w];
      if (!at_w.empty()) out.push_back(SV::internal_thread(w, at_w[0], t));
      if (at_w.size() >= 2) out.push_back(SV::internal_intersection(at_w[0], at_w[1], t));
    }
    if (with_axis) out.push_back(SV::axis(t));
  }
  return out;
}

inline std::vector<symbolic::Symbolic_plane> all_planes(const scene::Scene& s) {
  using SP = symbolic::Symbolic_plane;
  std::vector<SP> out;
  for (std::size_t v = 0; v < s.rest.size(); ++v) out.push_back({SP::Kind::P, v});
  for (std::size_t e = 0; e < s.edges.size(); ++e) out.push_back({SP::Kind::E, e});
  for (std::size_t t = 0; t < s.triangles.size(); ++t) out.push_back({SP::Kind::T, t});
  return out;
}

}  // namespace kvd::test
