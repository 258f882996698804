// The frontier nodes made again with their old subtrees kept where their
// arrivals did not change (kvd/segments/kinetic_segment_bsp.hpp,
// remake_frontier_node; proofs/segment-local-update.md, "Cells kept").
#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"

namespace kvd::segments {

template <class K>
std::vector<std::size_t> Kinetic_segment_bsp<K>::set_aside(std::size_t v, std::size_t r, std::set<std::size_t>& dirty) {
  const auto& rank = scene_.rank;
  std::vector<std::size_t> spare, stack{v};
  while (!stack.empty()) {
    const std::size_t n = stack.back();
    stack.pop_back();
    const Bsp_node& node = tree_.nodes[n];
    if (cut_rank(node, rank) > r) {
      spare.push_back(n);
      continue;
    }
    for (const std::int32_t c : node.child) stack.push_back(static_cast<std::size_t>(c));
    forget(n);
    if (n != v) log_.free.push_back(n);
  }
  if (!spare.empty() && spare.front() == v) {
    // v keeps its slot for the segment's cuts: what it held moves aside.
    Bsp_node aside;
    aside.cell = tree_.nodes[v].cell;
    const std::size_t m = place_node(tree_, &log_, aside);
    move_node(v, m);
    if (dirty.count(v)) dirty.insert(m);
    // The segment had no step at v (it would have cut v): its new ones go.
    auto& log = log_.at[m];
    const auto [from, to] = rank_block(log, scene_.rank, r);
    log.erase(log.begin() + static_cast<std::ptrdiff_t>(from), log.begin() + static_cast<std::ptrdiff_t>(to));
    spare.front() = m;
  }
  return spare;
}

template <class K>
void Kinetic_segment_bsp<K>::remake_frontier_node(Bsp_builder<K>& builder, std::size_t v, std::size_t r,
                                                  const std::vector<Arrival>& arrivals, std::vector<std::size_t>& spare,
                                                  std::set<std::size_t>& dirty, std::vector<std::size_t>& tops) {
  const auto [from, to] = rank_block(arrivals, scene_.rank, r);
  builder.replay(v, std::vector<Arrival>(arrivals.begin() + static_cast<std::ptrdiff_t>(from),
                                         arrivals.begin() + static_cast<std::ptrdiff_t>(to)));
  for (auto& [cell, steps] : cells_below(builder, v, r, arrivals, to, tops)) fit(builder, cell, steps, spare, dirty, tops);
}

template <class K>
std::vector<std::pair<std::size_t, std::vector<Arrival>>> Kinetic_segment_bsp<K>::cells_below(
    Bsp_builder<K>& builder, std::size_t v, std::size_t r, const std::vector<Arrival>& arrivals, std::size_t to,
    std::vector<std::size_t>& tops) {
  // The later segments' steps; their crossings with the segment of rank r
  // are found again at its new cuts, or are gone.
  const auto s = static_cast<std::uint32_t>(scene_.priority_order[r]);
  std::vector<Arrival> later;
  for (std::size_t k = to; k < arrivals.size(); ++k)
    if (arrivals[k].kind != Arrival::Kind::intersection || other_segment(arrivals[k]) != s) later.push_back(arrivals[k]);
  log_.at[v].insert(log_.at[v].end(), later.begin(), later.end());
  std::map<std::size_t, std::vector<Arrival>> at;
  builder.reroute(v, later, r + 1, at);
  std::vector<std::pair<std::size_t, std::vector<Arrival>>> cells;
  tops.push_back(v);
  if (tree_.nodes[v].kind == Cut_kind::leaf) cells.emplace_back(v, log_.at[v]);
  for (auto& [n, got] : at) {
    if (tree_.nodes[n].kind == Cut_kind::leaf) {
      cells.emplace_back(n, std::move(got));
    } else {
      tops.push_back(n);
      auto& log = log_.at[n];
      log.insert(log.end(), got.begin(), got.end());
    }
  }
  return cells;
}

template <class K>
void Kinetic_segment_bsp<K>::fit(Bsp_builder<K>& builder, std::size_t cell, const std::vector<Arrival>& steps,
                                 std::vector<std::size_t>& spare, std::set<std::size_t>& dirty,
                                 std::vector<std::size_t>& tops) {
  const auto taken = [&](std::vector<std::size_t>::iterator o) {
    tree_.nodes[*o] = Bsp_node{};
    log_.free.push_back(*o);
    spare.erase(o);
  };
  // The arrivals of an old subtree that holds no failing node: it is the
  // subtree they make.
  const auto same = std::find_if(spare.begin(), spare.end(),
                                 [&](std::size_t o) { return !dirty.count(o) && log_.at[o] == steps; });
  if (same != spare.end()) {
    move_node(*same, cell);
    refresh_cells(cell);
    return taken(same);
  }
  // Otherwise the cuts of the first segment that cuts the cell; when an old
  // subtree has the same cut on top, its cells are fitted to the new ones
  // in turn (the cell's new wall changes only the arrivals that meet it).
  const auto first = std::find_if(steps.begin(), steps.end(),
                                  [](const Arrival& a) { return a.kind != Arrival::Kind::crossings; });
  if (first != steps.end()) {
    const std::size_t r = scene_.rank[first->segment];
    const auto [from, to] = rank_block(steps, scene_.rank, r);
    // A crossing walk that reaches a cell is followed there by its segment's
    // intersection or edge arrivals, in its block: no earlier block can hold
    // only walks. Anything else is a log out of step with the tree.
    if (from != 0) throw Bsp_contradiction("cylindrical BSP: a cell's arrivals precede the block of its first cut");
    builder.replay(cell, std::vector<Arrival>(steps.begin() + static_cast<std::ptrdiff_t>(from),
                                              steps.begin() + static_cast<std::ptrdiff_t>(to)));
    const Bsp_node& made = tree_.nodes[cell];
    const auto old = std::find_if(spare.begin(), spare.end(), [&](std::size_t o) {
      const Bsp_node& n = tree_.nodes[o];
      return n.kind == made.kind && (made.kind == Cut_kind::edge ? n.segment == made.segment : n.point == made.point);
    });
    if (old != spare.end()) {
      std::vector<std::size_t> below = set_aside(*old, r, dirty);
      taken(old);
      for (auto& [c, got] : cells_below(builder, cell, r, steps, to, tops)) fit(builder, c, got, below, dirty, tops);
      for (const std::size_t o : below) discard(o, true);
      return;
    }
    discard(cell, false);
  }
  builder.replay(cell, steps);
}

template <class K>
void Kinetic_segment_bsp<K>::move_node(std::size_t from, std::size_t to) {
  Bsp_node& d = tree_.nodes[to];
  const Bsp_node& f = tree_.nodes[from];
  d.kind = f.kind;
  d.point = f.point;
  d.segment = f.segment;
  d.child[0] = f.child[0];
  d.child[1] = f.child[1];
  if (d.kind != Cut_kind::leaf)
    for (const std::int32_t c : d.child) tree_.nodes[static_cast<std::size_t>(c)].parent = static_cast<std::int32_t>(to);
  log_.at[to] = std::move(log_.at[from]);
  log_.at[from].clear();
  if (from < node_keys_.size()) {
    if (node_keys_.size() <= to) node_keys_.resize(to + 1);
    const auto was = static_cast<std::int32_t>(from), is = static_cast<std::int32_t>(to);
    // A node's list may name a key dropped since through by_crossing_: it
    // is in force no more, or no more at `from`, and nothing names it there.
    for (const Segment_certificate_key& key : node_keys_[from]) {
      if (const auto it = certs_.find(key); it != certs_.end())
        std::replace(it->second.nodes.begin(), it->second.nodes.end(), was, is);
      for (const Site_point& x : {key.p, key.q})
        if (const auto at = by_crossing_.find(x); at != by_crossing_.end())
          std::replace(at->second.begin(), at->second.end(), std::pair{key, was}, std::pair{key, is});
    }
    node_keys_[to] = std::move(node_keys_[from]);
    node_keys_[from].clear();
  }
}

template <class K>
void Kinetic_segment_bsp<K>::refresh_cells(std::size_t v) {
  std::vector<std::size_t> stack{v};
  while (!stack.empty()) {
    const Bsp_node& node = tree_.nodes[stack.back()];
    stack.pop_back();
    if (node.kind == Cut_kind::leaf) continue;
    for (const std::size_t side : {0, 1}) {
      Cell c = node.cell;
      if (node.kind == Cut_kind::edge) (side ? c.floor : c.roof) = node.segment;
      else (side ? c.left : c.right) = node.point;
      Bsp_node& child = tree_.nodes[static_cast<std::size_t>(node.child[side])];
      if (child.cell == c) continue;
      child.cell = c;
      stack.push_back(static_cast<std::size_t>(node.child[side]));
    }
  }
}

template <class K>
void Kinetic_segment_bsp<K>::discard(std::size_t v, bool with_root) {
  for (const std::size_t n : tree_.preorder(v)) {
    forget(n);
    if (n != v || with_root) log_.free.push_back(n);
  }
}

#define KVD_INSTANTIATE_FRONTIER_CELLS(K)                                                                    \
  template std::vector<std::size_t> Kinetic_segment_bsp<K>::set_aside(std::size_t, std::size_t,                  \
                                                                      std::set<std::size_t>&);                   \
  template void Kinetic_segment_bsp<K>::remake_frontier_node(Bsp_builder<K>&, std::size_t, std::size_t,          \
                                                             const std::vector<Arrival>&, std::vector<std::size_t>&, \
                                                             std::set<std::size_t>&, std::vector<std::size_t>&); \
  template std::vector<std::pair<std::size_t, std::vector<Arrival>>> Kinetic_segment_bsp<K>::cells_below(       \
      Bsp_builder<K>&, std::size_t, std::size_t, const std::vector<Arrival>&, std::size_t,                        \
      std::vector<std::size_t>&);                                                                                 \
  template void Kinetic_segment_bsp<K>::fit(Bsp_builder<K>&, std::size_t, const std::vector<Arrival>&,          \
                                            std::vector<std::size_t>&, std::set<std::size_t>&,                  \
                                            std::vector<std::size_t>&);                                          \
  template void Kinetic_segment_bsp<K>::move_node(std::size_t, std::size_t);                                   \
  template void Kinetic_segment_bsp<K>::refresh_cells(std::size_t);                                            \
  template void Kinetic_segment_bsp<K>::discard(std::size_t, bool);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_FRONTIER_CELLS)

}  // namespace kvd::segments
