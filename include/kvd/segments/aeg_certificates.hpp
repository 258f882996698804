// The certificates of seed 003, section 3.1 (Lemma 3.1): one per transient
// node (its cell collapses), one per endpoint (the segment just above or just
// below it changes) and one per segment (it turns through vertical).
//
// The kinetic BSP with local updates keeps a larger set, every sign its
// construction decides (kinetic_segment_bsp.hpp), because its updates replay
// that construction. The paper's set is computed here from a tree and an
// instant: to count it next to ours (kvd bench aeg), and to check the
// paper's claim that one of its certificates fails wherever the tree changes
// (proofs/segment-certificates.md, tests/test_aeg_certificates.cpp). A run
// on this set alone, with exact failure times, is aeg_kinetic_bsp.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

// The transient nodes of b, in pre-order: the parent is a point cut, and no
// point cut lies in the subtree (the cell holds no endpoint and no crossing).
std::vector<std::size_t> transient_nodes(const Cylindrical_bsp& b);

struct Aeg_certificate_counts {
  std::size_t transient = 0, endpoints = 0, flips = 0;
  std::size_t total() const { return transient + endpoints + flips; }
};
Aeg_certificate_counts aeg_certificate_counts(const Cylindrical_bsp& b, std::size_t segments);

// What the endpoint and flip certificates assert just after t.
struct Aeg_state {
  std::vector<int> flips;  // per segment: the sign of x(endpoint 1) - x(endpoint 0)
  // Per endpoint: the segment just below it and the one just above it, among
  // the others whose x-range holds it (-1: none).
  std::vector<std::array<std::int64_t, 2>> neighbours;
};

template <class K>
Aeg_state aeg_state(const Segment_predicates<K>& pred, const typename K::Time& t);

// The neighbours of endpoint e read off the tree b built at t: the floor and
// the roof of the leaf that holds the points just beside e on the side away
// from its segment (aeg_leaf; -1: none). The same as aeg_state's, in O(depth) instead
// of O(n): that leaf's near wall is e's, so its floor and roof hold x(e) in
// their x-ranges, and a segment between them and e would cross the leaf.
// The walk starts at `from`, an ancestor of that leaf (the root by default).
template <class K>
std::size_t aeg_leaf(const Cylindrical_bsp& b, const Segment_predicates<K>& pred, const typename K::Time& t,
                     std::size_t e, std::size_t from = 0);
template <class K>
std::array<std::int64_t, 2> aeg_neighbours(const Cylindrical_bsp& b, const Segment_predicates<K>& pred,
                                           const typename K::Time& t, std::size_t e);

// The paper's certificates that fail from t0 to t1 (t0 < t1), `before` being
// the tree just after t0 and `after` the one just after t1: the segments and
// endpoints whose state differs, the transient nodes of `before` whose cell
// is not proper at t1, and those of `after` whose cell was not proper at t0
// (a cell born at an event, seen backwards in time).
struct Aeg_failures {
  std::vector<std::size_t> flips, endpoints, transient_before, transient_after;
  bool any() const {
    return !flips.empty() || !endpoints.empty() || !transient_before.empty() || !transient_after.empty();
  }
};

template <class K>
Aeg_failures aeg_failures(const Cylindrical_bsp& before, const Cylindrical_bsp& after,
                          const Segment_predicates<K>& pred, const typename K::Time& t0,
                          const typename K::Time& t1);

}  // namespace kvd::segments
