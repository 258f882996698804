// Back-to-front visibility order of triangle fragments (thesis 1.2): walk the
// tree from the viewpoint, visiting at every node the subtree on the far side
// of its plane, then the node's own triangle fragment (T-nodes), then the
// near side. A viewpoint on a node's plane sees that node's fragments edge-on,
// and either order of the two sides is correct; the negative side goes first.
// The tree built at t holds on (t, t + δ): its planes and fragment corners at
// t are their limits from after t (Classifier::plane_after, position_after),
// which stay defined where the cuts degenerate at t itself.
#pragma once

#include <array>
#include <vector>

#include "kvd/predicates/classify.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::query {

// The T-nodes of `tree` (indices into tree.nodes), farthest first, as seen
// from the Euclidean point `view` at instant t.
template <class K>
std::vector<int> back_to_front(const predicates::Classifier<K>& classifier, const tree::Kvd_tree& tree,
                               const Point4<typename K::FT>& view, const typename K::FT& t);

// The Euclidean place at t of a corner of one of the tree's triangle
// fragments, exactly: Classifier::position_after divided by its W. Throws
// std::logic_error if that W is zero (no corner of a fragment is at infinity
// while the scene's triangles are proper).
template <class K>
std::array<typename K::FT, 3> corner_at(const predicates::Classifier<K>& classifier, const symbolic::Symbolic_vertex& v,
                                        const typename K::FT& t);

// Occlusion culling (thesis 8.2.4) when the decomposition point z is the
// viewpoint: every P- and E-plane then passes through the viewer, so the
// subtree on the far side of an opaque T-node lies behind its fragment and
// is not traversed. The counts are those of the thesis's Figure 8.9.
struct Culling {
  std::vector<int> order;  // the T-nodes drawn, back to front
  std::size_t triangle_nodes_culled = 0, triangle_nodes_total = 0;
  std::size_t tree_nodes_culled = 0, tree_nodes_total = 0;
};

// Requires the scene's z to be a Euclidean point; it is the viewpoint.
template <class K>
Culling back_to_front_culled(const predicates::Classifier<K>& classifier, const tree::Kvd_tree& tree,
                             const typename K::FT& t);

}  // namespace kvd::query
