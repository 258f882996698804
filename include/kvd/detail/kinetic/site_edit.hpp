// The two ways a local update edits the tree in force inside a cell whose
// moving sites' pieces it knows (proofs/local_update.md, sections 3, 5, 6).
//
//  * reinsert: every node of a moving site in the subtree is dragged,
//    lowest priority first, and each moving site inserted again at the
//    subtree's place with its piece, highest priority first.
//  * recut: the subtree is walked down from its root with the pieces the
//    moving sites have just after the batch, split by each node's cut. A
//    node of a site that does not move keeps its piece; a node of a moving
//    site keeps its place, and takes its new piece, when its site still
//    meets the cell, no moving site of higher priority enters the cell,
//    and no piece of a site that does not move changes sides of its plane
//    (checked below it). Where one of these fails, the subtree there is
//    made again by `reinsert`; a subtree that holds no moving site and that
//    no moving piece enters is not visited. So only the cells the moving
//    walls swept are re-cut.
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "kvd/detail/tree/fragment_split.hpp"
#include "kvd/detail/tree/journal.hpp"
#include "kvd/detail/tree/operations.hpp"
#include "kvd/detail/tree/slot_marks.hpp"
#include "kvd/detail/tree/tree_links.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::kinetic {

// Moving sites with their pieces in one cell, highest priority first.
using Site_pieces = std::vector<std::pair<symbolic::Symbolic_plane, tree::Fragment>>;

template <class K>
class Site_edit {
public:
  // `links` are those of t before any edit (they find the moving sites'
  // nodes). With a journal, every node is saved there before its first edit.
  Site_edit(tree::Kvd_tree& t, const tree::Tree_links& links, const tree::Fragment_splitter<K>& split,
            const std::set<symbolic::Symbolic_plane>& moving, tree::Tree_journal* journal);

  // A child link: the subtree hanging from `parent` on its right or left
  // side; parent -1 is the root.
  struct Place {
    int parent;
    bool right;
  };

  // The subtree at `at` made the tree just after the batch of its cell,
  // `pieces` being the moving sites' pieces in that cell just after.
  void reinsert(Place at, Site_pieces pieces);
  void recut(Place at, Site_pieces pieces);

  // The nodes the edits re-cut, relinked, created or removed, the parents
  // given a new child among them (Update_cost::changed), increasing.
  std::vector<int> changed() const;

private:
  int child(Place at) const;
  void hang(Place at, int sub);
  bool moves(int n) const;
  // Whether no node below n of a site that does not move lies, just after
  // the batch, across the plane of n's cut from the side it hangs on.
  bool sides_kept(int n) const;
  bool sides_kept(int n, const symbolic::Symbolic_plane& plane, bool right) const;

  tree::Kvd_tree& t_;
  const tree::Fragment_splitter<K>& split_;
  const scene::Scene& s_;
  const std::set<symbolic::Symbolic_plane>& moving_;
  tree::Tree_editor<K> editor_;
  tree::Tree_journal* journal_;
  tree::Slot_marks holds_;  // the nodes whose subtree holds a node of a moving site
  std::vector<int> relinked_;
};

}  // namespace kvd::kinetic
