// The KVD tree (thesis 4.4, 5.2): a BSP whose nodes are P-, E- and T-cuts
// named by scene features, each holding its fragment symbolically. The
// negative side of a node's plane is its left subtree, the positive side its
// right subtree.
#pragma once

#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include "kvd/symbolic/symbolic.hpp"

namespace kvd::tree {

using symbolic::Edge_fragment;
using symbolic::Symbolic_plane;
using symbolic::Symbolic_vertex;
using symbolic::Triangle_fragment;

// A P-node's fragment is its vertex; an E-node's a piece of its edge; a
// T-node's a convex piece of its triangle.
using Fragment = std::variant<Symbolic_vertex, Edge_fragment, Triangle_fragment>;

struct Node {
  Symbolic_plane cut;
  Fragment fragment;
  int left = -1, right = -1;  // indices into Kvd_tree::nodes, -1 for none
};

struct Tree_statistics {
  std::size_t p_nodes = 0, e_nodes = 0, t_nodes = 0, nodes = 0;
  std::size_t height = 0;  // nodes on the longest root-to-leaf path
};

class Kvd_tree {
public:
  std::vector<Node> nodes;
  int root = -1;
  // Slots of nodes that local updates removed, for reuse; no longer linked.
  std::vector<int> free_nodes;

  // Of the whole tree, or of the subtree rooted at node `subtree`.
  Tree_statistics statistics() const { return statistics(root); }
  Tree_statistics statistics(int subtree) const;
  // The tree in pre-order, one node a line, indented by depth, each child
  // prefixed by "-" (left) or "+" (right): "+ E(2) [SV(e2,P1) SV(v0) SE(e2)]".
  std::string describe() const;
};

std::string to_string(const Fragment& f);

}  // namespace kvd::tree
