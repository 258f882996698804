// A batch of the run on the paper's certificates whose failing certificates
// changed only keys that one segment's steps decide, updated by rerouting
// that segment: two walls crossing (the later wall's segment), an endpoint
// passing through a segment (the later of the two); several such at one
// instant, each down to its own frontier when they lie apart, else all down
// to the frontier of the earliest (kvd/segments/aeg_kinetic_bsp.hpp,
// reroutes; proofs/segment-local-update.md, "Rerouting on the paper's set").
#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"

namespace kvd::segments {

namespace {

using Key = Segment_certificate_key;

// The rank of the latest segment a key names: in the construction only
// that segment's steps decide it (a step decides keys of its own segment's
// points against the cut of an earlier or the same insertion). A
// certificate's key that no step of it decides is looked for in vain, and
// the batch is replayed.
std::size_t latest(const Key& k, const std::vector<std::size_t>& rank) {
  std::size_t r = 0;
  for (const std::size_t s : named_segments(k)) r = std::max(r, rank[s]);
  return r;
}

// A key as the x order of two points, for keys whose signs change together
// (their polynomials differ by factors that keep their sign off a flip):
// the side of a point of line a to line s is the x order of the point and
// the crossing of a and s, and the vertical order of lines i and j at the
// abscissa of p is the x order of p and their crossing. (Of a crossing of
// a and b, line a is taken: both vanish when the three lines meet.)
Key normal(const Key& k) {
  switch (k.kind) {
    case Key::Kind::x_order: return k;
    case Key::Kind::order_at: return k.i == k.j ? k : x_order_key(k.p, Site_point::crossing(k.i, k.j));
    case Key::Kind::side: {
      const std::uint32_t a = k.p.kind == Site_point::Kind::endpoint ? k.p.a / 2 : (k.p.a != k.i ? k.p.a : k.p.b);
      return x_order_key(k.p, Site_point::crossing(a, k.i));
    }
  }
  return k;
}

// The keys one segment's steps changed (normal), and what the guards ask
// about them.
struct Change {
  std::set<Key> keys;
  std::set<Key> above;                    // of those, the ones decided above the frontier (all but x orders of its own points)
  std::set<Site_point> points;            // the keys' points, as asked and as normal
  std::set<std::size_t> segments;         // the segments of side and order_at keys as asked
  std::vector<std::size_t> tops, starts;  // the topmost nodes deciding a key; the failing certificates' nodes
  std::set<std::size_t> frontiers;        // the frontier nodes above the starts

