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

#include <cstdint>
#include <vector>

#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

struct Arrival {
  enum class Kind : std::uint8_t { vertex, crossings, intersection, edges };
  Kind kind = Kind::vertex;
  std::uint32_t segment = 0;
  Site_point a, b;  // vertex: the endpoint; intersection: the crossing; walks: the part from a to b (endpoint 0's way first)
  std::int8_t dir = 0;  // intersection: +1 the leaf above the crossing, -1 below
};

// The arrivals at every node, and the node slots free for reuse.
struct Build_log {
  std::vector<std::vector<Arrival>> at;
  std::vector<std::size_t> free;
};

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
  // The nodes added since the builder was made.
  std::size_t added() const { return added_; }

private:
  std::size_t add_leaf(const Cell& c, std::size_t parent);
  void split(std::size_t n, Cut_kind kind, const Site_point& q);
  void split_edge(std::size_t n, std::uint32_t s);
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
};

}  // namespace kvd::segments
