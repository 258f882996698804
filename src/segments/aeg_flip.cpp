// A flip of the run on the paper's certificates, done in place (seed 003,
// section 3.1.4; kvd/segments/aeg_kinetic_bsp.hpp, and
// proofs/segment-certificates.md, "Flips in place").
#include <algorithm>
#include <map>
#include <optional>

#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"

namespace kvd::segments {

namespace {

// One leaf of B_{i-1} that the flipping segment s meets, as s's insertion
// cut it: s's first point cut at v, its second at p2 on side d of v (0 left,
// 1 right), s's edge cut m between them, the subtrees o1 beside v (on side
// 1 - d) and o2 beside p2 (on side d).
struct Flip_site {
  std::size_t v = 0, p2 = 0, m = 0, o1 = 0, o2 = 0;
  int d = 0;
  std::size_t own = 0;  // the place of v's own arrival in v's log
};

bool walks(const Arrival& a) { return !locates(a); }

}  // namespace

template <class K>
bool Aeg_kinetic_bsp<K>::flip_in_place(const std::vector<std::size_t>& turning, const std::set<std::size_t>& failing,
                                       Batch& b) {
  // Whether they are lone flips, with nothing changed yet. In each leaf of
  // B_{i-1} the segment, about to be vertical, runs from its floor (or an
  // endpoint) to its roof (or the other): two point cuts, its edge cut
  // between them, and below that only the cuts of later segments crossing
  // it. Another event at this instant shows as another shape, a point cut
  // beside the strip or a cut above v meeting the strip's walls now, or a
  // failing certificate of an endpoint or outside the strips (the caller's
  // and the last check).
  const std::vector<std::size_t>& rank = scene_.rank;
  std::vector<Flip_site> sites;
  std::map<std::size_t, std::size_t> middle;  // the subtrees of the sites' m, each with its flipping segment
  // Whether a point beside the strip has its abscissa meet the wall's (at
  // w) now, as one can without crossing it: it lies inside the strip just
  // after. A point between it and the wall would too, so the nodes along
  // the wall show it.
  const auto touching = [&](std::size_t top, int side, const Site_point& w) {
    bool found = false;
    along_wall(tree_, top, side, w, [&](std::size_t x) {
      const Bsp_node& q = tree_.nodes[x];
      found = found || (point_cut(q) && pred_.compare_x(q.point, w, now_).rule != Segment_rule::value);
    });
    return found;
  };
  for (const std::size_t s : turning) {
    for (const std::size_t v : tops(s)) {
      const std::size_t r = rank[s];
      Flip_site f;
      f.v = v;
      const Bsp_node& n = tree_.nodes[v];
      if (!point_cut(n)) return false;
      f.d = -1;
      for (const int side : {0, 1}) {
        const Bsp_node& c = tree_.nodes[child(n, side)];
        if (point_cut(c) && cut_rank(c, rank) == r) f.d = side;
      }
      if (f.d < 0) return false;
      const int d = f.d;
      f.p2 = child(n, d);
      f.o1 = child(n, 1 - d);
      const Bsp_node& p2 = tree_.nodes[f.p2];
      f.m = child(p2, 1 - d);
      f.o2 = child(p2, d);
      const Bsp_node& m = tree_.nodes[f.m];
      if (m.kind != Cut_kind::edge || m.segment != s) return false;
      if (cut_rank(tree_.nodes[f.o1], rank) <= r || cut_rank(tree_.nodes[f.o2], rank) <= r) return false;
      if (touching(f.o1, d, n.point) || touching(f.o2, 1 - d, p2.point)) return false;
      if (above_ties(v, n.point, false) != v || above_ties(v, p2.point, false) != v) return false;
      const std::vector<Arrival>& log = log_.at[v];
      const auto own = std::find_if(log.begin(), log.end(), [&](const Arrival& a) {
        return locates(a) && a.segment == s && a.a == n.point;
      });
      if (own == log.end()) return false;
      f.own = static_cast<std::size_t>(own - log.begin());
      for (const std::size_t x : tree_.preorder(f.m)) {
        const Bsp_node& q = tree_.nodes[x];
        if (point_cut(q) && (q.kind != Cut_kind::intersection || !q.point.on(s))) return false;
        middle.emplace(x, s);
      }
      sites.push_back(std::move(f));
    }
  }
  if (sites.empty()) return false;
  for (const std::size_t t : failing)
    if (!middle.count(t)) return false;
  // Flips at one instant are done one after the other where no site lies
  // below another's v (two that cross lie one below the other): each edits
  // only its v's subtree, which holds nothing of the others.
  std::set<std::size_t> tops_of_sites;
  for (const Flip_site& f : sites) tops_of_sites.insert(f.v);
  for (const Flip_site& f : sites)
    if (below_any(tree_, f.v, [&](std::size_t a) { return tops_of_sites.count(a) > 0; })) return false;

  std::vector<std::size_t> edited;
  // The nodes of `top`'s subtree along its wall on `side`, which was at
  // `from` and is now at `to`: their cells, and the ends of the walks they
  // logged there.
  const auto rewall = [&](std::size_t top, int side, const Site_point& from, const Site_point& to) {
    along_wall(tree_, top, side, from, [&](std::size_t x) {
      wall(tree_.nodes[x].cell, side) = to;
      for (Arrival& a : log_.at[x])
        if (walks(a)) {
          if (a.a == from) a.a = to;
          if (a.b == from) a.b = to;
        }
      edited.push_back(x);
    });
  };
  for (const Flip_site& f : sites) {
    const int d = f.d;
    const Site_point p1 = tree_.nodes[f.v].point, p2 = tree_.nodes[f.p2].point;
    // p2's arrivals: those after v's own that v now sends to side 1 - d.
    std::vector<Arrival> moved;
    const std::vector<Arrival>& log = log_.at[f.v];
    const auto at = [&](const Site_point& q) { return q == p1 ? 0 : pred_.compare_x(q, p1, now_).sign; };
    for (std::size_t k = f.own + 1; k < log.size(); ++k) {
      const Arrival& a = log[k];
      if (!walks(a)) {
        if (static_cast<int>(at(a.a) > 0) == 1 - d) moved.push_back(a);
      } else if (const auto part = split_walk(a, at(a.a), at(a.b), p1)[1 - d]) {
        moved.push_back(*part);
      }
    }
    log_.at[f.p2] = std::move(moved);
    // v: o2 on side d, p2 on side 1 - d; p2: o1 beyond it, m towards v.
    Bsp_node& v = tree_.nodes[f.v];
    Bsp_node& q2 = tree_.nodes[f.p2];
    v.child[d] = static_cast<std::int32_t>(f.o2);
    v.child[1 - d] = static_cast<std::int32_t>(f.p2);
    q2.child[1 - d] = static_cast<std::int32_t>(f.o1);
    q2.child[d] = static_cast<std::int32_t>(f.m);
    tree_.nodes[f.o1].parent = static_cast<std::int32_t>(f.p2);
    tree_.nodes[f.o2].parent = static_cast<std::int32_t>(f.v);
    q2.cell = v.cell;
    wall(q2.cell, d) = p1;
    edited.push_back(f.v);
    edited.push_back(f.p2);
    rewall(f.o1, d, p1, p2);
    rewall(f.o2, 1 - d, p2, p1);
  }
  // Below each m, mirrored: walls, the sides of the cuts through s, and the
  // direction in which the later segments' walks cross each cell.
  for (const auto& [x, s] : middle) {
    Bsp_node& q = tree_.nodes[x];
    std::swap(q.cell.left, q.cell.right);
    if (point_cut(q)) std::swap(q.child[0], q.child[1]);
    for (Arrival& a : log_.at[x])
      if (walks(a) && a.segment != s) std::swap(a.a, a.b);
    edited.push_back(x);
  }
  // Certificates: the transient nodes with a new cell and the endpoints
  // beside a leaf with one (the turning segments' own are the caller's), in
  // preorder, not by slot (sort_in_preorder).
  sort_in_preorder(tree_, edited, [](std::size_t x) { return x; });
  for (const std::size_t x : edited)
    if (transient_.count(x) || failing.count(x)) make_transient(x);
  for (const std::size_t x : edited) remake_beside(x, x);
  b.flipped_in_place = sites.size();
  b.nodes_edited = edited.size();
  return true;
}

template bool Aeg_kinetic_bsp<Exact_kernel>::flip_in_place(const std::vector<std::size_t>&, const std::set<std::size_t>&,
                                                           Batch&);

}  // namespace kvd::segments
