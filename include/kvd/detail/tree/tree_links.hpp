// What a kinetic run looks up in the tree in force without walking it: each
// node's parent, whether a slot is in the tree, and the nodes holding each
// site (thesis 7.3: the pieces a V- or E-update moves). Kept up to date from
// the nodes an edit changed, as the structure hash is (Subtree_hashes).
#pragma once

#include <map>
#include <set>
#include <vector>

#include "kvd/detail/tree/slot_marks.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::tree {

class Tree_links {
public:
  Tree_links() = default;
  explicit Tree_links(const Kvd_tree& t) { reset(t); }
  // Every node of t indexed afresh.
  void reset(const Kvd_tree& t);
  // t after edits that re-cut, relinked, created or released exactly the
  // nodes `changed` (Update_cost::changed), from the tree these links were of.
  void update(const Kvd_tree& t, const std::vector<int>& changed);

  // -1 at the root; meaningful for nodes in the tree only.
  int parent(int n) const { return parent_[static_cast<std::size_t>(n)]; }
  // Whether slot n holds a node of the tree (not a released slot).
  bool live(int n) const;
  // The nodes cut by `site`, increasing.
  const std::set<int>& holding(const Symbolic_plane& site) const;
  // Marks n and its ancestors, up to the first already marked; n must be live.
  void mark_path(int n, Slot_marks& marks) const;

private:
  void index(const Kvd_tree& t, int n);
  void unindex(int n);

  std::vector<int> parent_;      // per slot
  std::vector<char> released_;   // per slot
  std::vector<int> free_;        // t.free_nodes when last indexed
  std::vector<char> indexed_;    // per slot: whether it is in sites_ (under cut_)
  std::vector<Symbolic_plane> cut_;
  std::map<Symbolic_plane, std::set<int>> sites_;
};

}  // namespace kvd::tree
