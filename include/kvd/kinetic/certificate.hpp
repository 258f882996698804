// Certificates (thesis 6.3-6.4): named polynomial signs that hold while the
// tree stays what it is. A certificate fails at the earliest sign-changing
// root, after the current time, of any of its polynomials.
//
// Two sets are computed from the tree in force:
//  * full: every sign the construction evaluated (DESIGN.md section 5);
//    complete by construction, since the construction branches on nothing
//    else;
//  * reduced: the thesis's set (thesis 6.4), per node, against the walls of
//    its cell: VV, VE, VT for a P-node's vertex, IV and II for the
//    intersection points held by E-node fragments, ET and VE for an E-node's
//    intersection and thread endpoints, TT (a VT certificate) for the
//    P-cuts crossing a T-node's fragment; and IV or II between each nearest
//    P-wall and the intersection cuts farther on its side, which keeps the
//    choice of wall right while a node keeps its certificates
//    (detail/kinetic/reduced_upkeep.hpp). Polynomials and their derivation:
//    proofs/certificates.md.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "kvd/predicates/classify.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::kinetic {

// `other` only occurs in the full set: signs of fragment corners (threads,
// internal vertices) that the thesis's set does not name.
enum class Certificate_type { VV, VE, VT, ET, IV, II, TT, other };
inline constexpr std::size_t certificate_types = 8;
const char* to_string(Certificate_type t);
// Vertex-triangle, edge-edge and triangle-vertex failures are collisions
// when the features touch (thesis 6.2.3).
bool may_collide(Certificate_type t);

// A certificate's identity: its type and the features it names, a vertex
// against a plane (VV, VE, VT, IV, TT, other), an intersection point
// against the P-cut through another (II, thesis 6.3.7), or two edges whose
// lines meet (the reduced set's ET: the point where the first meets the
// second's E-plane, against that plane; the full set's ET is a point
// against a triangle's plane). Ordered and hashable; text only for printing.
struct Certificate_key {
  Certificate_type type;
  symbolic::Symbolic_vertex vertex;
  std::variant<symbolic::Symbolic_plane, symbolic::Symbolic_vertex> against;
  auto operator<=>(const Certificate_key&) const = default;
};
// The features in words, as traces print them: "SV(v3) P(7)",
// "SV-int(e1,E4) P(SV-int(e2,E5))", "E(1) E(4)".
std::string features(const Certificate_key& k);
// Printing order: by type, then by the features' text (traces and
// certificate files list certificates in this order).
bool printed_before(const Certificate_key& a, const Certificate_key& b);
// Whether the certificate's polynomials depend on the motion of `object`:
// whether a feature it names (a vertex, edge or triangle of a symbolic
// vertex or plane) belongs to it.
bool names_object(const scene::Scene& s, const Certificate_key& k, std::size_t object);
struct Certificate_key_hash {
  std::size_t operator()(const Certificate_key& k) const noexcept;
};

template <class Poly>
struct Certificate {
  Certificate_key key;
  int node;                 // the tree node holding it (the kinetic priority queue's slot)
  std::vector<Poly> polys;  // non-constant, each positive just after the time it was made
  // The features it names: when it fails, the sites holding them move
  // (detail/kinetic/local_update.hpp).
  std::vector<symbolic::Symbolic_vertex> vertices;
  std::vector<symbolic::Symbolic_plane> planes;
};

enum class Certificate_set { reduced, full };

// The full set: one certificate per distinct classification in `evaluated`
// that is not an incidence by construction, held by the first node of t
// (pre-order) whose cut is the classification's plane.
template <class K>
std::vector<Certificate<typename K::Poly>> full_certificates(const predicates::Classifier<K>& c,
                                                             const tree::Kvd_tree& t, tree::Evaluated evaluated,
                                                             const typename K::Time& now);

// The reduced set of the tree in force just after `now`, every node making
// its certificates (Reduced_upkeep keeps them over a run).
template <class K>
std::vector<Certificate<typename K::Poly>> reduced_certificates(const predicates::Classifier<K>& c,
                                                                const tree::Kvd_tree& t,
                                                                const typename K::Time& now);

}  // namespace kvd::kinetic
