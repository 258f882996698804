// Whether a symbolic vertex lying in a triangle's plane lies in the closed
// triangle at an instant: what tells a contact from a vertex that only
// meets the triangle's plane (X-collide, proofs/collision_response.md) and a
// fragment lying in a triangle's plane from one that overlaps it (the
// construction, detail/tree/fragment_split.hpp).
#pragma once

#include <cstddef>

#include "kvd/predicates/classify.hpp"

namespace kvd::predicates {

// For each side of the triangle, the vertex is not strictly on the other
// side from the opposite corner, against the plane through the side and a
// coordinate axis not parallel to the triangle at t. Signs at t only, exact
// in the exact kernel. The vertex must lie in the triangle's plane at t;
// false for a vertex at infinity or a triangle degenerate at t.
template <class K>
bool in_closed_triangle(const Classifier<K>& c, const symbolic::Symbolic_vertex& v, std::size_t triangle,
                        const typename K::Time& t);

// Whether two triangles that lie in one plane at t meet there, boundaries
// included: a corner of either lies in the other's closed triangle, or a
// side of one crosses a side of the other (against the planes through a
// side and a coordinate axis not parallel to the plane of `b` at t). Two
// closed triangles in a plane that meet with no corner of either in the
// other meet where two sides cross at a point inside both, and sides that
// overlap along a line put a corner in the other triangle. Signs at t
// only, exact in the exact kernel. Both must lie in one plane at t (the
// caller checks); false for a triangle degenerate at t.
template <class K>
bool coplanar_triangles_meet(const Classifier<K>& c, std::size_t a, std::size_t b, const typename K::Time& t);

}  // namespace kvd::predicates
