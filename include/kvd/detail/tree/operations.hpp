// The tree operations of thesis 7.2, on a KVD kept in place. Every node
// holds a piece of one site (a vertex's P-cut, an edge's E-cut or a
// triangle's T-cut); sites have the fixed priority of the construction. The
// tree of a cell C over sites S is defined recursively (proofs/local_update.md):
// its root is the highest-priority site meeting C, its subtrees the trees of
// the two halves of C. The operations keep that form:
//  * split_tree: the trees of the two halves of a cell cut by a new plane;
//  * merge: priority-based merging (thesis Fig. 7.2), the tree of a cell
//    from the trees of its two halves once the cut between them is gone;
//    pieces of one site meeting across that cut are joined into one node;
//  * insert: out-of-order insertion (thesis Fig. 7.3), a site placed above
//    the lower-priority nodes it meets, which are split by its plane;
//  * drag: a node taken out of the tree, its subtrees merged (thesis
//    Fig. 7.5; its MERGE effects are drags of incident nodes, its SPLIT
//    effects their reinsertion, see kinetic/local_update.hpp).
// Removed nodes are recycled. `touched` counts the distinct nodes the
// operations created, re-cut (a new fragment, by split, join or refit),
// relinked (new children) or removed; nodes only descended through are not
// counted.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "kvd/scene/scene.hpp"
#include "kvd/detail/tree/fragment_split.hpp"
#include "kvd/detail/tree/journal.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::tree {

// A site's place in the construction order (0 first): the priority of its cut.
std::size_t cut_priority(const scene::Scene& s, const Symbolic_plane& cut);
// A site's whole fragment: the vertex, the whole edge, the whole triangle.
Fragment site_fragment(const scene::Scene& s, const Symbolic_plane& cut);
// `sites` in construction order.
void sort_by_priority(const scene::Scene& s, std::vector<Symbolic_plane>& sites);
// Every site of the scene, in construction order.
std::vector<Symbolic_plane> sites_in_priority_order(const scene::Scene& s);

// The planes are taken by value: the operations add nodes, and a reference
// to a node's cut would dangle once the node array grows (AddressSanitizer
// found merge passing one).
template <class K>
class Tree_editor {
public:
  // With a journal, every node is saved there before its first change.
  Tree_editor(Kvd_tree& t, const Fragment_splitter<K>& split, Tree_journal* journal = nullptr);

  // The trees on the negative and positive side of `plane`, the plane of a
  // site of higher priority than every node of subtree t.
  std::pair<int, int> split_tree(int t, Symbolic_plane plane);
  // One tree from t1 and t2, the trees of the two sides of `between`.
  int merge(int t1, int t2, Symbolic_plane between);
  // Subtree t with the site `cut` (fragment f, inside t's cell) added.
  int insert(int t, Symbolic_plane cut, Fragment f);
  // Subtree n without node n.
  int drag(int n);
  // Node n given f, a new piece of its own site in the same cell.
  void refit(int n, Fragment f);

  // The distinct nodes touched, increasing.
  std::vector<int> touched_nodes() const;

private:
  Node& node(int i) { return t_.nodes[static_cast<std::size_t>(i)]; }
  // Node i, about to be changed.
  Node& edit(int i);
  std::size_t priority(int n) const;
  int make(Node n);
  void relink(int n, int left, int right);
  void release(int n);
  Fragment join(const Fragment& a, const Fragment& b, const Symbolic_plane& between, const Symbolic_plane& cut) const;

  Kvd_tree& t_;
  const Fragment_splitter<K>& split_;
  const scene::Scene& s_;
  Tree_journal* journal_;
  std::vector<int> touched_;
};

}  // namespace kvd::tree
