// The construction of the cylindrical BSP (kvd/segments/cylindrical_bsp.hpp)
// as steps that a kinetic run can replay in one subtree.
//
// Every step of an insertion reaches a chain of nodes from the root: a point
// located for a vertex or an intersection cut, a part (from, to) of a segment
// walked down for its crossings or its edge cuts. With a log, each node keeps
// the arrivals that reached it, in build order. Whatever the later segments
// do, the arrivals at a node depend only on the decisions of its ancestors;
// so when only decisions inside the subtree of v change, replaying v's
// arrivals on a leaf with v's cell makes the subtree the whole construction
// would make (proofs/segment-local-update.md).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

struct Arrival {
  enum class Kind : std::uint8_t { vertex, crossings, intersection, edges };
  Kind kind = Kind::vertex;
  std::uint32_t segment = 0;
  Site_point a, b;  // vertex: the endpoint; intersection: the crossing; walks: the part from a to b (endpoint 0's way first)
  std::int8_t dir = 0;  // intersection: +1 the leaf above the crossing, -1 below
  friend bool operator==(const Arrival&, const Arrival&) = default;
};

// Whether an arrival locates a point (a vertex or an intersection), not
// walks a part.
inline bool locates(const Arrival& a) { return a.kind == Arrival::Kind::vertex || a.kind == Arrival::Kind::intersection; }

// The arrivals at every node, and the node slots free for reuse. A node's
// arrivals are in build order, so by the priority rank of their segment, and
// within one segment by phase: vertex, crossings, intersection, edges. They
// are those of the whole construction at the current time: a replay below a
// node logs there the crossings it finds anew, and takes away those gone.
struct Build_log {
  std::vector<std::vector<Arrival>> at;
  std::vector<std::size_t> free;
};

// The place of the insertion that made a node's cut in the priority order
// (`rank`: Segment_scene::rank); a leaf's is past every segment. It does not
// decrease down any path: each insertion splits leaves of the tree before it.
std::size_t cut_rank(const Bsp_node& node, const std::vector<std::size_t>& rank);
// That of the insertion that puts a point's cut: an endpoint's segment's,
// the later of a crossing's two.
std::size_t point_rank(const Site_point& p, const std::vector<std::size_t>& rank);

// Puts `node` in a free slot of the tree (one of the log's, when it has
// one; the slot's log emptied), or in a new one; returns the slot.
std::size_t place_node(Cylindrical_bsp& bsp, Build_log* log, const Bsp_node& node);

// The children taken from the root down to node n (0: left or below).
std::vector<std::uint8_t> route(const Cylindrical_bsp& bsp, std::size_t n);

// Whether some proper ancestor a of node n has in(a).
template <class In>
bool below_any(const Cylindrical_bsp& bsp, std::size_t n, const In& in) {
  for (std::int32_t a = bsp.nodes[n].parent; a >= 0; a = bsp.nodes[static_cast<std::size_t>(a)].parent)
    if (in(static_cast<std::size_t>(a))) return true;
  return false;
}

// Sorts items by their nodes (`node(item)`) in the tree's preorder, so that
// what is done to them in turn does not depend on the slots the nodes
// happen to hold: a run made afresh numbers its nodes otherwise than one
// that got there by events.
template <class T, class Node>
void sort_in_preorder(const Cylindrical_bsp& bsp, std::vector<T>& items, const Node& node) {
  std::vector<std::pair<std::vector<std::uint8_t>, std::size_t>> keyed;
  keyed.reserve(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) keyed.emplace_back(route(bsp, node(items[i])), i);
  std::sort(keyed.begin(), keyed.end());
  std::vector<T> sorted;
  sorted.reserve(items.size());
  for (const auto& k : keyed) sorted.push_back(std::move(items[k.second]));
  items = std::move(sorted);
}

// The arrivals of the segment of rank r in a log (a range: a log is in rank order).
std::pair<std::size_t, std::size_t> rank_block(const std::vector<Arrival>& log, const std::vector<std::size_t>& rank,
                                               std::size_t r);

// The parts of walk a that a cut through x sends below or left ([0]) and
// above or right ([1]), given the sides of the part's two ends (0: on the
// cut, taking the other end's side): the piece (from, x) goes to from's
// side and (x, to) to to's side. Each end is compared on its own, never one
// end with the other: the walk is the same whichever end is left.
std::array<std::optional<Arrival>, 2> split_walk(const Arrival& a, int at_from, int at_to, const Site_point& x);

// The crossings with an intersection cut in the subtree of v, sorted, each once.
std::vector<Site_point> crossings_below(const Cylindrical_bsp& bsp, std::size_t v);

