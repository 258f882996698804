// Definitions of Scene_geometry's plane and point; see scene_geometry.hpp.
// Compiled once for the rings of every kernel (src/symbolic/scene_geometry.cpp);
// for another ring, include this and kvd/detail/geometry/plucker_impl.hpp.
#pragma once

#include "kvd/symbolic/scene_geometry.hpp"

namespace kvd::symbolic {

template <class R>
Plane4<R> Scene_geometry<R>::plane(const Symbolic_plane& p) const {
  const scene::Scene& s = *scene_;
  switch (p.kind) {
    case Symbolic_plane::Kind::P: return join(join(x_, z_), vertex(p.id));
    case Symbolic_plane::Kind::E: return join(join(vertex(s.edges[p.id][0]), vertex(s.edges[p.id][1])), z_);
    case Symbolic_plane::Kind::T: {
      const auto& t = s.triangles[p.id];
      return join(join(vertex(t[0]), vertex(t[1])), vertex(t[2]));
    }
  }
  return {};
}

template <class R>
Point4<R> Scene_geometry<R>::point(const Symbolic_vertex& v) const {
  using K = Symbolic_vertex::Kind;
  using P = Symbolic_plane::Kind;
  const scene::Scene& s = *scene_;
  const auto& i = v.ids;
  auto edge_line = [&](std::size_t e) { return join(vertex(s.edges[e][0]), vertex(s.edges[e][1])); };
  switch (v.kind) {
    case K::endpoint: return vertex(i[0]);
    case K::intersection: return meet(edge_line(i[0]), plane({P::E, i[1]}));
    case K::thread: return meet(edge_line(i[0]), plane({P::P, i[1]}));
    case K::internal_intersection: return meet(plane({P::E, i[0]}), plane({P::E, i[1]}), plane({P::T, i[2]}));
    case K::internal_thread: return meet(plane({P::P, i[0]}), plane({P::E, i[1]}), plane({P::T, i[2]}));
    case K::axis: return meet(join(x_, z_), plane({P::T, i[0]}));
    case K::plumb: return meet(join(vertex(i[0]), z_), plane({P::T, i[1]}));
  }
  return {};
}

}  // namespace kvd::symbolic
