#include "kvd/detail/tree/fragment_split.hpp"

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/predicates/in_triangle.hpp"
#include "kvd/symbolic/incidence.hpp"

namespace kvd::tree {

namespace {
using SE = symbolic::Symbolic_edge;
using SP = Symbolic_plane;
using SV = Symbolic_vertex;
}  // namespace

template <class K>
int Fragment_splitter<K>::side(const SV& v, const SP& p, In_plane& in_plane) const {
  if (evaluated_) evaluated_->emplace_back(v, p);
  const predicates::Classification c = c_.classify(v, p, t_);
  if (c.rule == predicates::Rule::perturbation) in_plane.perturbed.push_back(v);
  else if (c.rule != predicates::Rule::incidence) in_plane.all = false;
  return c.side;
}

// A fragment of `cut` whose corners all lie in a triangle's plane for good
// (the perturbation decided them, or they lie there by construction), cut
// from a scene feature of another object lying in that plane for good (a
// triangle sliding in another's plane), lies in the plane, and the two meet
// where it meets the triangle. The perturbation puts it on one side, and no
// sign changes when they come to meet (proofs/collision_response.md, case
// (iii)). In a non-vertical triangle's cell every corner of such a fragment
// is in the triangle, since the cell meets the plane in the triangle; the
// exact test keeps a vertical triangle apart from the fragments in its plane
// beside it. (A vertical triangle's fragment can have every corner in the
// plane of a triangle below it, which it does not lie in: hence the test of
// the feature, made only when the corners pass.)
template <class K>
void Fragment_splitter<K>::check_not_overlapping(const In_plane& in_plane, const SP& plane, const SP& cut) const {
  if (plane.kind != SP::Kind::T || !in_plane.all || in_plane.perturbed.empty()) return;
  const scene::Scene& s = c_.motion().scene();
  // An object's own features lie in its faces' planes (an edge between two
  // of them, a face split in two): no contact.
  if (symbolic::object_of(s, cut) == s.triangle_object[plane.id]) return;
  bool feature_in_plane = true;
  symbolic::for_each_vertex(s, cut, [&](std::size_t v) {
    feature_in_plane = feature_in_plane && c_.classify(SV::endpoint(v), plane, t_).rule == predicates::Rule::perturbation;
  });
  if (!feature_in_plane) return;
  for (const SV& v : in_plane.perturbed)
    if (predicates::in_closed_triangle(c_, v, plane.id, t_))
      throw Build_error("a fragment of " + symbolic::to_string(cut) + " lies in the plane of triangle " +
                            std::to_string(plane.id) + " and meets the triangle: the triangles meet at the build instant",
                        Contact{cut, plane.id});
}

// The vertex where `edge` crosses `plane`.
// Only P- and E-planes cross fragments (split() throws before a T-plane does).
template <class K>
SV Fragment_splitter<K>::crossing(const SE& edge, const SP& plane) const {
  const bool p_cut = plane.kind == SP::Kind::P;
  SV v{};
  switch (edge.kind) {
    case SE::Kind::edge: v = p_cut ? SV::thread(edge.a, plane.id) : SV::intersection(edge.a, plane.id); break;
    // Two P-planes meet only on the axis x ∨ z (a Euclidean z makes them a pencil).
    case SE::Kind::pt: v = p_cut ? SV::axis(edge.b) : SV::internal_thread(edge.a, plane.id, edge.b); break;
    case SE::Kind::et:
      v = p_cut ? SV::internal_thread(plane.id, edge.a, edge.b) : SV::internal_intersection(edge.a, plane.id, edge.b);
      break;
  }
  return symbolic::canonical(c_.motion().scene(), v);
}

namespace {
// A fragment of `cut` crossing a triangle's plane: the triangles meet.
void check_not_triangle(const SP& plane, const SP& cut) {
  if (plane.kind == SP::Kind::T)
    throw Build_error("a fragment of " + symbolic::to_string(cut) + " crosses the plane of triangle " +
                          std::to_string(plane.id) + ": the triangles intersect at the build instant",
                      Contact{cut, plane.id});
}
}  // namespace

template <class K>
std::pair<Piece, Piece> Fragment_splitter<K>::split(const Fragment& f, const SP& plane, const SP& cut) const {
  In_plane in_plane{true, {}};
  if (const auto* v = std::get_if<SV>(&f)) {
    // A point on the plane can only be one that lies there by construction
    // and never happens in priority order; it goes to the positive side.
    const int s = side(*v, plane, in_plane);
    check_not_overlapping(in_plane, plane, cut);
    if (s < 0) return {f, std::nullopt};
    return {std::nullopt, f};
  }
  if (const auto* e = std::get_if<Edge_fragment>(&f)) {
    const int sa = side(e->a, plane, in_plane), sb = side(e->b, plane, in_plane);
    check_not_overlapping(in_plane, plane, cut);
    if (sa <= 0 && sb <= 0 && (sa < 0 || sb < 0)) return {f, std::nullopt};
    if (sa >= 0 && sb >= 0) return {std::nullopt, f};
    check_not_triangle(plane, cut);
    const SV x = crossing(e->edge, plane);
    const Edge_fragment first{e->a, x, e->edge}, second{x, e->b, e->edge};
    return sa < 0 ? std::pair<Piece, Piece>{first, second} : std::pair<Piece, Piece>{second, first};
  }
  const auto& t = std::get<Triangle_fragment>(f);
  std::vector<int> s;
  bool any_neg = false, any_pos = false;
  for (const auto& c : t.corners) {
    s.push_back(side(c, plane, in_plane));
    any_neg = any_neg || s.back() < 0;
    any_pos = any_pos || s.back() > 0;
  }
  check_not_overlapping(in_plane, plane, cut);
  if (!any_pos) return {f, std::nullopt};
  if (!any_neg) return {std::nullopt, f};
  check_not_triangle(plane, cut);
  // A triangle fragment travels with its own T-cut: cut.id is its triangle.
  const SE cut_line{plane.kind == SP::Kind::P ? SE::Kind::pt : SE::Kind::et, plane.id, cut.id};
  return {clip(t, s, -1, plane, cut_line), clip(t, s, +1, plane, cut_line)};
}

// The part of a crossed triangle fragment on side `keep` (corners keep
// their order; new corners where sides cross, joined by the cut line).
// Internal sides already name their triangle, as cut_line does.
template <class K>
Triangle_fragment Fragment_splitter<K>::clip(const Triangle_fragment& t, const std::vector<int>& s, int keep,
                                           const SP& plane, const SE& cut_line) const {
  Triangle_fragment out;
  const std::size_t n = t.corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const int si = s[i] * keep, sj = s[j] * keep;
    if (si >= 0) {
      out.corners.push_back(t.corners[i]);
      out.sides.push_back(sj < 0 ? (si > 0 ? t.sides[i] : cut_line) : t.sides[i]);
      if (si > 0 && sj < 0) {
        out.corners.push_back(crossing(t.sides[i], plane));
        out.sides.push_back(cut_line);
      }
    } else if (sj > 0) {
      out.corners.push_back(crossing(t.sides[i], plane));
      out.sides.push_back(t.sides[i]);
    }
  }
  return out;
}

#define KVD_INSTANTIATE_SPLITTER(K) template class Fragment_splitter<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SPLITTER)

}  // namespace kvd::tree
