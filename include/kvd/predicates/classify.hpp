// The single classification entry point (DESIGN.md section 4): the side of a
// symbolic vertex with respect to a symbolic plane on (t, t + δ).
//
// Decided lexicographically, in the same code for every kernel:
//  1. incidence by construction: ON (0), without arithmetic;
//  2. the sign at t of f = dot(plane, point), times the sign of the point's W
//     (scene vertices have W > 0; derived vertices may not);
//  3. if that is zero, the sign just after t (kernel sign_after);
//  4. if f is identically zero in t, the symbolic perturbation: vertex i moved
//     by ε g_i (moment curve), ε → 0+ after time; the sign is that of the
//     first coefficient of f in ε that is not identically zero in t, decided
//     by rules 2–3. Rule 4 answers "unresolved" (0, counted in
//     `unresolved()`) only if every coefficient vanishes; see
//     proofs/classification.md for when that can happen.
#pragma once

#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "kvd/detail/flat_map.hpp"
#include "kvd/scene/scene.hpp"
#include "kvd/symbolic/incidence.hpp"
#include "kvd/symbolic/scene_geometry.hpp"
#include "kvd/symbolic/symbolic.hpp"

namespace kvd::predicates {

class Classification_filter;  // the exact kernel's interval filter (src/predicates/classify_filter.hpp)

enum class Rule { incidence, value, after, perturbation, unresolved };

struct Classification {
  int side;   // -1, 0 (on), +1
  Rule rule;  // the rule that decided
};

template <class K>
class Classifier {
public:
  Classifier(const K& k, const scene::Scene& s);

  Classification classify(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p,
                          const typename K::Time& t) const;
  int side(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p, const typename K::Time& t) const {
    return classify(v, p, t).side;
  }

  const K& kernel() const { return *k_; }
  // The polynomials in t whose sign changes are the only times classify(v, p)
  // can change: the value (or, under rule 4, the first ε-coefficient that is
  // not identically zero) and the W of a derived vertex; constants left out.
  // Empty for an incidence by construction. Computed once per pair: a
  // simulation asks again at every batch.
  const std::vector<typename K::Poly>& certificate(const symbolic::Symbolic_vertex& v,
                                                   const symbolic::Symbolic_plane& p) const;
  // The polynomial whose sign, times that of the vertex's W, is the side:
  // the value, or under rule 4 the first ε-coefficient that is not
  // identically zero; zero for an incidence by construction.
  const typename K::Poly& value(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p) const {
    return deciding(symbolic::canonical(motion_.scene(), v), p).value;
  }
  const symbolic::Scene_geometry<typename K::Poly>& motion() const { return motion_; }
  // The motion polynomials of each plane and vertex, computed once: a build
  // classifies the same features against each other many times.
  const Plane4<typename K::Poly>& plane_poly(const symbolic::Symbolic_plane& p) const;
  const Point4<typename K::Poly>& point_poly(const symbolic::Symbolic_vertex& v) const;
  // coplanar (thesis equation 6.3) of the endpoints of scene edges e1 and
  // e2, in that order: zero when their lines meet. Computed once per pair,
  // like the motion polynomials (the reduced set's ET certificates).
  const typename K::Poly& edge_lines(std::size_t e1, std::size_t e2) const;
  // The sign of f at t, or just after t where f(t) = 0 (zero only for f = 0).
  int lex_sign(const typename K::Poly& f, const typename K::Time& t) const;
  // Whether the coefficients of t^from, t^(from+1), ... of f are all zero by
  // the kernel's test: "identically zero" (from = 0) or "constant" (from = 1)
  // exactly in the exact kernel, within epsilon in the others (so a
  // configuration degenerate in the scene's rationals, such as a vertical
  // triangle, goes to the perturbation there too, not to rounding noise).
  bool vanishes(const typename K::Poly& f, int from = 0) const;
  // The position of v in the perturbed scene as ε -> 0+: its motion point,
  // or, where that vanishes identically (v built from planes that coincide
  // in the unperturbed scene, such as P(v) and E(e) of an edge parallel to
  // x), the first non-zero order of its ε-expansion.
  // Computed once per vertex, like the motion polynomials.
  const Point4<typename K::Poly>& position(const symbolic::Symbolic_vertex& v) const;
  // Where v is at the instant t for the tree built at t, which holds on
  // (t, t + δ): position(v) at t, or, where all four coordinates vanish at t
  // (v made by planes that coincide at t only: the P-plane of a vertex
  // crossing the line x ∨ z, or every P-plane when x meets z or x vanishes
  // at t), its limit as t' -> t+, the lowest order of its expansion around t
  // that is not zero. A corner of a triangle fragment is then a Euclidean
  // point (W != 0) while the scene is valid.
  Point4<typename K::FT> position_after(const symbolic::Symbolic_vertex& v, const typename K::FT& t) const;
  // The plane of site p the same way: its motion plane, or, where that
  // vanishes identically (the E-plane of an edge parallel to z), the first
  // order of its ε-expansion that does not, at t or, where it vanishes at t,
  // as t' -> t+. The fragments on each side of p's node lie on that side of
  // this plane, so a point's side of it is the side it sees them from.
  Plane4<typename K::FT> plane_after(const symbolic::Symbolic_plane& p, const typename K::FT& t) const;
  // The P-plane of the pencil through v, x ∨ z ∨ position(v): the implicit
  // P-cut through an intersection point (thesis 6.4.2). Computed once per vertex.
  const Plane4<typename K::Poly>& p_plane_through(const symbolic::Symbolic_vertex& v) const;
  // How many classifications rule 4 could not decide, and the first few.
  long unresolved() const { return unresolved_; }
  const std::vector<std::pair<symbolic::Symbolic_vertex, symbolic::Symbolic_plane>>& unresolved_cases() const {
    return unresolved_cases_;
  }

private:

