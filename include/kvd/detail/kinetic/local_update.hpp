// The local update of thesis 7.3: the tree just after a batch of events,
// obtained from the tree in force by the operations of thesis 7.2 alone.
//
// A failing certificate names features (its vertex, its plane's feature,
// the edges of an intersection point); the sites holding them, less three,
// are the moving sites. V-update (VV, VE and the vertex certificates) moves
// the sites of a vertex: its P-cut and the E- and T-cuts of its edges and
// triangles, but not the P-cut a VV vertex crosses (thesis Fig. 7.8).
// E-update (IV, II, ET) moves the sites of the edge whose intersection
// point moved: its E-cut and the T-cuts of its triangles, not those of the
// edge whose E-plane it lies on, and an IV's crossed P-cut only when its
// node hangs below a node of those sites. A batch moves the union of its
// events' sites.
//
// The reference update drags the nodes of the moving sites, lowest
// priority first, so each drag merges subtrees that hold no moving site
// (the thesis's MERGE effects), then inserts the moving sites again in
// priority order, out of order where they meet lower-priority nodes (the
// thesis's SPLIT effects: the pieces land wherever the sites now are). The
// part of the tree that holds no moving site is the tree of the other
// sites, which no failing sign involves, so it is unchanged by the batch;
// the insertions then give the tree just after it, whatever order the
// batch's events would be taken in (proofs/local_update.md, sections 3 and
// 4). Where the batch's failing signs all lie in one subtree, the update is
// confined to it (section 5); and there it drags and inserts only where a
// walk down from the subtree's root cannot keep a node (site_edit.hpp,
// section 6).
#pragma once

#include <cstddef>
#include <set>
#include <vector>

#include "kvd/kinetic/certificate.hpp"
#include "kvd/scene/scene.hpp"
#include "kvd/detail/tree/fragment_split.hpp"
#include "kvd/detail/tree/journal.hpp"
#include "kvd/detail/tree/tree_links.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::kinetic {

// A site with the sites whose cuts it bounds: a vertex's P-cut with the
// E- and T-cuts of its edges and triangles, an edge's E-cut with the T-cuts
// of its triangles. A T-cut is only valid inside its edges' walls, so an
// edge never moves without its triangles.
std::set<symbolic::Symbolic_plane> sites_with(const scene::Scene& s, const symbolic::Symbolic_plane& site);

// The sites that a failing certificate's features move, in the tree in
// force `t` with its links (an IV failure moves its P-plane only where its
// node hangs below a node of the moving edge's sites).
template <class Poly>
std::set<symbolic::Symbolic_plane> moving_sites(const scene::Scene& s, const tree::Tree_links& links,
                                                const tree::Kvd_tree& t, const Certificate<Poly>& failing);

struct Update_cost {
  std::size_t sites = 0;          // moving sites
  std::size_t nodes_touched = 0;  // distinct nodes re-cut, relinked, created or removed
  // What the event changed: the larger of the number of cuts and fragments
  // after the update that no node had before and the number before that no
  // node has after, the fewest nodes any update between the two trees must
  // write. A piece dragged out and inserted again as it was, or a node only
  // relinked, is touched, not changed. Counted with a journal only.
  std::size_t nodes_changed = 0;
  // The nodes touched, with the parents given a new child in place of a
  // dragged node or of the confined subtree's old root: what the structure hash and
  // the links must see again (Subtree_hashes::update, Tree_links::update).
  std::vector<int> changed;
  bool widened = false;  // a scope was asked for and the whole tree taken
};

// The subtree a batch is confined to (proofs/local_update.md, section 5):
// the lowest node whose subtree holds, for every failing certificate, the
// node holding it and every ancestor of that node cut by a site the
// certificate names (moved or not); for a VE failure of a vertex of one of
// the edge's triangles (that triangle turning through z), every node cut
// by the triangle or by its edges' E-planes. -1 (the whole tree) when a
// failure is not a VV, IV, II or VE one, or for no failure.
template <class Poly>
int update_scope(const scene::Scene& s, const tree::Tree_links& links, const tree::Kvd_tree& t,
                 const std::vector<const Certificate<Poly>*>& failing);

// How the update edits the tree (site_edit.hpp): `recut` walks down from the
// scope and makes again only the subtrees where a moving site's piece or
// plane changed sides (`--update local`); `reinsert` drags every node of a
// moving site in the scope and inserts the sites again (`--update
// reinsert`, the reference, with the scope the whole tree).
enum class Edit { recut, reinsert };

// `links` are t's: they find the nodes of the moving sites without a walk
// of the tree. With a journal, every node is saved there before its first
// change, so that a failed update can be undone.
//
// With `scope` a node, the update stays in its subtree: each moving site is
// taken with its piece inside the scope's cell. When a sign above the scope
// shows as changed (a moving site meeting the cell of an ancestor of lower
// or equal priority, or meeting the scope's cell now but holding no node in
// it before, or the reverse), the update takes the whole tree instead
// (Update_cost::widened). With `scope` -1 it takes the whole tree, each
// site with its whole fragment.
template <class K>
Update_cost local_update(tree::Kvd_tree& t, const tree::Tree_links& links, const tree::Fragment_splitter<K>& split,
                         const std::set<symbolic::Symbolic_plane>& moving, int scope = -1,
                         tree::Tree_journal* journal = nullptr, Edit way = Edit::reinsert);

}  // namespace kvd::kinetic
