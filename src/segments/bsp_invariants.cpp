// The invariants of a cylindrical BSP, checked on the finished tree
// (cylindrical_bsp.hpp, bsp_violations).
#include <algorithm>
#include <optional>
#include <string>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

namespace {

template <class K>
class Checker {
public:
  using Time = typename K::Time;
  Checker(const Cylindrical_bsp& b, const Segment_predicates<K>& p, const Time& t) : b_(b), p_(p), t_(t) {}

  std::vector<std::string> run() {
    cells(0, Cell{});
    for (std::size_t s = 0; s < p_.size(); ++s) tiling(s);
    for (const std::size_t n : b_.preorder()) {
      const Bsp_node& node = b_.nodes[n];
      if (node.kind == Cut_kind::edge) fragment(n);
      if (node.kind != Cut_kind::leaf) continue;
      for (std::size_t s = 0; s < p_.size(); ++s)
        if (meets_interior(s, node.cell)) fail(n, "segment s" + std::to_string(s) + " meets the leaf's interior");
    }
    return violations_;
  }

private:
  void fail(std::size_t n, const std::string& what) {
    if (violations_.size() < 20) violations_.push_back("node " + std::to_string(n) + ": " + what);
  }
  int cmp(const Site_point& a, const Site_point& b) const { return p_.compare_x(a, b, t_).sign; }
  int order(const Site_point& at, std::size_t i, std::size_t j) const { return p_.order_at(at, i, j, t_).sign; }

  // The cells as the cuts above each node give them, and non-empty.
  void cells(std::size_t n, const Cell& expected) {
    const Bsp_node& node = b_.nodes[n];
    if (!(node.cell == expected)) fail(n, "its cell is not the one its ancestors' cuts make");
    const Cell& c = expected;
    switch (cell_shape(c, p_, t_)) {
      case Cell_shape::proper: break;
      case Cell_shape::walls_crossed: fail(n, "its left wall is not left of its right wall"); break;
      case Cell_shape::roof_below_floor: {
        // The wall where it does (cell_shape says only that one does).
        std::string at;
        for (const auto& wall : {c.left, c.right})
          if (wall && at.empty() && order(*wall, *c.roof, *c.floor) < 0) at = point_name(*wall);
        fail(n, "its roof s" + std::to_string(*c.roof) + " passes below its floor s" + std::to_string(*c.floor) +
                    " at the wall through " + at);
        break;
      }
      case Cell_shape::pinched: fail(n, "its roof meets its floor at both walls"); break;
    }
    if (node.kind == Cut_kind::leaf) return;
    cells(static_cast<std::size_t>(node.child[0]), child_cell(c, node, 0));
    cells(static_cast<std::size_t>(node.child[1]), child_cell(c, node, 1));
  }

  // A fragment crosses its cell from wall to wall, between floor and roof.
  void fragment(std::size_t n) {
    const Bsp_node& node = b_.nodes[n];
    const std::size_t s = node.segment;
    const Cell& c = node.cell;
    if (!c.left || !c.right) return fail(n, "a fragment in a cell without two walls");
    if (cmp(Site_point::endpoint(p_.left_endpoint(s, t_)), *c.left) > 0 ||
        cmp(Site_point::endpoint(p_.right_endpoint(s, t_)), *c.right) < 0)
      fail(n, "the fragment of s" + std::to_string(s) + " does not reach both walls");
    for (const Site_point& wall : {*c.left, *c.right}) {
      if (c.floor && order(wall, s, *c.floor) < 0) fail(n, "the fragment passes below the floor at " + point_name(wall));
      if (c.roof && order(wall, s, *c.roof) > 0) fail(n, "the fragment passes above the roof at " + point_name(wall));
    }
  }

