// Whether an old subtree of the run on the paper's certificates can be kept
// with its cell's moved walls renamed (kvd/segments/aeg_kinetic_bsp.hpp,
// walls_renamed; proofs/segment-local-update.md, "Cells kept", walls
// renamed).
#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"

namespace kvd::segments {

template <class K>
bool Aeg_kinetic_bsp<K>::walls_renamed(std::size_t o, const Cell& now) const {
  const Cell& was = tree_.nodes[o].cell;
  return counting(phases_.walls, [&] {
    const auto by_value = [](const Segment_sign& s) { return s.rule == Segment_rule::value; };
    for (const int side : {0, 1}) {
      const Site_point p = *wall(was, side), q = *wall(now, side);
      if (p == q) continue;
      // p and q at one abscissa now, neither a crossing of lines that
      // coincide now (against the cell's other wall, by value).
      const Site_point& other = *wall(now, 1 - side);
      if (by_value(pred_.compare_x(p, q, now_)) || !by_value(pred_.compare_x(p, other, now_)) ||
          !by_value(pred_.compare_x(q, other, now_)))
        return false;
      // No point cut along the wall at that abscissa, and no two segments
      // crossing the wall meeting there: those are ordered along it by the
      // leaves, so two that meet make a leaf's floor and roof meet.
      bool clear = true;
      along_wall(tree_, o, side, p, [&](std::size_t x) {
        const Bsp_node& n = tree_.nodes[x];
        if (!clear) return;
        if (point_cut(n)) {
          clear = by_value(pred_.compare_x(p, n.point, now_));
        } else if (n.kind == Cut_kind::leaf && n.cell.floor && n.cell.roof) {
          // (order_at asks p's side of the other line when p lies on one,
          // and is 0 by identity when on both: no value, not clear.)
          clear = by_value(pred_.order_at(p, *n.cell.floor, *n.cell.roof, now_));
        }
      });
      if (!clear) return false;
    }
    return true;
  });
}

template bool Aeg_kinetic_bsp<Exact_kernel>::walls_renamed(std::size_t, const Cell&) const;

}  // namespace kvd::segments