  // What decides classify(v, p) at every instant: the value f = dot(plane,
  // point), or, when f is identically zero (rule 4), the first coefficient of
  // its ε-expansion that is not; and the W of a derived vertex taken the same
  // way (zero for a scene vertex, whose W is positive, and for a direction).
  struct Deciding {
    bool incident = false;   // rule 1: nothing to decide
    bool perturbed = false;  // the polynomials come from the ε-expansion
    typename K::Poly value, w;
  };
  // Computed once per pair (v canonical): a simulation rebuilds the tree at
  // every batch and classifies mostly the same pairs again.
  const Deciding& deciding(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p) const;
  Deciding decide(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p) const;
  // Rules 1-4 in exact arithmetic, v canonical.
  Classification classify_exactly(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p,
                                  const typename K::Time& t) const;
  const symbolic::Scene_geometry<Poly<typename K::Poly>>& perturbed() const;
  Point4<typename K::Poly> position_of(const symbolic::Symbolic_vertex& v) const;  // position, not cached

  const K* k_;
  symbolic::Scene_geometry<typename K::Poly> motion_;
  // Caches, looked up only (node-based: the references handed out stay valid).
  using Pair = std::pair<symbolic::Symbolic_vertex, symbolic::Symbolic_plane>;
  mutable std::unordered_map<symbolic::Symbolic_plane, Plane4<typename K::Poly>, symbolic::Symbolic_hash> planes_;
  mutable std::unordered_map<symbolic::Symbolic_vertex, Point4<typename K::Poly>, symbolic::Symbolic_hash> points_;
  // Flat, the values held apart: a slot is a cache line, the table about as
  // large as a node-based one, and a Deciding stays in place.
  mutable kvd::detail::Flat_map<Pair, std::unique_ptr<Deciding>, symbolic::Symbolic_hash> deciding_;
  mutable std::unordered_map<Pair, std::vector<typename K::Poly>, symbolic::Symbolic_hash> certificates_;
  mutable std::unordered_map<std::pair<std::size_t, std::size_t>, typename K::Poly, symbolic::Symbolic_hash> edge_lines_;
  mutable std::unordered_map<symbolic::Symbolic_vertex, Point4<typename K::Poly>, symbolic::Symbolic_hash> positions_;
  mutable std::unordered_map<symbolic::Symbolic_vertex, Plane4<typename K::Poly>, symbolic::Symbolic_hash> p_planes_;
  mutable std::unordered_map<symbolic::Symbolic_plane, Plane4<typename K::Poly>, symbolic::Symbolic_hash> site_planes_;
  mutable std::optional<symbolic::Scene_geometry<Poly<typename K::Poly>>> perturbed_;
  bool z_euclidean_;
  // Rule 2 on intervals first: the exact kernel with its filter on only.
  // Copies share it (it caches the positions at the last instant only).
  std::shared_ptr<Classification_filter> filter_;
  mutable long unresolved_ = 0;
  mutable std::vector<std::pair<symbolic::Symbolic_vertex, symbolic::Symbolic_plane>> unresolved_cases_;
};

}  // namespace kvd::predicates
