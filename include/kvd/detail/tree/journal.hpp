// The edits of a tree, kept so that they can be undone: each node as it
// was before its first edit, the node count, the free slots and the root.
// A kinetic batch edits the tree in force in place and undoes the edits
// when it fails (a collision, a floating-point repair) instead of working
// on a copy of the whole tree.
#pragma once

#include <cstddef>
#include <unordered_set>
#include <utility>
#include <vector>

#include "kvd/tree/kvd_tree.hpp"

namespace kvd::tree {

class Tree_journal {
public:
  explicit Tree_journal(Kvd_tree& t)
      : t_(t), nodes_(t.nodes.size()), root_(t.root), free_(t.free_nodes) {}

  // Called before node n is changed.
  void save(int n) {
    const auto i = static_cast<std::size_t>(n);
    if (i >= nodes_ || !saved_.insert(n).second) return;  // new since the journal began, or saved already
    old_.emplace_back(n, t_.nodes[i]);
  }

  // The nodes saved, each as it was before its first edit, and the free
  // slots when the journal began (a saved slot among them held no node).
  const std::vector<std::pair<int, Node>>& saved() const { return old_; }
  const std::vector<int>& free_at_start() const { return free_; }

  // The tree exactly as it was when the journal began, node for node.
  void undo() {
    t_.nodes.resize(nodes_);
    for (auto& [n, node] : old_) t_.nodes[static_cast<std::size_t>(n)] = std::move(node);
    t_.root = root_;
    t_.free_nodes = std::move(free_);
    old_.clear();
  }

private:
  Kvd_tree& t_;
  std::size_t nodes_;
  int root_;
  std::vector<int> free_;
  std::unordered_set<int> saved_;
  std::vector<std::pair<int, Node>> old_;
};

}  // namespace kvd::tree
