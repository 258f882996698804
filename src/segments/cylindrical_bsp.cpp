// The construction of the cylindrical BSP (seed 003, section 2.1), and its
// replay in one subtree (kvd/detail/segments/bsp_builder.hpp).
#include "kvd/segments/cylindrical_bsp.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <stdexcept>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/segments/bsp_builder.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

template <class K>
Bsp_builder<K>::Bsp_builder(const Segment_predicates<K>& pred, const Time& t, Cylindrical_bsp& bsp, Build_log* log)
    : p_(pred), t_(t), b_(bsp), log_(log) {}

template <class K>
void Bsp_builder<K>::start() {
  b_.nodes.assign(1, Bsp_node{});
  if (log_) *log_ = Build_log{{{}}, {}};
  added_ = 1;
}

template <class K>
void Bsp_builder<K>::insert(std::uint32_t i) {
  for (const std::size_t e : {2 * std::size_t(i), 2 * std::size_t(i) + 1}) {
    const Site_point q = Site_point::endpoint(e);
    split(locate(0, {Arrival::Kind::vertex, i, q, {}, 0}), Cut_kind::vertex, q);
  }
  // The paper's flip certificate: the x order of the segment's endpoints.
  // The construction does not branch on it (the walks go from endpoint 0 to
  // endpoint 1, whichever is left), so it is decided at no node.
  const Site_point from = Site_point::endpoint(2 * std::size_t(i)), to = Site_point::endpoint(2 * std::size_t(i) + 1);
  p_.at_node(-1);
  p_.compare_x(from, to, t_);
  insert_crossings(0, i, from, to, {});
  walk(0, {Arrival::Kind::edges, i, from, to, 0}, [&](std::size_t leaf) { split_edge(leaf, i); }, [](std::uint32_t) {});
}

template <class K>
void Bsp_builder<K>::replay(std::size_t v, const std::vector<Arrival>& arrivals) {
  Bsp_node& node = b_.nodes[v];
  node.kind = Cut_kind::leaf;
  node.child[0] = node.child[1] = -1;
  if (log_) log_->at[v].clear();
  steps(v, arrivals);
}

template <class K>
void Bsp_builder<K>::reroute(std::size_t u, const std::vector<Arrival>& arrivals, std::size_t rank,
                             std::map<std::size_t, std::vector<Arrival>>& at) {
  frontier_ = rank;
  collect_ = &at;
  origin_ = u;
  steps(u, arrivals);
  collect_ = nullptr;
}

// Each arrival continues from v as it did from the root. A segment whose
// crossing walk reaches v finds again the crossings strictly inside v's part
// of it; a crossing at an end of that part was found above v, and its logged
// intersection cut is kept. Both go in the order of the whole construction:
// by the other segment's priority.
template <class K>
void Bsp_builder<K>::steps(std::size_t v, const std::vector<Arrival>& arrivals) {
  std::set<std::uint32_t> walked;
  for (std::size_t k = 0; k < arrivals.size(); ++k) {
    const Arrival& a = arrivals[k];
    switch (a.kind) {
      case Arrival::Kind::vertex: split(locate(v, a), Cut_kind::vertex, a.a); break;
      case Arrival::Kind::crossings: {
        walked.insert(a.segment);
        std::vector<Arrival> kept;
        // (The segment's intersection arrivals follow its crossing walk in
        // its block: arrivals are in build order.)
        for (std::size_t l = k + 1; l < arrivals.size() && arrivals[l].segment == a.segment; ++l) {
          const Arrival& c = arrivals[l];
          if (c.kind != Arrival::Kind::intersection) continue;
          // Found above v (at an end of v's part); or, while rerouting, to
          // be found below the frontier, where the walk does not go.
          if (c.a == a.a || c.a == a.b || (collect_ && p_.scene().rank[other_segment(c)] >= frontier_)) kept.push_back(c);
        }
        insert_crossings(v, a.segment, a.a, a.b, kept);
        break;
      }
      case Arrival::Kind::intersection:
        if (!walked.count(a.segment)) split(locate(v, a), Cut_kind::intersection, a.a);
        break;
      case Arrival::Kind::edges:
        walk(v, a, [&](std::size_t leaf) { split_edge(leaf, a.segment); }, [](std::uint32_t) {});
        break;
    }
  }
}

// Whether a step ends at n: at a leaf, and while rerouting at the frontier.
template <class K>
bool Bsp_builder<K>::stops(std::size_t n) const {
  const Bsp_node& node = b_.nodes[n];
  return node.kind == Cut_kind::leaf || (collect_ && cut_rank(node, p_.scene().rank) >= frontier_);
}