// A replay below a node logs there, and up to the root, where it locates a
// crossing it finds; a crossing it no longer finds was logged there too.
// Takes the locations of the crossings `gone` (sorted) out of the logs of
// `nodes`.
void unlog_crossings(Build_log& log, const std::set<std::size_t>& nodes, const std::vector<Site_point>& gone);

// The segment an intersection arrival's segment crosses there.
inline std::uint32_t other_segment(const Arrival& c) { return c.a.a == c.segment ? c.a.b : c.a.a; }

// Whether intersection arrival x of a segment comes before y of the same
// segment in build order: by the other segment's priority, above first.
bool located_before(const Arrival& x, const Arrival& y, const std::vector<std::size_t>& rank);

// Inserts intersection arrival a into a node's log at its place in build
// order, unless it is there (then false): for a crossing found below a
// replayed node, whose location from the root the replay decides above that
// node (trace).
bool log_in_order(std::vector<Arrival>& log, const Arrival& a, const std::vector<std::size_t>& rank);

// The certificate keys that the arrival decides at the node, read off the
// node's cut and the arrival's points without arithmetic: the keys that
// Bsp_builder's step and walk ask the predicates for there (none at a leaf,
// and none where a sign is 0 by identity). A key does not depend on the sign.
// An arrival logged while the node was a leaf decided nothing there: it is a
// crossing walk of the segment that cut the node next, whose edge walk then
// asks the same keys (at its own intersection cut), or keys no predicate
// records (order_at of a segment's line with itself, at its own edge cut).
void decided_keys(const Bsp_node& node, const Arrival& a, std::vector<Segment_certificate_key>& out);

template <class K>
class Bsp_builder {
public:
  using Time = typename K::Time;
  // `log` may be null (a static build keeps none). The predicates are told
  // the node of every sign they decide (Segment_predicates::at_node).
  Bsp_builder(const Segment_predicates<K>& pred, const Time& t, Cylindrical_bsp& bsp, Build_log* log);

  // The tree of no segment: one leaf.
  void start();
  // Inserts segment i (the next in priority order) from the root.
  void insert(std::uint32_t i);
  // Makes the subtree of v again from `arrivals` (v's log before the change),
  // v reset to a leaf with its cell. The nodes below v must have been freed.
  void replay(std::size_t v, const std::vector<Arrival>& arrivals);
  // The arrivals of one segment at u (of rank `rank`, as logged there),
  // decided again from u down to the frontier: the first nodes whose cut is
  // of rank `rank` or later, or leaves. Nothing is split, and the logs below
  // u are left to the caller: `at` gets the arrivals at every node below u
  // that they reach, frontier nodes included, in build order, as replay
  // would log them (crossings found again, and located from u after their
  // signs above u are decided; a crossing found anew is logged at u and
  // above). A logged crossing with a segment of rank `rank` or later, which
  // the walks do not find above the frontier, is located as logged.
  // proofs/segment-local-update.md, "Frontier replay".
  void reroute(std::size_t u, const std::vector<Arrival>& arrivals, std::size_t rank,
               std::map<std::size_t, std::vector<Arrival>>& at);
  // The nodes added since the builder was made.
  std::size_t added() const { return added_; }
  // A crossing found below a replayed node is logged above it without the
  // signs of its way down being decided again: for a run that keeps no
  // sign as a certificate (those signs are not a certificate of its set).
  void log_traces_only() { decide_traces_ = false; }

private:
  void steps(std::size_t v, const std::vector<Arrival>& arrivals);
  bool stops(std::size_t n) const;
  std::size_t add_leaf(const Cell& c, std::size_t parent);
  void split(std::size_t n, Cut_kind kind, const Site_point& q);
  void split_edge(std::size_t n, std::uint32_t s);
  // Gives node n, its cut set, two leaves with the cells the cut makes.
  void add_children(std::size_t n);
  void arrive(std::size_t n, const Arrival& a);
  std::size_t locate(std::size_t from, const Arrival& a);
  std::size_t step(std::size_t n, const Arrival& a) const;
  void trace(std::size_t to, const Arrival& a);
  void insert_crossings(std::size_t node, std::uint32_t i, const Site_point& from, const Site_point& to,
                        std::vector<Arrival> kept);
  template <class Leaf, class Crossing>
  void walk(std::size_t n, Arrival a, const Leaf& leaf, const Crossing& crossing);

  const Segment_predicates<K>& p_;
  const Time& t_;
  Cylindrical_bsp& b_;
  Build_log* log_;
  std::size_t added_ = 0;
  bool decide_traces_ = true;
  // While rerouting: the frontier's rank, and where arrivals are collected
  // instead of logged.
  std::size_t frontier_ = 0;
  std::map<std::size_t, std::vector<Arrival>>* collect_ = nullptr;
  std::size_t origin_ = 0;  // the node rerouted from: its arrivals stay
};

}  // namespace kvd::segments
