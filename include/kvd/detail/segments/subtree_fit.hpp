// A node of the cylindrical BSP made again with the old subtrees below it
// kept where their arrivals did not change (proofs/segment-local-update.md,
// "Cells kept"). Both kinetic runs use it: Kinetic_segment_bsp for its
// frontier nodes, Aeg_kinetic_bsp for the subtrees its failing certificates
// name. The remake locates the crossings of later segments as the node's
// log holds them, so that log must hold only crossings that exist now (the
// frontier replay changes one segment's steps; the run on the paper's set
// drops those gone). Each run keeps its certificates by node slot, so it is
// told when a node's are to go (forget) or move to another slot (moved), and
// which nodes kept whole got a new cell (recelled, optional). A run that
// records no sign below the node as a certificate may let the fit keep an
// old subtree whose cell's walls moved (renamed, optional).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "kvd/detail/segments/bsp_builder.hpp"
#include "kvd/detail/segments/replay_ledger.hpp"
#include "kvd/segments/segment_scene.hpp"

namespace kvd::segments {

struct Subtree_fit_hooks {
  std::function<void(std::size_t)> forget;              // the node's certificates go
  std::function<void(std::size_t, std::size_t)> moved;  // a node's certificates move from one slot to another
  std::function<void(std::size_t)> recelled;            // a node kept whole got a new cell
  // Whether old subtree o keeps every sign of its steps when its cell's
  // moved walls are renamed, the new cell being `now` (the caller's check:
  // proofs/segment-local-update.md, "Cells kept", walls renamed).
  std::function<bool(std::size_t o, const Cell& now)> renamed;
};

template <class K>
class Subtree_fit {
public:
  // `dirty`: nodes holding a change (a failing certificate below them, or a
  // log changed in several segments' blocks, Replay_root::several): a
  // subtree of one is never taken whole.
  Subtree_fit(Cylindrical_bsp& tree, Build_log& log, const Segment_scene& scene, Bsp_builder<K>& builder,
              std::set<std::size_t>& dirty, Subtree_fit_hooks hooks);

  // Before a remake: the cuts of rank r below v are forgotten and their
  // slots freed, v's included; the first nodes below them of a later cut,
  // or leaves, are set aside whole (v's content moved to a free slot when v
  // is one, and marked dirty when v is). With `several`
  // (Replay_root::several), v is marked dirty first: its log changed in
  // several blocks, so its old content must not be taken whole. Returns
  // those set aside.
  std::vector<std::size_t> set_aside(std::size_t v, std::size_t r, bool several = false);
  // Node v made again: the cuts of the segment of rank r first, from its
  // steps in `arrivals` (v's log before); then the later segments' steps
  // decided down to the cells those cuts make; a cell whose arrivals are
  // those of an old subtree of `spare` not dirty takes that subtree whole,
  // one whose first cut is an old subtree's top is fitted to it cell by
  // cell (each such old subtree going to one of those cells, the pairs
  // sharing most arrivals first), one whose first cuts were made for an old
  // subtree that went elsewhere has the cells below them fitted to the
  // spares left, and the others are replayed. The spares left are
  // discarded.
  void remake(std::size_t v, std::size_t r, const std::vector<Arrival>& arrivals, std::vector<std::size_t> spare);
  // The subtree of v forgotten and its slots freed (v's too when `with_root`).
  void discard(std::size_t v, bool with_root);
  // The nodes made above cells taken whole (with cuts of the ranks remade),
  // whose logs may name a crossing gone.
  const std::vector<std::size_t>& tops() const { return tops_; }
  // What the remakes replaced: the old nodes forgotten, the contents moved,
  // the cells that took an old subtree whole (below each, every node but
  // those given a new cell, hooks.recelled, is as it was).
  Replay_ledger& ledger() { return ledger_; }

private:
  std::vector<std::pair<std::size_t, std::vector<Arrival>>> cells_below(std::size_t v, std::size_t r,
                                                                        const std::vector<Arrival>& arrivals,
                                                                        std::size_t to);
  // A cell below a new cut, with its arrivals; once its first segment's
  // cuts are made, that segment's rank and the end of its block; and the
  // old subtree with the same cut on top that it is fitted to, if any.
  struct Fitting {
    std::size_t cell;
    std::vector<Arrival> steps;
    std::optional<std::size_t> rank;
    std::size_t to = 0;
    std::optional<std::size_t> old;
  };
  // Fits the cells made below one node to the old subtrees of `spare`,
  // taking from it those used.
  void fit_cells(std::vector<std::pair<std::size_t, std::vector<Arrival>>> cells, std::vector<std::size_t>& spare);
  // Whether an old subtree of `spare` makes the cell whole (Lemma 5, or
  // 5' with walls renamed); if so it moves there.
  bool take_whole(std::size_t cell, const std::vector<Arrival>& steps, std::vector<std::size_t>& spare);
  // The cuts of the first segment that cuts the cell, when an old subtree
  // of `spare` has a cut of that segment on top.
  void first_cuts(Fitting& f, const std::vector<std::size_t>& spare);
  // Below a matched top the cells fitted in turn to the old subtree's below
  // its cuts of that rank; below first cuts with no old top left for them,
  // to the old subtrees `left` over here; a cell without first cuts replayed.
  void fit(const Fitting& f, std::vector<std::size_t>& left);
  // The old subtree of `spare` not dirty, with the cell's floor and roof,
  // whose log is `steps` once the walls of its cell that moved are named as
  // the new ones, and that hooks.renamed accepts; or none.
  std::vector<std::size_t>::iterator renamable(std::size_t cell, const std::vector<Arrival>& steps,
                                               std::vector<std::size_t>& spare);
  // The walk ends at o's moved walls named as cell's, in the logs along them.
  void rename_walls(std::size_t o, const Cell& now);
  // Node `from`'s cut, children and log move to slot `to`, which keeps its
  // parent and cell.
  void move_node(std::size_t from, std::size_t to);
  // Old node o's slot, its content moved or set aside, freed.
  void release(std::size_t o);
  // The cells below v made again from v's, down to those that stay.
  void refresh_cells(std::size_t v);

  Cylindrical_bsp& tree_;
  Build_log& log_;
  const Segment_scene& scene_;
  Bsp_builder<K>& builder_;
  std::set<std::size_t>& dirty_;
  Subtree_fit_hooks hooks_;
  std::vector<std::size_t> tops_;
  Replay_ledger ledger_;
};

}  // namespace kvd::segments