template <class K>
std::size_t Bsp_builder<K>::add_leaf(const Cell& c, std::size_t parent) {
  Bsp_node leaf;
  leaf.cell = c;
  leaf.parent = static_cast<std::int32_t>(parent);
  ++added_;
  return place_node(b_, log_, leaf);
}

std::size_t place_node(Cylindrical_bsp& bsp, Build_log* log, const Bsp_node& node) {
  if (log && !log->free.empty()) {
    const std::size_t n = log->free.back();
    log->free.pop_back();
    bsp.nodes[n] = node;
    // Released, not cleared: a slot that held a big log near the root and
    // comes back as a leaf would keep its capacity for the rest of the run.
    log->at[n] = std::vector<Arrival>();
    return n;
  }
  bsp.nodes.push_back(node);
  if (log) log->at.emplace_back();
  return bsp.nodes.size() - 1;
}

template <class K>
void Bsp_builder<K>::split(std::size_t n, Cut_kind kind, const Site_point& q) {
  if (collect_) return;  // rerouting: the frontier's replay splits
  b_.nodes[n].kind = kind;
  b_.nodes[n].point = q;
  add_children(n);
}

template <class K>
void Bsp_builder<K>::split_edge(std::size_t n, std::uint32_t s) {
  if (collect_) return;
  b_.nodes[n].kind = Cut_kind::edge;
  b_.nodes[n].segment = s;
  add_children(n);
}

template <class K>
void Bsp_builder<K>::add_children(std::size_t n) {
  // add_leaf may move the nodes: no reference is held across it.
  const std::size_t l = add_leaf(child_cell(b_.nodes[n].cell, b_.nodes[n], 0), n);
  const std::size_t r = add_leaf(child_cell(b_.nodes[n].cell, b_.nodes[n], 1), n);
  b_.nodes[n].child[0] = static_cast<std::int32_t>(l);
  b_.nodes[n].child[1] = static_cast<std::int32_t>(r);
}

template <class K>
void Bsp_builder<K>::arrive(std::size_t n, const Arrival& a) {
  if (collect_) {
    if (n != origin_) (*collect_)[n].push_back(a);
    // The origin's arrivals come from above and stay, but a crossing found
    // anew below it is located through it, as from the root.
    else if (a.kind == Arrival::Kind::intersection && log_) log_in_order(log_->at[n], a, p_.scene().rank);
  } else if (log_) {
    log_->at[n].push_back(a);
  }
  p_.at_node(static_cast<std::int32_t>(n));
}

// The leaf whose cell holds a.a; where a.a lies on an edge cut by
// construction (a crossing on the earlier segment's fragment), the leaf just
// above it (a.dir = +1) or just below it (a.dir = -1).
template <class K>
std::size_t Bsp_builder<K>::locate(std::size_t from, const Arrival& a) {
  std::size_t n = from;
  for (;;) {
    arrive(n, a);
    if (stops(n)) return n;
    n = step(n, a);
  }
}

// The child of cut node n that holds a.a (see locate).
template <class K>
std::size_t Bsp_builder<K>::step(std::size_t n, const Arrival& a) const {
  const Bsp_node& node = b_.nodes[n];
  int s;
  if (node.kind == Cut_kind::edge) {
    s = p_.side(a.a, node.segment, t_).sign;
    if (s == 0) s = a.dir;
  } else {
    if (node.point == a.a) throw Bsp_contradiction("cylindrical BSP: a point is cut twice in one region");
    s = p_.compare_x(a.a, node.point, t_).sign;
  }
  return static_cast<std::size_t>(node.child[s > 0]);
}

// Phase 2 for segment i from node `node`: its crossings with the earlier
// segments found there, each cut above and below, and the cuts `kept` (of
// crossings found above `node`), in priority order of the other segment.
template <class K>
void Bsp_builder<K>::insert_crossings(std::size_t node, std::uint32_t i, const Site_point& from, const Site_point& to,
                                      std::vector<Arrival> kept) {
  walk(node, {Arrival::Kind::crossings, i, from, to, 0}, [](std::size_t) {}, [&](std::uint32_t j) {
    for (const std::int8_t dir : {std::int8_t(1), std::int8_t(-1)})
      kept.push_back({Arrival::Kind::intersection, i, Site_point::crossing(i, j), {}, dir});
  });
  std::stable_sort(kept.begin(), kept.end(),
                   [&](const Arrival& x, const Arrival& y) { return located_before(x, y, p_.scene().rank); });
  for (const Arrival& c : kept) {
    // A crossing found below `node` is located from the root by the whole
    // construction: its signs above `node` are certificates too.
    const bool found_here = c.a != from && c.a != to;
    if (found_here && node != 0) trace(node, c);
    split(locate(node, c), Cut_kind::intersection, c.a);
  }
}

