// The certificates of seed 003, section 3.1, computed from a tree and an
// instant (kvd/segments/aeg_certificates.hpp).
#include "kvd/segments/aeg_certificates.hpp"

#include <stdexcept>
#include <string>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

namespace {

// Whether the subtree of v holds a point cut; the transient nodes below v
// are appended to `out` in pre-order. A transient node has none below it,
// so appending it after its subtree keeps the order.
bool collect(const Cylindrical_bsp& b, std::size_t v, bool parent_point_cut, std::vector<std::size_t>& out) {
  const Bsp_node& node = b.nodes[v];
  bool points = point_cut(node);
  if (node.kind != Cut_kind::leaf)
    for (const std::int32_t c : node.child) points = collect(b, static_cast<std::size_t>(c), point_cut(node), out) || points;
  if (parent_point_cut && !points) out.push_back(v);
  return points;
}

}  // namespace

std::vector<std::size_t> transient_nodes(const Cylindrical_bsp& b) {
  std::vector<std::size_t> out;
  collect(b, 0, false, out);
  return out;
}

Aeg_certificate_counts aeg_certificate_counts(const Cylindrical_bsp& b, std::size_t segments) {
  return {transient_nodes(b).size(), 2 * segments, segments};
}

template <class K>
Aeg_state aeg_state(const Segment_predicates<K>& pred, const typename K::Time& t) {
  const std::size_t n = pred.size();
  Aeg_state s;
  for (std::size_t i = 0; i < n; ++i)
    s.flips.push_back(pred.compare_x(Site_point::endpoint(2 * i + 1), Site_point::endpoint(2 * i), t).sign);
  for (std::size_t e = 0; e < 2 * n; ++e) {
    const Site_point p = Site_point::endpoint(e);
    std::array<std::int64_t, 2> near{-1, -1};  // below, above
    for (std::size_t j = 0; j < n; ++j) {
      if (j == e / 2) continue;
      const int l = pred.compare_x(p, Site_point::endpoint(2 * j), t).sign;
      const int r = pred.compare_x(p, Site_point::endpoint(2 * j + 1), t).sign;
      if (l == r) continue;  // p is outside j's x-range
      const bool above = pred.side(p, j, t).sign < 0;  // j passes above p
      std::int64_t& best = near[above];
      // The lowest of the segments above, the highest of those below.
      if (best < 0 || pred.order_at(p, j, static_cast<std::size_t>(best), t).sign == (above ? -1 : 1))
        best = static_cast<std::int64_t>(j);
    }
    s.neighbours.push_back(near);
  }
  return s;
}

template <class K>
std::size_t aeg_leaf(const Cylindrical_bsp& b, const Segment_predicates<K>& pred, const typename K::Time& t,
                     std::size_t e, std::size_t from) {
  const Site_point p = Site_point::endpoint(e);
  // -1 when e is its segment's left endpoint: the side away from the segment.
  const int away = pred.compare_x(p, Site_point::endpoint(e ^ 1U), t).sign;
  std::size_t v = from;
  while (b.nodes[v].kind != Cut_kind::leaf) {
    const Bsp_node& n = b.nodes[v];
    const int side = n.kind == Cut_kind::edge ? pred.side(p, n.segment, t).sign
                     : n.point == p           ? away
                                              : pred.compare_x(p, n.point, t).sign;
    // 0 only by identity: p on an edge cut, which its own segment's never
    // are on the way to the far side.
    if (side == 0) throw std::logic_error("aeg_leaf: " + point_name(p) + " lies on a cut of its path");
    v = static_cast<std::size_t>(n.child[side > 0]);
  }
  return v;
}

template <class K>
std::array<std::int64_t, 2> aeg_neighbours(const Cylindrical_bsp& b, const Segment_predicates<K>& pred,
                                           const typename K::Time& t, std::size_t e) {
  const Cell& c = b.nodes[aeg_leaf(b, pred, t, e)].cell;
  return {c.floor ? std::int64_t(*c.floor) : -1, c.roof ? std::int64_t(*c.roof) : -1};
}

template <class K>
Aeg_failures aeg_failures(const Cylindrical_bsp& before, const Cylindrical_bsp& after,
                          const Segment_predicates<K>& pred, const typename K::Time& t0,
                          const typename K::Time& t1) {
  Aeg_failures f;
  const Aeg_state s0 = aeg_state(pred, t0), s1 = aeg_state(pred, t1);
  for (std::size_t i = 0; i < s0.flips.size(); ++i)
    if (s0.flips[i] != s1.flips[i]) f.flips.push_back(i);
  for (std::size_t e = 0; e < s0.neighbours.size(); ++e)
    if (s0.neighbours[e] != s1.neighbours[e]) f.endpoints.push_back(e);
  for (const std::size_t v : transient_nodes(before))
    if (cell_shape(before.nodes[v].cell, pred, t1) != Cell_shape::proper) f.transient_before.push_back(v);
  for (const std::size_t v : transient_nodes(after))
    if (cell_shape(after.nodes[v].cell, pred, t0) != Cell_shape::proper) f.transient_after.push_back(v);
  return f;
}

#define KVD_INSTANTIATE_AEG_CERTIFICATES(K)                                                                       \
  template Aeg_state aeg_state<K>(const Segment_predicates<K>&, const typename K::Time&);                         \
  template std::size_t aeg_leaf<K>(const Cylindrical_bsp&, const Segment_predicates<K>&, const typename K::Time&, \
                                   std::size_t, std::size_t);                                                     \
  template std::array<std::int64_t, 2> aeg_neighbours<K>(const Cylindrical_bsp&, const Segment_predicates<K>&,     \
                                                         const typename K::Time&, std::size_t);                   \
  template Aeg_failures aeg_failures<K>(const Cylindrical_bsp&, const Cylindrical_bsp&, const Segment_predicates<K>&, \
                                        const typename K::Time&, const typename K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_AEG_CERTIFICATES)

}  // namespace kvd::segments