  // The fragments of s, in x order, run from its left endpoint to its right
  // one without gap or overlap.
  void tiling(std::size_t s) {
    std::vector<std::size_t> f = b_.fragments(s);
    const std::string who = "segment s" + std::to_string(s);
    if (f.empty()) return fail(0, who + " has no fragment");
    for (const std::size_t n : f)
      if (!b_.nodes[n].cell.left || !b_.nodes[n].cell.right) return;  // reported by fragment()
    std::sort(f.begin(), f.end(),
              [&](std::size_t a, std::size_t b) { return cmp(*b_.nodes[a].cell.left, *b_.nodes[b].cell.left) < 0; });
    if (*b_.nodes[f.front()].cell.left != Site_point::endpoint(p_.left_endpoint(s, t_)))
      fail(f.front(), who + ": the first fragment does not start at the left endpoint");
    if (*b_.nodes[f.back()].cell.right != Site_point::endpoint(p_.right_endpoint(s, t_)))
      fail(f.back(), who + ": the last fragment does not end at the right endpoint");
    for (std::size_t k = 1; k < f.size(); ++k)
      if (*b_.nodes[f[k - 1]].cell.right != *b_.nodes[f[k]].cell.left)
        fail(f[k], who + ": a gap or an overlap before this fragment");
  }

  // The x-interval [a, b] of (lo, hi) where the line of s is above (sign +1)
  // or below (-1) the line of `other`, or none.
  std::optional<std::pair<Site_point, Site_point>> where(std::size_t s, std::size_t other, int sign,
                                                         const Site_point& lo, const Site_point& hi) const {
    int a = order(lo, s, other) * sign, b = order(hi, s, other) * sign;
    if (a == 0) a = b;
    if (b == 0) b = a;
    if (a < 0 && b < 0) return std::nullopt;
    if (a > 0 && b > 0) return std::pair{lo, hi};
    const Site_point x = Site_point::crossing(s, other);
    return a > 0 ? std::pair{lo, x} : std::pair{x, hi};
  }

  bool meets_interior(std::size_t s, const Cell& c) const {
    Site_point lo = Site_point::endpoint(p_.left_endpoint(s, t_)), hi = Site_point::endpoint(p_.right_endpoint(s, t_));
    if (c.left && cmp(*c.left, lo) > 0) lo = *c.left;
    if (c.right && cmp(*c.right, hi) < 0) hi = *c.right;
    if (lo == hi || cmp(lo, hi) >= 0) return false;
    for (const auto& [bound, sign] : {std::pair{c.floor, +1}, std::pair{c.roof, -1}}) {
      if (!bound) continue;
      if (*bound == s) return false;  // the segment is the cell's boundary there
      const auto part = where(s, *bound, sign, lo, hi);
      if (!part) return false;
      if (cmp(part->first, lo) > 0) lo = part->first;
      if (cmp(part->second, hi) < 0) hi = part->second;
      if (lo == hi || cmp(lo, hi) >= 0) return false;
    }
    return true;
  }

  const Cylindrical_bsp& b_;
  const Segment_predicates<K>& p_;
  const Time& t_;
  std::vector<std::string> violations_;
};

}  // namespace

template <class K>
Cell_shape cell_shape(const Cell& c, const Segment_predicates<K>& pred, const typename K::Time& t) {
  if (c.left && c.right && pred.compare_x(*c.left, *c.right, t).sign >= 0) return Cell_shape::walls_crossed;
  if (!c.floor || !c.roof) return Cell_shape::proper;
  int strict = 0;
  for (const auto& wall : {c.left, c.right}) {
    if (!wall) continue;
    // 0 only by identity: the wall passes through the crossing of the two.
    const int o = pred.order_at(*wall, *c.roof, *c.floor, t).sign;
    if (o < 0) return Cell_shape::roof_below_floor;
    strict += o > 0;
  }
  return c.left && c.right && strict == 0 ? Cell_shape::pinched : Cell_shape::proper;
}

template <class K>
std::vector<std::string> bsp_violations(const Cylindrical_bsp& bsp, const Segment_predicates<K>& pred,
                                        const typename K::Time& t) {
  return Checker<K>(bsp, pred, t).run();
}

#define KVD_INSTANTIATE_BSP_VIOLATIONS(K)                                                                  \
  template Cell_shape cell_shape<K>(const Cell&, const Segment_predicates<K>&, const typename K::Time&);     \
  template std::vector<std::string> bsp_violations<K>(const Cylindrical_bsp&, const Segment_predicates<K>&, \
                                                      const typename K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_BSP_VIOLATIONS)

}  // namespace kvd::segments