// Decides the steps of locating a.a from the root down to `to`, which must be
// on the way, and logs them above `to` in build order (unless logged there).
template <class K>
void Bsp_builder<K>::trace(std::size_t to, const Arrival& a) {
  std::vector<std::size_t> path{to};  // `to` and its ancestors, bottom up
  for (std::int32_t n = b_.nodes[to].parent; n >= 0; n = b_.nodes[static_cast<std::size_t>(n)].parent)
    path.push_back(static_cast<std::size_t>(n));
  if (decide_traces_)
    for (std::size_t k = path.size() - 1; k > 0; --k) {
      p_.at_node(static_cast<std::int32_t>(path[k]));
      if (step(path[k], a) != path[k - 1])
        throw Bsp_contradiction("cylindrical BSP: a crossing found below a node does not reach it");
    }
  // Bottom up: a crossing logged at a node was located there from the root,
  // so every ancestor logs it too, and the first that does ends the climb.
  if (log_)
    for (std::size_t k = 1; k < path.size(); ++k)
      if (!log_in_order(log_->at[path[k]], a, p_.scene().rank)) break;
}

bool located_before(const Arrival& x, const Arrival& y, const std::vector<std::size_t>& rank) {
  const std::size_t rx = rank[other_segment(x)], ry = rank[other_segment(y)];
  return rx != ry ? rx < ry : x.dir > y.dir;
}

std::vector<std::uint8_t> route(const Cylindrical_bsp& bsp, std::size_t n) {
  std::vector<std::uint8_t> out;
  for (std::size_t c = n; bsp.nodes[c].parent >= 0;) {
    const auto u = static_cast<std::size_t>(bsp.nodes[c].parent);
    out.push_back(bsp.nodes[u].child[1] == static_cast<std::int32_t>(c));
    c = u;
  }
  std::reverse(out.begin(), out.end());
  return out;
}

std::pair<std::size_t, std::size_t> rank_block(const std::vector<Arrival>& log, const std::vector<std::size_t>& rank,
                                               std::size_t r) {
  const auto from = std::partition_point(log.begin(), log.end(), [&](const Arrival& a) { return rank[a.segment] < r; });
  const auto to = std::partition_point(from, log.end(), [&](const Arrival& a) { return rank[a.segment] == r; });
  return {static_cast<std::size_t>(from - log.begin()), static_cast<std::size_t>(to - log.begin())};
}

bool log_in_order(std::vector<Arrival>& log, const Arrival& a, const std::vector<std::size_t>& rank) {
  // Build order (Build_log): by rank, then vertex, crossings, intersections
  // in the order they are located, edges; one search, not a scan of the
  // segment's block, which at a high node holds all its crossings.
  const std::size_t r = rank[a.segment];
  const auto at = std::partition_point(log.begin(), log.end(), [&](const Arrival& x) {
    const std::size_t rx = rank[x.segment];
    if (rx != r) return rx < r;
    return x.kind == Arrival::Kind::vertex || x.kind == Arrival::Kind::crossings ||
           (x.kind == Arrival::Kind::intersection && located_before(x, a, rank));
  });
  if (at != log.end() && *at == a) return false;
  log.insert(at, a);
  return true;
}

// Visits the part from a.a to a.b of segment a.segment down the subtree of
// n: `leaf(n)` at every leaf whose cell it meets, `crossing(j)` at every edge
// cut of an earlier segment j that it crosses inside the cut's cell.
template <class K>
template <class Leaf, class Crossing>
void Bsp_builder<K>::walk(std::size_t n, Arrival a, const Leaf& leaf, const Crossing& crossing) {
  arrive(n, a);
  if (stops(n)) return leaf(n);
  const Bsp_node node = b_.nodes[n];  // a copy: `leaf` adds nodes
  const auto left = static_cast<std::size_t>(node.child[0]), right = static_cast<std::size_t>(node.child[1]);
  const std::uint32_t i = a.segment;
  const Site_point from = a.a, to = a.b;
  // The part splits at x where its ends' sides differ (split_walk), the
  // piece below or left walked first. Since each end is compared on its own,
  // a segment turning vertical changes no decision above its own cuts.
  const auto go = [&](int at_from, int at_to, const Site_point& x) {
    const auto parts = split_walk(a, at_from, at_to, x);
    if (parts[0]) walk(left, *parts[0], leaf, crossing);
    if (parts[1]) walk(right, *parts[1], leaf, crossing);
  };
  switch (node.kind) {
    case Cut_kind::leaf: return;  // stops() above
    case Cut_kind::vertex:
    case Cut_kind::intersection: {
      const Site_point& c = node.point;
      const auto at = [&](const Site_point& q) { return q == c ? 0 : p_.compare_x(q, c, t_).sign; };
      return go(at(from), at(to), c);
    }
    case Cut_kind::edge: {
      const std::uint32_t j = node.segment;
      const int at_from = p_.order_at(from, i, j, t_).sign, at_to = p_.order_at(to, i, j, t_).sign;
      if (at_from != 0 && at_to != 0 && at_from != at_to) crossing(j);
      return go(at_from, at_to, Site_point::crossing(i, j));
    }
  }
}

