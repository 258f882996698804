// Incidence by construction (thesis 5.3.1): whether a symbolic vertex lies on
// a symbolic plane because of how both are defined, decided from the scene's
// incidence alone, with no arithmetic.
#pragma once

#include "kvd/scene/scene.hpp"
#include "kvd/symbolic/symbolic.hpp"

namespace kvd::symbolic {

// The canonical name of a vertex: an internal vertex built on an E-plane of
// one of its own triangle's edges lies on that edge, so SV(V, E, T) with E an
// edge of T is the thread vertex (E, V), and SV(E1, E2, T) with E1 an edge of
// T is the intersection vertex (E1, E2). Other vertices are returned as they
// are. Symbolic identity is identity of canonical names.
Symbolic_vertex canonical(const scene::Scene& s, const Symbolic_vertex& v);

// True when v lies on p for every motion of the scene (v is canonicalised
// first):
//  * a P-plane SP(V) holds the endpoint V, every vertex built on SP(V)
//    (thread (e, V), internal thread (V, E, T)), and, when z is Euclidean,
//    every axis vertex (all P-planes contain the line x ∨ z);
//  * an E-plane SP(E) holds E's endpoints, every point of edge E (thread and
//    intersection vertices on E), and every vertex built on SP(E);
//  * a triangle's plane SP(T) holds T's vertices, every point on T's edges,
//    and every vertex built on SP(T);
//  * a vertex on the line w ∨ z by construction (an internal thread (w, E, T)
//    with w an endpoint of E, or an internal intersection of the E-planes of
//    two edges meeting at w) lies on P(w) and on the E-plane of every edge
//    at w, all of which contain that line.
// `z_euclidean` says whether the decomposition point z is Euclidean.
bool on_by_construction(const scene::Scene& s, const Symbolic_vertex& v, const Symbolic_plane& p, bool z_euclidean);

// The object of the feature a plane is built on: its vertex (P), edge (E) or
// triangle (T).
std::size_t object_of(const scene::Scene& s, const Symbolic_plane& p);

// Calls f with each scene vertex of the feature a plane is built on: its
// vertex (P), an edge's two (E), a triangle's three (T).
template <class F>
void for_each_vertex(const scene::Scene& s, const Symbolic_plane& p, F&& f) {
  switch (p.kind) {
    case Symbolic_plane::Kind::P: f(p.id); break;
    case Symbolic_plane::Kind::E: f(s.edges[p.id][0]), f(s.edges[p.id][1]); break;
    case Symbolic_plane::Kind::T:
      for (std::size_t v : s.triangles[p.id]) f(v);
      break;
  }
}

}  // namespace kvd::symbolic
