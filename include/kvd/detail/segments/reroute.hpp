// One segment's steps below a node decided again, down to the tree before
// that segment (proofs/segment-local-update.md, "Frontier replay"). Both
// kinetic runs use it: Kinetic_segment_bsp when the keys that changed at
// its topmost failing node are one segment's, Aeg_kinetic_bsp when the
// signs its failing certificates changed are one segment's (reroutes).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "kvd/detail/segments/bsp_builder.hpp"

namespace kvd::segments {

// A subtree to make again: its root, and for a frontier node the rank of
// the segment whose cuts come first there (its steps changed above it, or
// it is the earliest of several segments whose steps did). `several`: the
// node's log changed in the blocks of several segments, so its old content
// cannot be told by its log (the remake sets it aside with the log less the
// first segment's block, which would pass for unchanged): it counts as
// holding a failing node, and only the old subtrees below it whose own logs
// match are kept (proofs/segment-local-update.md, "Several segments at one
// instant"). A root without a rank is replayed whole (the kept run), or
// remade when it is its segment's first cut on its path (the run on the
// paper's set).
struct Replay_root {
  std::size_t node;
  std::optional<std::size_t> rank;
  bool several = false;
};

// Before a frontier node below which several segments' steps were decided
// again is made again, and on the steps of every cell a remake fits (the
// crossings of two segments later than the remade one are located as
// logged there too): the log's crossings of a segment whose crossing walk
// does not reach the node go. Such a crossing, with a segment of the
// frontier's rank or later, is not found by the walks above the frontier
// and is located as logged; it lands where its walk does not reach only if
// it went at this instant. (In an exact log a crossing's location and its
// segment's walk take the same way down to the first cut that segment made
// on it, below which the location goes on alone; no cut of a segment
// arriving at a frontier node lies above it, since its parent's rank is
// below the frontier's and ranks do not decrease down a path.)
void drop_unwalked_crossings(std::vector<Arrival>& log);

// Called (when set) for a node above the frontier whose block of the
// segment's arrivals was rewritten: the node, the block before and after.
using Reroute_above = std::function<void(std::size_t, const std::vector<Arrival>&, const std::vector<Arrival>&)>;

// The steps of the segment of rank r at u (whose cut is of an earlier rank
// than `frontier`) decided again from u down to the frontier: the first
// nodes of rank `frontier` or later, which the insertion of that rank split
// (Bsp_builder::reroute; `frontier` is r itself but when the steps of
// several segments changed: Kinetic_segment_bsp::frontier_replay). The
// segment's block in every log its steps reach, before or after, becomes the
// new one; u's own arrivals stay. Returns the frontier nodes whose block
// changed, to be made again with the frontier's segment's cuts first
// (Subtree_fit::remake with rank `frontier`); the cuts above them stay.
template <class K>
std::vector<std::size_t> reroute_segment(Bsp_builder<K>& builder, const Cylindrical_bsp& tree, Build_log& log,
                                         const std::vector<std::size_t>& rank, std::size_t u, std::size_t r,
                                         std::size_t frontier, const Reroute_above& above);

}  // namespace kvd::segments
