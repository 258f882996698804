// What a local update of the cylindrical BSP replaced, told as it goes by
// Subtree_fit: every old node it forgets (before its slot is freed or made
// again), every move of a node's content to another slot, and every cell
// that took an old subtree whole. From that it says whether a root's subtree
// changed and which crossings lost their cuts, at the cost of the nodes
// forgotten and made: comparing each root's subtree before and after, as
// the runs did, read the old subtrees kept whole too, so an update high in
// the tree cost that whole subtree however little changed.
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "kvd/detail/segments/bsp_builder.hpp"

namespace kvd::segments {

class Replay_ledger {
public:
  explicit Replay_ledger(const Cylindrical_bsp& tree) : tree_(tree) {}

  // Old node `slot`, its content as it was, is forgotten.
  void forgot(std::size_t slot);
  // The content of slot `from` moved to slot `to`.
  void moved(std::size_t from, std::size_t to);
  // Slot `top` took an old subtree whole: below it, every slot is as it was.
  void kept(std::size_t top) { kept_.insert(top); }
  const std::set<std::size_t>& kept() const { return kept_; }

  // With an audit, root v's subtree and its crossings are read before the
  // update too, and changed and gone throw std::logic_error where they
  // disagree with that reading (for validation runs). Call before v's
  // subtree is touched.
  void audit(std::size_t v);
  // Root v's subtree is read before the update, and changed and gone answer
  // from that reading, as the runs did before the ledger: for the
  // floating-point kernels, whose signs may contradict each other until a
  // repair, so that a subtree kept whole need not hold every crossing its
  // log locates. Call before v's subtree is touched.
  void read(std::size_t v) {
    audit(v);
    trust_reading_ = true;
  }

  // Whether v's subtree differs from v's subtree before the update
  // (Cylindrical_bsp::text). Every old node below v must have been
  // forgotten, moved or kept, or left alone.
  bool changed(std::size_t v) const;
  // The crossings with an intersection cut below `roots` before and none
  // below them now, sorted: those of the nodes forgotten that no node made
  // cuts, nor a subtree kept whole (its top's log locates every crossing
  // cut below it). `rank`: Segment_scene::rank.
  std::vector<Site_point> gone(const std::vector<std::size_t>& roots, const Build_log& log,
                               const std::vector<std::size_t>& rank) const;

private:
  // The old node whose content a slot holds now.
  std::size_t identity(std::size_t slot) const;
  // Old node `id` as it was.
  const Bsp_node& old_node(std::size_t id) const;
  // Whether old node `id`'s subtree as it was equals slot's now.
  bool same(std::size_t id, std::size_t slot) const;
  // The crossings below the roots read before and not now.
  std::vector<Site_point> read_gone(const std::vector<std::size_t>& roots) const;

  const Cylindrical_bsp& tree_;
  std::map<std::size_t, Bsp_node> forgotten_;    // by old node
  std::map<std::size_t, std::size_t> identity_;  // slot -> the old node whose content it holds, when moved there
  std::map<std::size_t, std::size_t> location_;  // old node -> the slot its content moved to
  std::set<std::size_t> kept_;
  struct Reading {
    std::string text;
    std::vector<Site_point> crossings;
  };
  std::map<std::size_t, Reading> audited_;
  bool trust_reading_ = false;
};

}  // namespace kvd::segments
