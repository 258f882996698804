#include "kvd/detail/tree/tree_links.hpp"

#include "kvd/detail/tree/slot_room.hpp"

#include <cstddef>

namespace kvd::tree {

namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

}  // namespace

void Tree_links::reset(const Kvd_tree& t) {
  room_for(parent_, t.nodes.size());
  room_for(released_, t.nodes.size());
  room_for(indexed_, t.nodes.size());
  room_for(cut_, t.nodes.size());
  parent_.assign(t.nodes.size(), -1);
  released_.assign(t.nodes.size(), 0);
  indexed_.assign(t.nodes.size(), 0);
  cut_.assign(t.nodes.size(), {});
  sites_.clear();
  free_ = t.free_nodes;
  for (int f : free_) released_[at(f)] = 1;
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    if (released_[i]) continue;
    for (int c : {t.nodes[i].left, t.nodes[i].right})
      if (c >= 0) parent_[at(c)] = static_cast<int>(i);
    index(t, static_cast<int>(i));
  }
}

void Tree_links::update(const Kvd_tree& t, const std::vector<int>& changed) {
  const std::size_t size = t.nodes.size();
  // Slots past the end were released and dropped.
  for (std::size_t i = size; i < indexed_.size(); ++i) unindex(static_cast<int>(i));
  parent_.resize(size, -1);
  indexed_.resize(size, 0);
  cut_.resize(size);
  released_.resize(size, 0);
  for (int f : free_)
    if (at(f) < size) released_[at(f)] = 0;
  free_ = t.free_nodes;
  for (int f : free_) released_[at(f)] = 1;
  // A node whose parent changed hangs under a relinked or new node: the
  // changed nodes give every new parent link.
  for (int n : changed) {
    if (at(n) >= size) continue;
    unindex(n);
    if (released_[at(n)]) continue;
    index(t, n);
    for (int c : {t.nodes[at(n)].left, t.nodes[at(n)].right})
      if (c >= 0) parent_[at(c)] = n;
  }
  if (t.root >= 0) parent_[at(t.root)] = -1;
}

bool Tree_links::live(int n) const { return n >= 0 && at(n) < released_.size() && !released_[at(n)]; }

const std::set<int>& Tree_links::holding(const Symbolic_plane& site) const {
  static const std::set<int> none;
  const auto it = sites_.find(site);
  return it == sites_.end() ? none : it->second;
}

void Tree_links::mark_path(int n, Slot_marks& marks) const {
  for (int i = n; i >= 0 && marks.set(at(i)); i = parent_[at(i)]) {
  }
}

void Tree_links::index(const Kvd_tree& t, int n) {
  cut_[at(n)] = t.nodes[at(n)].cut;
  indexed_[at(n)] = 1;
  sites_[cut_[at(n)]].insert(n);
}

void Tree_links::unindex(int n) {
  if (!indexed_[at(n)]) return;
  indexed_[at(n)] = 0;
  const auto it = sites_.find(cut_[at(n)]);
  it->second.erase(n);
  if (it->second.empty()) sites_.erase(it);
}

}  // namespace kvd::tree
