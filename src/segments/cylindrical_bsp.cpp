// The static construction of the cylindrical BSP (seed 003, section 2.1).
#include "kvd/segments/cylindrical_bsp.hpp"

#include <algorithm>
#include <stdexcept>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

namespace {

template <class K>
class Builder {
public:
  using Time = typename K::Time;
  Builder(const Segment_predicates<K>& pred, const Time& t, Cylindrical_bsp& bsp) : p_(pred), t_(t), b_(bsp) {
    b_.nodes.assign(1, Bsp_node{});
  }

  void insert(std::uint32_t i) {
    for (const std::size_t e : {2 * std::size_t(i), 2 * std::size_t(i) + 1}) {
      const Site_point q = Site_point::endpoint(e);
      split(locate(q, 0), Cut_kind::vertex, q);
    }
    const Site_point lo = Site_point::endpoint(p_.left_endpoint(i, t_)), hi = Site_point::endpoint(p_.right_endpoint(i, t_));
    std::vector<std::uint32_t> crossed;
    walk(0, i, lo, hi, [](std::size_t) {}, [&](std::uint32_t j) { crossed.push_back(j); });
    const auto& rank = p_.scene().rank;
    std::sort(crossed.begin(), crossed.end(), [&](std::uint32_t a, std::uint32_t b) { return rank[a] < rank[b]; });
    for (const std::uint32_t j : crossed) {
      const Site_point q = Site_point::crossing(i, j);
      split(locate(q, +1), Cut_kind::intersection, q);
      split(locate(q, -1), Cut_kind::intersection, q);
    }
    walk(0, i, lo, hi, [&](std::size_t leaf) { split_edge(leaf, i); }, [](std::uint32_t) {});
  }

private:
  std::size_t add_leaf(const Cell& c) {
    b_.nodes.push_back(Bsp_node{});
    b_.nodes.back().cell = c;
    return b_.nodes.size() - 1;
  }

  void split(std::size_t n, Cut_kind kind, const Site_point& q) {
    Cell left = b_.nodes[n].cell, right = left;
    left.right = q;
    right.left = q;
    const std::size_t l = add_leaf(left), r = add_leaf(right);
    Bsp_node& node = b_.nodes[n];
    node.kind = kind;
    node.point = q;
    node.child[0] = static_cast<std::int32_t>(l);
    node.child[1] = static_cast<std::int32_t>(r);
  }

  void split_edge(std::size_t n, std::uint32_t s) {
    Cell below = b_.nodes[n].cell, above = below;
    below.roof = s;
    above.floor = s;
    const std::size_t l = add_leaf(below), r = add_leaf(above);
    Bsp_node& node = b_.nodes[n];
    node.kind = Cut_kind::edge;
    node.segment = s;
    node.child[0] = static_cast<std::int32_t>(l);
    node.child[1] = static_cast<std::int32_t>(r);
  }

  // The leaf whose cell holds q; where q lies on an edge cut by construction
  // (a crossing on the earlier segment's fragment), the leaf just above it
  // (dir = +1) or just below it (dir = -1).
  std::size_t locate(const Site_point& q, int dir) const {
    std::size_t n = 0;
    while (b_.nodes[n].kind != Cut_kind::leaf) {
      const Bsp_node& node = b_.nodes[n];
      int s;
      if (node.kind == Cut_kind::edge) {
        s = p_.side(q, node.segment, t_).sign;
        if (s == 0) s = dir;
      } else {
        if (node.point == q) throw std::logic_error("cylindrical BSP: a point is cut twice in one region");
        s = p_.compare_x(q, node.point, t_).sign;
      }
      n = static_cast<std::size_t>(node.child[s > 0]);
    }
    return n;
  }

  // Visits the part of segment i with x in (lo, hi) down the subtree of n:
  // `leaf(n)` at every leaf whose cell it meets, `crossing(j)` at every edge
  // cut of an earlier segment j that it crosses inside the cut's cell.
  template <class Leaf, class Crossing>
  void walk(std::size_t n, std::uint32_t i, const Site_point& lo, const Site_point& hi, const Leaf& leaf,
            const Crossing& crossing) {
    const Bsp_node node = b_.nodes[n];  // a copy: `leaf` adds nodes
    const auto left = static_cast<std::size_t>(node.child[0]), right = static_cast<std::size_t>(node.child[1]);
    switch (node.kind) {
      case Cut_kind::leaf: leaf(n); return;
      case Cut_kind::vertex:
      case Cut_kind::intersection: {
        const Site_point& c = node.point;
        if (c == lo || p_.compare_x(c, lo, t_).sign < 0) return walk(right, i, lo, hi, leaf, crossing);
        if (c == hi || p_.compare_x(c, hi, t_).sign > 0) return walk(left, i, lo, hi, leaf, crossing);
        walk(left, i, lo, c, leaf, crossing);
        walk(right, i, c, hi, leaf, crossing);
        return;
      }
      case Cut_kind::edge: {
        const std::uint32_t j = node.segment;
        int a = p_.order_at(lo, i, j, t_).sign, b = p_.order_at(hi, i, j, t_).sign;
        if (a == 0) a = b;
        if (b == 0) b = a;
        if (a == b) return walk(a > 0 ? right : left, i, lo, hi, leaf, crossing);
        crossing(j);
        const Site_point x = Site_point::crossing(i, j);
        walk(a > 0 ? right : left, i, lo, x, leaf, crossing);
        walk(b > 0 ? right : left, i, x, hi, leaf, crossing);
        return;
      }
    }
  }

  const Segment_predicates<K>& p_;
  const Time& t_;
  Cylindrical_bsp& b_;
};

}  // namespace

template <class K>
Cylindrical_bsp build_cylindrical_bsp(const Segment_predicates<K>& pred, const typename K::Time& t) {
  Cylindrical_bsp bsp;
  Builder<K> builder(pred, t, bsp);
  for (const std::size_t s : pred.scene().priority_order) builder.insert(static_cast<std::uint32_t>(s));
  return bsp;
}

#define KVD_INSTANTIATE_CYLINDRICAL_BSP(K) \
  template Cylindrical_bsp build_cylindrical_bsp<K>(const Segment_predicates<K>&, const typename K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_CYLINDRICAL_BSP)

}  // namespace kvd::segments