  void add(const Key& k) {
    const Key n = normal(k);
    keys.insert(n);
    for (const Key* x : {&k, &n}) {
      points.insert(x->p);
      if (x->kind == Key::Kind::x_order) points.insert(x->q);
      else segments.insert(x->i);
      if (x->kind == Key::Kind::order_at) segments.insert(x->j);
    }
  }
};

}  // namespace

template <class K>
std::vector<Replay_root> Aeg_kinetic_bsp<K>::reroutes(const std::vector<Entry>& entries, std::vector<std::size_t>& asked,
                                                      const Reroute_check& proceed) {
  if (entries.empty()) return {};
  const std::vector<std::size_t>& rank = scene_.rank;
  // The signs of the failing certificates that changed, against those they
  // were made with, grouped by the segment whose steps decide them; a
  // certificate whose changes are several segments' starts each group.
  std::map<std::size_t, Change> changes;
  std::vector<std::size_t> unchanged;  // the nodes of certificates none of whose signs changed
  for (const Entry& e : entries) {
    if (e.kind == Aeg_certificate_kind::flip) return {};
    // A segment on its neighbour's line changes signs at every wall across
    // both, which no certificate holds (proofs/segment-certificates.md).
    if (e.kind == Aeg_certificate_kind::endpoint && !collinear(e.index).empty()) return {};
    const Certificate& c = held({e.kind, e.index});
    const Decided now = signs(c, e.index);
    if (now.size() != c.decided.size()) return {};
    std::set<std::size_t> by;  // the segments whose steps decide the changed keys
    for (std::size_t i = 0; i < now.size(); ++i) {
      if (now[i] == c.decided[i]) continue;
      const Key& k = now[i].first;
      if (k != c.decided[i].first) return {};
      const std::size_t r = latest(k, rank);
      by.insert(r);
      changes[r].add(k);
      // Only the x order of two of the segment's own points is decided by
      // its cuts alone, below the frontier.
      if (k.kind != Key::Kind::x_order || point_rank(k.p, rank) != r || point_rank(k.q, rank) != r)
        changes[r].above.insert(normal(k));
    }
    // A certificate whose changes are several segments' starts each of them.
    const std::size_t start = e.kind == Aeg_certificate_kind::transient ? e.index : leaf_[e.index];
    for (const std::size_t r : by) changes[r].starts.push_back(start);
    if (by.empty()) unchanged.push_back(start);
  }
  if (changes.empty() || (!unchanged.empty() && changes.size() > 1)) return {};
  changes.begin()->second.starts.insert(changes.begin()->second.starts.end(), unchanged.begin(), unchanged.end());
  const auto parent = [&](std::size_t n) { return tree_.nodes[n].parent; };
  std::vector<Key> keys;
  for (auto& group : changes) {
    // (Named, not bound: lambdas below capture them.)
    const std::size_t r = group.first;
    Change& change = group.second;
    const std::size_t s = scene_.priority_order[r];
    const auto feature = [&](const Bsp_node& q) {
      return q.kind == Cut_kind::edge ? change.segments.count(q.segment) > 0 : change.points.count(q.point) > 0;
    };
    // The topmost nodes, of a cut earlier than the segment's, where its
    // steps decide a changed key, found down the nodes whose log holds a
    // step of the segment, and every node below them where one is decided
    // (for the guard after the frontier's). Every changed key that names an
    // earlier cut must be decided on the way, at a top or below one; the x
    // order of two of the segment's own points is decided by its cuts below
    // the frontier. Above the tops none of the segment's other signs may
    // change now: no certificate tells, and the reroute does not decide
    // them again (below a top it does).
    std::set<Key> found;
    std::vector<std::size_t> deciding;  // every node where a changed key is decided
    std::vector<std::size_t> above;     // the nodes above the tops
    std::vector<std::size_t> ends;      // the tops, and the frontier nodes the segment reaches below no top
    // The keys of the segment's steps at node x (`range`, its block in x's
    // log) against x's cut, in `keys`.
    const auto own_keys = [&](std::size_t x, std::pair<std::size_t, std::size_t> range) -> const std::vector<Key>& {
      keys.clear();
      for (std::size_t i = range.first; i < range.second; ++i) decided_keys(tree_.nodes[x], log_.at[x][i], keys);
      return keys;
    };
    const auto block = [&](std::size_t x) { return rank_block(log_.at[x], rank, r); };
    std::vector<std::pair<std::size_t, bool>> stack{{0, false}};  // a node, and whether a top is above it
    while (!stack.empty()) {
      const auto [n, below] = stack.back();
      stack.pop_back();
      const Bsp_node& q = tree_.nodes[n];
      const auto steps = block(n);
      if (steps.first == steps.second) continue;
      if (cut_rank(q, rank) >= r) {
        if (!below) ends.push_back(n);
        continue;
      }
      const std::vector<Key>& here = own_keys(n, steps);
      bool top = false;
      for (const Key& k : here)
        if (const Key x = normal(k); change.keys.count(x) > 0) {
          if (change.above.count(x) > 0) found.insert(x);
          deciding.push_back(n);
          top = !below;
        }
      if (top) {
        change.tops.push_back(n);
        ends.push_back(n);
      } else if (!below) {
        above.push_back(n);
      }
      for (const std::int32_t ch : q.child) stack.emplace_back(static_cast<std::size_t>(ch), below || top);
    }
    if (found.size() != change.above.size()) return {};
    if (change.tops.empty()) return {};
    const auto unchanged_vanishes = [&](std::size_t n) {
      const std::vector<Key>& ks = own_keys(n, block(n));
      return std::any_of(ks.begin(), ks.end(), [&](const Key& k) { return !change.keys.count(normal(k)) && vanishes(k); });
    };
    for (const std::size_t u : change.tops)
      if (unchanged_vanishes(u)) return {};
    // The cuts above the ends lie beyond the sides of the ends' cells from
    // the ends' points: a sign of theirs that vanishes now makes one against
    // a side vanish (squeezed). Where that cannot tell, every node above is
    // asked.
    if (!squeezed(ends, r, change.keys))
      for (const std::size_t n : above)
        if (unchanged_vanishes(n)) return {};
    // The frontier node above each certificate's node (a transient cell, the
    // leaf beside an endpoint); and no tie at now of the segment's points
    // among the keys', or of the segment, with a cut on the path above the
    // frontier but the keys' own: a change there may be another event's.
    for (const std::size_t cell : change.starts) {
      // A start must lie in a leaf of the tree before the segment, at or
      // below its frontier (a cell of a cut no earlier than the segment's).
      if (cut_rank(tree_.nodes[cell], rank) < r) return {};
      std::size_t frontier = cell;
      // The points still asked: above the first cut of the keys' own on
      // the path, a point inside that node's cell meets no cut (inside).
      std::vector<Site_point> open(change.points.begin(), change.points.end());
      bool squeezed_points = false;
      for (std::int32_t a = parent(cell); a >= 0; a = parent(static_cast<std::size_t>(a))) {
        const auto n = static_cast<std::size_t>(a);
        const Bsp_node& q = tree_.nodes[n];
        if (cut_rank(q, rank) >= r) {
          frontier = n;
          continue;
        }
        if (feature(q)) {
          if (!squeezed_points) {
            squeezed_points = true;
            counting(phases_.ties, [&] { std::erase_if(open, [&](const Site_point& z) { return inside(z, n); }); });
          }
          continue;
        }
        for (const Site_point& z : open)
          if (ties(q, z, false)) return {};
        if (point_cut(q) && tied(pred_.side(q.point, s, now_), false)) return {};
      }
      change.frontiers.insert(frontier);
    }
    // Another segment's step, at any node where a changed key is decided,
    // whose sign vanishes now (a point at a changed point's abscissa or on a
    // changed line for good, hidden behind a wall, as in the degenerate
    // family and the small-integer scenes) changes unseen by any
    // certificate of the set.
    // (Its signs are counted apart from the other guards': Batch::phases;
    // abscissa_clear counts its own, the log's are moved there below.)
    // In the walk's order, the tree's (a node is listed once per key, in a
    // row), not the slots': the guard stops at the first sign that vanishes.
    deciding.erase(std::unique(deciding.begin(), deciding.end()), deciding.end());
    const long own = phases_.own_guard;
    const bool other_vanishes = [&] {
      for (const std::size_t u : deciding) {
        if (point_cut(tree_.nodes[u]) && abscissa_clear(u, change.keys)) continue;
        for (const Arrival& a : log_.at[u]) {
          if (a.segment == s) continue;
          keys.clear();
          decided_keys(tree_.nodes[u], a, keys);
          for (const Key& k : keys)
            if (!change.keys.count(normal(k)) && vanishes(k)) return true;
        }
      }
      return false;
    }();
    phases_.other_guard += phases_.own_guard - own;
    phases_.own_guard = own;
    if (other_vanishes) return {};
  }
  // Changes of different segments at one instant whose tops and frontier
  // nodes lie apart are rerouted each down to its own frontier (what a
  // reroute changes lies below its tops).
  bool nested = false;
  for (auto c = changes.begin(); c != changes.end() && !nested; ++c) {
    const auto& [r, change] = *c;
    std::vector<std::size_t> region(change.tops.begin(), change.tops.end());
    region.insert(region.end(), change.frontiers.begin(), change.frontiers.end());
    for (const std::size_t v : region)
      for (std::int32_t a = static_cast<std::int32_t>(v); a >= 0 && !nested; a = parent(static_cast<std::size_t>(a)))
        for (const auto& [r2, other] : changes)
          if (r2 != r && (other.frontiers.count(static_cast<std::size_t>(a)) > 0 ||
                          std::count(other.tops.begin(), other.tops.end(), static_cast<std::size_t>(a)) > 0))
            nested = true;
  }
  if (proceed) {
    std::vector<std::size_t> region;
    for (const auto& [r, change] : changes) {
      region.insert(region.end(), change.tops.begin(), change.tops.end());
      region.insert(region.end(), change.frontiers.begin(), change.frontiers.end());
    }
    if (!proceed(region, nested)) return {};
  }
  Bsp_builder<K> builder(pred_, now_, tree_, &log_);
  if (!validate_) builder.log_traces_only();
  std::vector<Replay_root> out;
  if (!nested) {
    for (auto& [r, change] : changes) {
      for (const std::size_t u : change.tops) {
        const std::vector<std::size_t> moved = reroute_segment(builder, tree_, log_, rank, u, r, r, {});
        change.frontiers.insert(moved.begin(), moved.end());
      }
      for (const std::size_t n : change.frontiers) out.push_back({n, r});
    }
    return out;
  }
  // Otherwise every segment's steps are decided again from its tops above
  // the frontier of the earliest segment, down to it, and the frontier
  // nodes above the changes are made again, that segment's cuts first
  // (proofs/segment-local-update.md, "Several segments at one instant").
  // The guards above asked each segment's signs down to its own frontier,
  // which lies at or below that one.
  const std::size_t first = changes.begin()->first;
  const auto frontier_of = [&](std::size_t n) {  // the topmost node of rank `first` or later on n's path
    std::size_t f = n;
    for (std::int32_t a = parent(n); a >= 0 && cut_rank(tree_.nodes[static_cast<std::size_t>(a)], rank) >= first;
         a = parent(static_cast<std::size_t>(a)))
      f = static_cast<std::size_t>(a);
    return f;
  };
  std::set<std::size_t> frontiers;
  for (const auto& group : changes) {
    // (Named, not bound: the lambda below captures them.)
    const std::size_t r = group.first;
    const Change& change = group.second;
    for (const std::size_t cell : change.starts) frontiers.insert(frontier_of(cell));
    // A node below the shared frontier and above the segment's own where
    // its steps decide a changed key, or ask a sign that vanishes now: its
    // frontier node is replayed (the segment's reroute, stopped above, does
    // not decide them again). Its tops there are such nodes.
    std::vector<std::size_t> stack(change.tops.begin(), change.tops.end());
    while (!stack.empty()) {
      const std::size_t n = stack.back();
      stack.pop_back();
      const Bsp_node& q = tree_.nodes[n];
      if (cut_rank(q, rank) >= r) continue;
      const std::vector<Arrival>& log = log_.at[n];
      const auto [from, to] = rank_block(log, rank, r);
      if (from == to) continue;
      if (cut_rank(q, rank) >= first) {
        keys.clear();
        for (std::size_t i = from; i < to; ++i) decided_keys(q, log[i], keys);
        // Every such node is asked, not only the topmost on a path: the
        // remake keeps old subtrees below one.
        if (std::any_of(keys.begin(), keys.end(),
                        [&](const Key& k) { return change.keys.count(normal(k)) > 0 || vanishes(k); })) {
          frontiers.insert(frontier_of(n));
          asked.push_back(n);
        }
      }
      for (const std::int32_t ch : q.child) stack.push_back(static_cast<std::size_t>(ch));
    }
    for (const std::size_t u : change.tops)
      if (cut_rank(tree_.nodes[u], rank) < first) {
        const std::vector<std::size_t> moved = reroute_segment(builder, tree_, log_, rank, u, r, first, {});
        frontiers.insert(moved.begin(), moved.end());
      }
  }
  for (const std::size_t n : frontiers) {
    drop_unwalked_crossings(log_.at[n]);
    out.push_back({n, first, true});
  }
  return out;
}

template <class K>
bool Aeg_kinetic_bsp<K>::abscissa_clear(std::size_t u, const std::set<Key>& changed) const {
  const Bsp_node& n = tree_.nodes[u];
  const Site_point& y = n.point;
  return counting(phases_.other_guard, [&] {
    // Whether w's x order with y, s, is a change other than the keys'.
    const auto meets = [&](const Site_point& w, const Segment_sign& s) {
      return s.at_root && !changed.count(x_order_key(w, y));
    };
    for (const std::optional<Site_point>& wall : {n.cell.left, n.cell.right})
      if (wall && *wall != y && meets(*wall, pred_.compare_x(*wall, y, now_))) return false;
    // Down the cells whose closed x-range holds y's abscissa now: a point
    // cut decided by its value keeps it on one side (the points below the
    // other lie strictly beyond), any other sign keeps both.
    std::vector<std::size_t> stack{child(n, 0), child(n, 1)};
    while (!stack.empty()) {
      const Bsp_node& q = tree_.nodes[stack.back()];
      stack.pop_back();
      if (q.kind == Cut_kind::leaf) continue;
      if (point_cut(q) && q.point != y) {
        const Segment_sign s = pred_.compare_x(q.point, y, now_);
        if (meets(q.point, s)) return false;
        if (s.rule == Segment_rule::value) {
          stack.push_back(child(q, s.sign > 0 ? 0 : 1));
          continue;
        }
      }
      stack.push_back(child(q, 0));
      stack.push_back(child(q, 1));
    }
    return true;
  });
}

template <class K>
bool Aeg_kinetic_bsp<K>::squeezed(const std::vector<std::size_t>& ends, std::size_t r,
                                  const std::set<Key>& changed) const {
  // A tie for good against a side (decided by the perturbation) may hide
  // one above whose leading ε-coefficient vanishes now.
  const auto settled = [&](const Key& k) {
    return !changed.count(normal(k)) && counting(phases_.own_guard, [&] {
      const Segment_sign sign = pred_.sign_of(k, now_);
      return !sign.at_root && sign.rule != Segment_rule::perturbation;
    });
  };
  // The floor (side 0) or roof (1) of the cell of segment j's cut above x.
  const auto beyond = [&](std::size_t x, std::uint32_t j, int side) -> std::optional<std::uint32_t> {
    for (std::int32_t a = tree_.nodes[x].parent; a >= 0; a = tree_.nodes[static_cast<std::size_t>(a)].parent)
      if (const Bsp_node& n = tree_.nodes[static_cast<std::size_t>(a)]; n.kind == Cut_kind::edge && n.segment == j)
        return side ? n.cell.roof : n.cell.floor;
    return std::nullopt;
  };
  std::vector<Key> keys;
  for (const std::size_t x : ends) {
    const Cell& cell = tree_.nodes[x].cell;
    const auto [from, to] = rank_block(log_.at[x], scene_.rank, r);
    for (const Bsp_node& side : cell_sides(cell)) {
      keys.clear();
      for (std::size_t i = from; i < to; ++i) decided_keys(side, log_.at[x][i], keys);
      if (!std::all_of(keys.begin(), keys.end(), settled)) return false;
    }
    // A point on the floor (a crossing with it) has no key against it; an
    // edge cut above meeting it there meets that segment there, so the
    // floor of the segment's own cut.
    for (std::size_t i = from; i < to; ++i) {
      const Arrival& a = log_.at[x][i];
      for (const Site_point& q : {a.a, a.b}) {
        for (const int s : {0, 1})
          if (const std::optional<std::uint32_t> j = s ? cell.roof : cell.floor; j && q.on(*j))
            if (const std::optional<std::uint32_t> f = beyond(x, *j, s);
                f && !q.on(*f) && !settled({Key::Kind::side, q, {}, *f, 0}))
              return false;
        if (locates(a)) break;
      }
    }
  }
  return true;
}

template std::vector<Replay_root> Aeg_kinetic_bsp<Exact_kernel>::reroutes(const std::vector<Entry>&,
                                                                         std::vector<std::size_t>&,
                                                                         const Reroute_check&);
template bool Aeg_kinetic_bsp<Exact_kernel>::squeezed(const std::vector<std::size_t>&, std::size_t,
                                                      const std::set<Key>&) const;
template bool Aeg_kinetic_bsp<Exact_kernel>::abscissa_clear(std::size_t, const std::set<Key>&) const;

}  // namespace kvd::segments
