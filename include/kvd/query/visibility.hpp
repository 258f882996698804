// Back-to-front visibility order of triangle fragments (thesis 1.2): walk the
// tree from the viewpoint, visiting at every node the subtree on the far side
// of its plane, then the node's own triangle fragment (T-nodes), then the
// near side. A viewpoint on a node's plane sees that node's fragments edge-on,
// and either order of the two sides is correct; the negative side goes first.
#pragma once

#include <vector>

#include "kvd/predicates/classify.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::query {

// The T-nodes of `tree` (indices into tree.nodes), farthest first, as seen
// from the Euclidean point `view` at instant t.
template <class K>
std::vector<int> back_to_front(const predicates::Classifier<K>& classifier, const tree::Kvd_tree& tree,
                               const Point4<typename K::FT>& view, const typename K::FT& t);

}  // namespace kvd::query
