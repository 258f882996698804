// Structural comparison of KVD trees (DESIGN.md sections 5 and 6).
//
// Two trees are equal when they have the same shape, node kinds, features
// and fragments. Fragments are compared in canonical form: an edge
// fragment's two vertices in increasing order, a triangle fragment's corners
// starting from the smallest and keeping their cyclic orientation.
//
// The canonical serialisation is the pre-order walk
// S(n) = TEXT(n) "[" S(left) "][" S(right) "]", with S of an empty subtree
// the empty string, and TEXT(n) = KIND FEATURE ":" the fragment's canonical
// vertices joined by ",", e.g. "E2:SV(v0),SV(e2,P1)". KIND is P, E or T;
// vertices are written as symbolic::to_string writes them.
//
// The structure hash digests the same text subtree by subtree (a Merkle
// hash), so that a kinetic run keeps it up to date along the paths an
// update changed (detail/tree/subtree_hashes.hpp):
// H(n) = SHA256(TEXT(n) "[" H(left) "][" H(right) "]"), with H of an empty
// subtree the empty string and each H written as lowercase hex (UTF-8, no
// terminator). The structure hash is H(root), and SHA256("") for a tree
// with no node: the same for every kernel and platform.
#pragma once

#include <compare>
#include <optional>
#include <string>
#include <vector>

#include "kvd/tree/kvd_tree.hpp"

namespace kvd::tree {

// The fragment in canonical form (a triangle fragment's sides rotated with
// its corners): fragments equal as pieces of a tree are equal here.
Fragment canonical(Fragment f);

std::string canonical_serialisation(const Kvd_tree& t);
// What TEXT(n) writes, as values: two nodes have equal contents exactly
// when their texts are equal. Cheaper to compare than the texts.
struct Node_content {
  Symbolic_plane cut;
  std::vector<Symbolic_vertex> vertices;  // canonical order
  auto operator<=>(const Node_content&) const = default;
};
Node_content content(const Node& n);
// TEXT(n), and H(n) from the hashes of n's subtrees.
std::string canonical_text(const Node& n);
std::string node_hash(const Node& n, const std::string& left, const std::string& right);
std::string structure_hash(const Kvd_tree& t);
// The first difference in pre-order, in words ("at root/+/-: node kinds
// differ: P(3) against E(2)"), or none when the trees are equal.
std::optional<std::string> first_difference(const Kvd_tree& a, const Kvd_tree& b);

}  // namespace kvd::tree
