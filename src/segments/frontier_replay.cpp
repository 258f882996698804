// The frontier replay of the kinetic segment BSP
// (kvd/segments/kinetic_segment_bsp.hpp; proofs/segment-local-update.md,
// "Frontier replay"): when the signs that changed at the topmost node u are
// those of one segment's steps, only those steps are decided again below u,
// down to the leaves of the tree before that segment, and only the subtrees
// there whose arrivals changed are replayed (with several segments at u or
// at failing nodes below it, each one's steps from the topmost of them,
// down to the leaves of the tree before the earliest of them: "Several
// segments at one instant"); and the frontier nodes of a flip
// (flip_frontiers).
#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/segments/reroute.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"

namespace kvd::segments {

namespace {

using Key = Segment_certificate_key;

// The keys the arrivals decide at the node, sorted, each once.
std::vector<Key> keys_of(const Bsp_node& node, const std::vector<Arrival>& arrivals) {
  std::vector<Key> keys;
  for (const Arrival& a : arrivals) decided_keys(node, a, keys);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

bool has(const std::vector<Key>& sorted, const Key& k) { return std::binary_search(sorted.begin(), sorted.end(), k); }

}  // namespace

template <class K>
std::optional<std::vector<typename Kinetic_segment_bsp<K>::Replay_root>> Kinetic_segment_bsp<K>::frontier_replay(std::size_t u,
                                                                                const std::vector<Failing>& failing,
                                                                                const std::vector<std::int32_t>& nodes) {
  const auto& rank = scene_.rank;
  const auto node = [&](std::size_t n) -> const Bsp_node& { return tree_.nodes[n]; };
  // The segments whose steps decided the failing keys at n, sorted (with
  // exact logs every failing key at n has a logged step deciding it; one
  // without is taken as a reason to replay u's subtree).
  const auto changing = [&](std::size_t n) -> std::optional<std::vector<std::uint32_t>> {
    std::set<Key> failing_here, seen;
    for (const auto& [key, at] : failing)
      if (std::find(at.begin(), at.end(), static_cast<std::int32_t>(n)) != at.end()) failing_here.insert(key);
    std::set<std::uint32_t> segments;
    std::vector<Key> keys;
    for (const Arrival& a : log_.at[n]) {
      keys.clear();
      decided_keys(node(n), a, keys);
      for (const Key& k : keys)
        if (failing_here.count(k)) {
          seen.insert(k);
          segments.insert(a.segment);
        }
    }
    if (segments.empty() || seen.size() != failing_here.size()) return std::nullopt;
    return std::vector<std::uint32_t>(segments.begin(), segments.end());
  };
  const std::optional<std::vector<std::uint32_t>> at_u = changing(u);
  if (!at_u) return std::nullopt;
  // u on the frontier of rank rf (a leaf of B_{rf-1}: its cut's segment
  // decides a failing key at it, say): it is made again as a frontier node
  // is, from its log, which no failing sign above it changed, keeping the
  // old subtrees below its cuts whose arrivals did not change. Below the
  // frontier, u's subtree is replayed.
  const auto remade = [&](std::size_t rf) -> std::optional<std::vector<Replay_root>> {
    const std::int32_t p = node(u).parent;
    if (p >= 0 && cut_rank(node(static_cast<std::size_t>(p)), rank) >= rf) return std::nullopt;
    return std::vector<Replay_root>{{u, rf}};
  };
  const auto at_u_has = [&](std::uint32_t x) { return std::binary_search(at_u->begin(), at_u->end(), x); };
  // The segments whose steps changed above the frontier, by rank, with the
  // nodes their steps are decided again from: u's segments from u (several
  // where a crossing passes a third segment's line, say), another (a
  // failure of its own at the same instant, in the crown) from its topmost
  // failing crown nodes. The frontier is the earliest one's: the
  // crown's cuts are older than every one of them, so each one's steps
  // there are decided against cuts that stay, and all are decided again
  // before any frontier node is replayed from its log.
  std::map<std::size_t, std::vector<std::size_t>> starts;
  for (const std::uint32_t x : *at_u) starts[rank[x]] = {u};
  std::size_t r = 0;
  bool several = false;
  const auto frontier = [&](std::size_t n) { return cut_rank(node(n), rank) >= r; };
  std::set<std::size_t> replayed;
  for (bool grew = true; grew;) {
    grew = false;
    r = starts.begin()->first;
    if (cut_rank(node(u), rank) >= r) return remade(r);
    replayed.clear();
    // The failing crown nodes of each segment not starting at u.
    std::map<std::size_t, std::vector<std::size_t>> crown;
    // At a failing node below u above the frontier, the steps of each
    // segment deciding a failing key there are decided again, from there or
    // from a start above. Below, the frontier node above it is replayed.
    // Every such segment sets the frontier first: two decide one key where
    // their walks' parts end at a wall of the node's cell and the key is the
    // wall's x order with the node's cut, and the cut's own segment, one of
    // them, puts the node on the frontier.
    for (const std::int32_t f : nodes) {
      std::size_t top = static_cast<std::size_t>(f);
      bool under = false;
      for (std::int32_t a = node(top).parent; a >= 0; a = node(static_cast<std::size_t>(a)).parent) {
        if (static_cast<std::size_t>(a) == u) {
          under = true;
          break;
        }
        if (frontier(static_cast<std::size_t>(a))) top = static_cast<std::size_t>(a);
      }
      if (!under) continue;
      if (frontier(top)) {
        replayed.insert(top);
        continue;
      }
      const std::optional<std::vector<std::uint32_t>> others = changing(top);
      if (!others) return std::nullopt;
      for (const std::uint32_t other : *others) {
        // A segment earlier than the frontier's lowers it: the pass is made again.
        if (starts.emplace(rank[other], std::vector<std::size_t>{}).second && rank[other] < r) grew = true;
        if (!at_u_has(other)) crown[rank[other]].push_back(top);
      }
    }
    if (grew) continue;
    // A segment whose failing nodes all fell below the frontier as it rose
    // (its own cuts) has its changes made by the frontier nodes' replays
    // alone; if it is the earliest, it still set the frontier.
    several = starts.size() > 1;
    std::erase_if(starts, [&](const auto& e) {
      return !at_u_has(scene_.priority_order[e.first]) && !crown.count(e.first);
    });
    for (auto& [ro, at] : crown) {
      const std::set<std::size_t> failing_here(at.begin(), at.end());
      for (const std::size_t n : at) {
        bool below = false;
        for (std::int32_t a = node(n).parent; a >= 0 && static_cast<std::size_t>(a) != u && !below;
             a = node(static_cast<std::size_t>(a)).parent)
          below = failing_here.count(static_cast<std::size_t>(a)) > 0;
        if (!below) starts[ro].push_back(n);
      }
    }
  }

  // Decided again from each start: the certificates there, above the
  // frontier, and above the start for crossings found anew, are recorded.
  // Above the frontier the cut stays; a key the segment's steps decided
  // there before and do not now goes, unless another step decides it. A
  // step decides a key at a node only through a point it carries (its
  // located point, or an end of its walk: decided_keys), so only the steps
  // carrying a point of a key that may go are read, not the whole log
  // (some 20,000 arrivals near the root of 12,800 segments).
  Bsp_builder<K> builder(pred_, now_, tree_, &log_);
  const Reroute_above above = [&](std::size_t n, const std::vector<Arrival>& was, const std::vector<Arrival>& now) {
    const std::vector<Key> new_keys = keys_of(node(n), now);
    std::vector<Key> may_go;
    for (const Key& k : keys_of(node(n), was))
      if (!has(new_keys, k)) may_go.push_back(k);
    if (may_go.empty()) return;
    // (Only an x order names a second point; only a walk has a second end.)
    std::vector<Site_point> points;
    for (const Key& k : may_go) {
      points.push_back(k.p);
      if (k.kind == Key::Kind::x_order) points.push_back(k.q);
    }
    std::sort(points.begin(), points.end());
    const auto carried = [&](const Site_point& x) { return std::binary_search(points.begin(), points.end(), x); };
    std::vector<Arrival> carrying;
    for (const Arrival& a : log_.at[n])
      if (carried(a.a) || (!locates(a) && carried(a.b))) carrying.push_back(a);
    const std::vector<Key> others = keys_of(node(n), carrying);
    for (const Key& k : may_go)
      if (!has(others, k)) unrecord(k, static_cast<std::int32_t>(n));
  };
  for (const auto& [rs, from] : starts)
    for (const std::size_t v : from) {
      const std::vector<std::size_t> moved = reroute_segment(builder, tree_, log_, rank, v, rs, r, above);
      replayed.insert(moved.begin(), moved.end());
    }
  // With one segment's steps changed, a frontier node is remade with that
  // segment's cuts first and the old subtrees kept where the later steps
  // did not change; with several, the earliest one's cuts first, and only
  // what lies below its old content is kept (Replay_root::several).
  std::vector<Replay_root> roots;
  for (const std::size_t n : replayed) {
    if (several) drop_unwalked_crossings(log_.at[n]);
    roots.push_back({n, r, several});
  }
  return roots;
}

// A flip changes only signs decided in the cells of the turning segment's
// cuts (Bsp_builder::walk). A topmost node that is the first cut of a
// turning segment on its path (one of its frontier nodes: a leaf of the tree
// before it), with no other failing key below it, is remade as the frontier
// replay remakes one: the segment's cuts again, and the later segments' old
// subtrees moved where their arrivals did not change (section 3.1.4).
// Another failure elsewhere in the batch does not matter: the remake reads
// only the node's log and the signs below it.
template <class K>
std::map<std::size_t, std::size_t> Kinetic_segment_bsp<K>::flip_frontiers(const std::vector<Failing>& failing,
                                                                          const std::vector<std::int32_t>& nodes) const {
  std::vector<Key> keys;
  for (const auto& f : failing) keys.push_back(f.first);
  const std::vector<std::size_t> turning = turning_segments(keys);
  if (turning.empty()) return {};
  const auto parent = [&](std::int32_t n) { return tree_.nodes[static_cast<std::size_t>(n)].parent; };
  // The topmost failing node on n's path.
  const auto topmost = [&](std::int32_t n) {
    std::int32_t top = n;
    for (std::int32_t a = parent(n); a >= 0; a = parent(a))
      if (std::binary_search(nodes.begin(), nodes.end(), a)) top = a;
    return static_cast<std::size_t>(top);
  };
  std::set<std::size_t> other;  // topmost nodes with another failing key below
  for (const Failing& f : failing) {
    if (!part_of_flip(f.first, turning))
      for (const std::int32_t n : f.second)
        if (n >= 0) other.insert(topmost(n));
  }
  std::map<std::size_t, std::size_t> out;
  for (const std::int32_t n : nodes) {
    const auto u = static_cast<std::size_t>(n);
    if (topmost(n) != u) continue;
    const Bsp_node& node = tree_.nodes[u];
    const std::size_t r = cut_rank(node, scene_.rank);
    if (other.count(u) || r == scene_.rank.size() ||
        !std::binary_search(turning.begin(), turning.end(), scene_.priority_order[r]))
      continue;
    if (node.parent >= 0 && cut_rank(tree_.nodes[static_cast<std::size_t>(node.parent)], scene_.rank) == r) continue;
    out.emplace(u, r);
  }
  return out;
}

#define KVD_INSTANTIATE_FRONTIER_REPLAY(K)                                                               \
  template std::optional<std::vector<Kinetic_segment_bsp<K>::Replay_root>> Kinetic_segment_bsp<K>::frontier_replay( \
      std::size_t, const std::vector<Kinetic_segment_bsp<K>::Failing>&, const std::vector<std::int32_t>&); \
  template std::map<std::size_t, std::size_t> Kinetic_segment_bsp<K>::flip_frontiers(                   \
      const std::vector<Kinetic_segment_bsp<K>::Failing>&, const std::vector<std::int32_t>&) const;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_FRONTIER_REPLAY)

}  // namespace kvd::segments
