// The collision response X-collide (thesis 7.3.3): when a batch's failures
// include a contact, or its update finds two triangles crossing, the motions
// of both objects are reversed at a rational time r strictly between the
// last batch and the collision, close to the collision
// (proofs/collision_response.md). Positions are continuous at r and every
// velocity of the two objects changes sign there; a rational r keeps the
// reversed motions exact polynomials.
#pragma once

#include <gmpxx.h>

#include <vector>

#include "kvd/kernel/exact_time.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/scene/scene.hpp"
#include "kvd/tree/build.hpp"

namespace kvd::kinetic {

// The rational of smallest denominator (then smallest magnitude) in the
// closed interval [lo, hi], lo <= hi: continued fractions keep the reversal
// time, and so the reversed motions' coefficients, short.
mpq_class simplest_rational(const mpq_class& lo, const mpq_class& hi);

// The reversal time for a collision at c after the last batch at a < c: with
// a and c refined until c's isolating interval is narrower than 1/64 of the
// gap g between a's upper and c's lower end, the simplest rational in
// [lo(c) - g/16, lo(c) - g/64]. So a < r < c and c - r < g/8.
mpq_class reversal_time(const Exact_time& a, const Exact_time& c);

// What a VT, ET or TT certificate says may touch (thesis 6.2): a vertex and
// a triangle. For VT and TT, the vertex and the triangle of the plane named;
// for the reduced set's ET, E(I) E(J), the intersection point of edge I with
// E(J) and a triangle of edge J (when the lines meet, the point is on line J,
// and a triangle of J meets its line in exactly the segment J).
struct Touch {
  symbolic::Symbolic_vertex vertex;
  std::size_t triangle;
};
Touch touch(const scene::Scene& s, const std::vector<symbolic::Symbolic_vertex>& vertices,
            const std::vector<symbolic::Symbolic_plane>& planes);

// The object of the feature a vertex lies on: its own, the edge it is on, or
// the triangle whose plane defines it.
std::size_t object_of(const scene::Scene& s, const symbolic::Symbolic_vertex& v);

// The objects that meet, increasing (one when an object meets itself).
std::vector<std::size_t> contact_objects(const scene::Scene& s, const Touch& touch);
// Those of a crossing found by a build.
std::vector<std::size_t> contact_objects(const scene::Scene& s, const tree::Contact& c);

}  // namespace kvd::kinetic
