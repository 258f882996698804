// A batch of the run on the paper's certificates whose failing certificates
// changed one x order, two walls crossing, updated by rerouting the later
// wall's segment
// (kvd/segments/aeg_kinetic_bsp.hpp, walls_crossed;
// proofs/segment-local-update.md, "Frontier replay").
#include <algorithm>
#include <optional>
#include <set>
#include <utility>

#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"

namespace kvd::segments {

template <class K>
std::vector<Replay_root> Aeg_kinetic_bsp<K>::walls_crossed(const std::vector<Entry>& entries) {
  // The signs of the failing certificates that changed, against those they
  // were made with: one key for all, the x order of two points.
  if (entries.empty()) return {};
  std::optional<Segment_certificate_key> changed;
  std::vector<std::size_t> starts;  // the node each certificate's path starts at
  for (const Entry& e : entries) {
    if (e.kind == Aeg_certificate_kind::flip) return {};
    const Certificate& c = held({e.kind, e.index});
    const Decided now = signs(c, e.index);
    if (now.size() != c.decided.size()) return {};
    for (std::size_t i = 0; i < now.size(); ++i) {
      if (now[i] == c.decided[i]) continue;
      if (now[i].first != c.decided[i].first || (changed && *changed != now[i].first)) return {};
      changed = now[i].first;
    }
    starts.push_back(e.kind == Aeg_certificate_kind::transient ? e.index : leaf_[e.index]);
  }
  if (!changed || changed->kind != Segment_certificate_key::Kind::x_order) return {};
  const std::vector<std::size_t>& rank = scene_.rank;
  Site_point later = changed->p, earlier = changed->q;
  if (point_rank(later, rank) < point_rank(earlier, rank)) std::swap(later, earlier);
  const std::size_t r = point_rank(later, rank);
  if (point_rank(earlier, rank) == r) return {};
  const auto parent = [&](std::size_t n) { return tree_.nodes[n].parent; };
  // The frontier node above each certificate's node (a transient cell, the
  // leaf beside an endpoint), and no tie at now of the later point with a
  // cut above it but the earlier point's: a change there may be another
  // event's.
  std::set<std::size_t> replayed;
  std::vector<std::set<std::size_t>> paths;
  for (const std::size_t cell : starts) {
    std::size_t frontier = cell;
    std::set<std::size_t>& path = paths.emplace_back();
    for (std::int32_t a = parent(cell); a >= 0; a = parent(static_cast<std::size_t>(a))) {
      const auto n = static_cast<std::size_t>(a);
      const Bsp_node& q = tree_.nodes[n];
      path.insert(n);
      if (cut_rank(q, rank) >= r) {
        frontier = n;
        continue;
      }
      if (!(point_cut(q) && q.point == earlier) && ties(q, later, false)) return {};
    }
    replayed.insert(frontier);
  }
  // The topmost nodes where the later segment's steps decide the x order of
  // the two points: cuts of the earlier point above the frontier, found down
  // the nodes whose log holds a step of that segment.
  const Segment_certificate_key& key = *changed;
  std::vector<std::size_t> tops, stack{0};
  std::vector<Segment_certificate_key> keys;
  while (!stack.empty()) {
    const std::size_t n = stack.back();
    stack.pop_back();
    const Bsp_node& q = tree_.nodes[n];
    const std::vector<Arrival>& log = log_.at[n];
    const auto [from, to] = rank_block(log, rank, r);
    if (cut_rank(q, rank) >= r || from == to) continue;
    if (point_cut(q) && q.point == earlier) {
      keys.clear();
      for (std::size_t i = from; i < to; ++i) decided_keys(q, log[i], keys);
      if (std::find(keys.begin(), keys.end(), key) != keys.end()) {
        tops.push_back(n);
        continue;
      }
    }
    for (const std::int32_t ch : q.child) stack.push_back(static_cast<std::size_t>(ch));
  }
  // Each certificate's node lies below one of them (a cell below its
  // earlier wall's cut, through which its later wall's point was located).
  for (const std::set<std::size_t>& path : paths)
    if (std::none_of(tops.begin(), tops.end(), [&](std::size_t u) { return path.count(u) > 0; })) return {};
  // Another segment's point reaching the earlier point's abscissa now (as
  // one with the later point's x for good does, in the degenerate family)
  // changes its own steps there, which no certificate of the set may say:
  // the later point's wall hides it from the earlier one's.
  std::set<Site_point> asked{later, earlier};
  for (const std::size_t u : tops)
    for (const Arrival& a : log_.at[u]) {
      if (a.segment == scene_.priority_order[r]) continue;
      keys.clear();
      decided_keys(tree_.nodes[u], a, keys);
      for (const Segment_certificate_key& k : keys) {
        const Site_point& z = k.p == earlier ? k.q : k.p;
        if (k.kind != Segment_certificate_key::Kind::x_order || !asked.insert(z).second) continue;
        if (pred_.compare_x(z, earlier, now_).rule != Segment_rule::value) return {};
      }
    }
  Bsp_builder<K> builder(pred_, now_, tree_, &log_);
  if (!validate_) builder.log_traces_only();
  for (const std::size_t u : tops) {
    const std::vector<std::size_t> moved = reroute_segment(builder, tree_, log_, rank, u, r, {});
    replayed.insert(moved.begin(), moved.end());
  }
  std::vector<Replay_root> out;
  for (const std::size_t n : replayed) out.push_back({n, r});
  return out;
}

template std::vector<Replay_root> Aeg_kinetic_bsp<Exact_kernel>::walls_crossed(const std::vector<Entry>&);

}  // namespace kvd::segments
