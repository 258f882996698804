// The augmented BSP of seed 003, section 3.1.4: the cylindrical BSP
// (cylindrical_bsp.hpp) written so that a flip changes none of it.
//
// Two changes of representation, both the paper's:
//  - ternary nodes: where a segment s_i puts two point cuts into one leaf of
//    B_{i-1} (its endpoints, or its crossings with that leaf's floor and
//    roof), they are one node with three children, the cells left of both
//    cuts, between them and right of both. In B the first cut's child on
//    the second's side is the second cut, a side that changes when s_i
//    turns through vertical;
//  - the marked endpoint: the children of an intersection cut through
//    s_i ∩ s_j, s_i the earlier in priority, are the side of s_i's marked
//    endpoint (endpoint 0, the first written) and the other, not left and
//    right. A flip of s_i reverses the x order of the points on it, so in B
//    it swaps the children of every such cut.
// Vertex cuts left alone keep left and right; edge cuts keep below and
// above. Nodes keep no cells: a cell is read off the cuts above it.
//
// `augment` writes a tree B, in force at t, in this form, and `expand` reads
// it back at t. Why a lone flip leaves the augmented tree as it was is
// argued in proofs/segment-certificates.md, "The augmented BSP"; the run on
// the paper's certificates checks it after every flip it turns in place,
// when it validates (aeg_kinetic_bsp.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

enum class Augmented_kind : std::uint8_t { leaf, ternary, vertex, intersection, edge };

struct Augmented_node {
  Augmented_kind kind = Augmented_kind::leaf;
  Site_point point;   // point cuts; a ternary node's first cut (the one its segment's insertion put first)
  Site_point second;  // a ternary node's second cut
  std::uint32_t segment = 0;  // edge cuts; a ternary node's segment; an intersection cut's earlier segment
  // ternary: left, between, right; vertex: left, right; intersection: the
  // marked endpoint's side, the other; edge: below, above.
  std::array<std::int32_t, 3> child{-1, -1, -1};
};

struct Augmented_counts {
  std::size_t ternary = 0, binary_point_cuts = 0, edge_cuts = 0, leaves = 0;
};

class Augmented_bsp {
public:
  std::vector<Augmented_node> nodes;  // pre-order: nodes[0] is the root

  // Pre-order as nested parentheses, as Cylindrical_bsp::text: "(T s3.0
  // s1xs3 L M R)" a ternary node (its first cut, its second, then its
  // children), "(I s1xs4 M O)" an intersection cut with its marked-endpoint
  // side first, "(V s3.0 L R)", "(E s2 B A)" and ".".
  std::string text() const;
  Augmented_counts counts() const;
};

template <class K>
Augmented_bsp augment(const Cylindrical_bsp& bsp, const Segment_predicates<K>& pred, const typename K::Time& t);

// The tree B that `a` encodes at t (cells included), numbered in pre-order
// as Cylindrical_bsp::compacted.
template <class K>
Cylindrical_bsp expand(const Augmented_bsp& a, const Segment_predicates<K>& pred, const typename K::Time& t);

}  // namespace kvd::segments