std::array<std::optional<Arrival>, 2> split_walk(const Arrival& a, int at_from, int at_to, const Site_point& x) {
  if (at_from == 0) at_from = at_to;
  if (at_to == 0) at_to = at_from;
  if (at_from == at_to) {
    std::array<std::optional<Arrival>, 2> whole;
    whole[at_from > 0] = a;
    return whole;
  }
  Arrival first = a, second = a;
  first.b = x;
  second.a = x;
  if (at_from > 0) std::swap(first, second);
  return {first, second};
}

std::vector<Site_point> crossings_below(const Cylindrical_bsp& bsp, std::size_t v) {
  std::vector<Site_point> x;
  for (const std::size_t n : bsp.preorder(v))
    if (bsp.nodes[n].kind == Cut_kind::intersection) x.push_back(bsp.nodes[n].point);
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  return x;
}

void unlog_crossings(Build_log& log, const std::set<std::size_t>& nodes, const std::vector<Site_point>& gone) {
  if (gone.empty()) return;
  for (const std::size_t a : nodes) {
    auto& at = log.at[a];
    at.erase(std::remove_if(at.begin(), at.end(),
                            [&](const Arrival& x) {
                              return x.kind == Arrival::Kind::intersection &&
                                     std::binary_search(gone.begin(), gone.end(), x.a);
                            }),
             at.end());
  }
}

std::size_t point_rank(const Site_point& p, const std::vector<std::size_t>& rank) {
  return p.kind == Site_point::Kind::endpoint ? rank[p.a / 2] : std::max(rank[p.a], rank[p.b]);
}

std::size_t cut_rank(const Bsp_node& node, const std::vector<std::size_t>& rank) {
  switch (node.kind) {
    case Cut_kind::leaf: return rank.size();
    case Cut_kind::vertex:
    case Cut_kind::intersection: return point_rank(node.point, rank);
    case Cut_kind::edge: return rank[node.segment];
  }
  return rank.size();
}

void decided_keys(const Bsp_node& node, const Arrival& a, std::vector<Segment_certificate_key>& out) {
  using Key = Segment_certificate_key;
  const auto x_order = [&](const Site_point& p, const Site_point& q) {
    if (p != q) out.push_back(x_order_key(p, q));
  };
  const auto side = [&](const Site_point& p, std::uint32_t s) {
    if (!p.on(s)) out.push_back({Key::Kind::side, p, {}, s, 0});
  };
  switch (node.kind) {
    case Cut_kind::leaf: return;
    case Cut_kind::vertex:
    case Cut_kind::intersection:
      x_order(a.a, node.point);
      if (!locates(a)) x_order(a.b, node.point);
      return;
    case Cut_kind::edge: {
      const std::uint32_t i = a.segment, j = node.segment;
      if (locates(a)) return side(a.a, j);
      // Segment_predicates::order_at: a point on either line asks the side of the other.
      for (const Site_point& q : {a.a, a.b}) {
        if (q.on(i)) side(q, j);
        else if (q.on(j)) side(q, i);
        else out.push_back({Key::Kind::order_at, q, {}, i, j});
      }
      return;
    }
  }
}

template <class K>
Cylindrical_bsp build_cylindrical_bsp(const Segment_predicates<K>& pred, const typename K::Time& t) {
  Cylindrical_bsp bsp;
  Bsp_builder<K> builder(pred, t, bsp, nullptr);
  builder.start();
  for (const std::size_t s : pred.scene().priority_order) builder.insert(static_cast<std::uint32_t>(s));
  return bsp;
}

#define KVD_INSTANTIATE_CYLINDRICAL_BSP(K)                                                                   \
  template class Bsp_builder<K>;                                                                             \
  template Cylindrical_bsp build_cylindrical_bsp<K>(const Segment_predicates<K>&, const typename K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_CYLINDRICAL_BSP)

}  // namespace kvd::segments
