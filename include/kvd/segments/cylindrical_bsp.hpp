// The cylindrical BSP of possibly intersecting segments in the plane
// (Agarwal, Erickson and Guibas, seed 003, section 2.1), at an instant.
//
// Segments are inserted in priority order (Segment_scene::priority_order).
// Segment s_i is inserted into B_{i-1} in three phases:
//  1. a vertex cut through each endpoint, into the leaf that contains it
//     (the marked endpoint, the first written, first);
//  2. for each earlier segment s_j that s_i crosses, in priority order of j,
//     an intersection cut through s_i ∩ s_j into the leaf just above that
//     point and the leaf just below it;
//  3. an edge cut along s_i into every leaf whose cell meets the interior of
//     s_i.
// Point cuts (vertex and intersection cuts) are vertical; their children are
// left and right. Edge cuts run along a segment across their cell; their
// children are below and above. Every cell is a trapezoid: two walls from
// point cuts (or none: unbounded) and a floor and a roof from edge cuts.
//
// The tree is a deterministic function of the scene, its priority and the
// instant (t, t + δ), degenerate input included (the predicates decide every
// sign symbolically, kvd/segments/segment_predicates.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "kvd/segments/segment_predicates.hpp"

namespace kvd::segments {

enum class Cut_kind : std::uint8_t { leaf, vertex, intersection, edge };

// A trapezoid: walls through points (none: unbounded that way), floor and
// roof along segments (none: unbounded).
struct Cell {
  std::optional<Site_point> left, right;
  std::optional<std::uint32_t> floor, roof;
  friend bool operator==(const Cell&, const Cell&) = default;
};

struct Bsp_node {
  Cut_kind kind = Cut_kind::leaf;
  std::int32_t parent = -1;
  Site_point point;             // vertex and intersection cuts
  std::uint32_t segment = 0;    // edge cuts
  std::int32_t child[2] = {-1, -1};  // point cut: left, right; edge cut: below, above
  Cell cell;                    // this node's region
};

// Whether a node's cut is vertical, through a point (a vertex or an
// intersection cut).
inline bool point_cut(const Bsp_node& n) { return n.kind == Cut_kind::vertex || n.kind == Cut_kind::intersection; }

// Whether two nodes have the same cut (two leaves: yes).
inline bool same_cut(const Bsp_node& a, const Bsp_node& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == Cut_kind::edge) return a.segment == b.segment;
  return a.kind == Cut_kind::leaf || a.point == b.point;
}

// The slot of a cut node's child `side` (0: left or below, 1: right or above).
inline std::size_t child(const Bsp_node& n, int side) { return static_cast<std::size_t>(n.child[side]); }

// A node's cut as the tree's text names it: "V s3.0" (a vertex cut through
// endpoint 0 of segment 3), "I s1xs4" (an intersection cut), "E s2" (an edge
// cut); "." for a leaf.
std::string cut_name(const Bsp_node& n);

// A cell's wall on `side` (0: left, 1: right).
inline std::optional<Site_point>& wall(Cell& c, int side) { return side ? c.right : c.left; }
inline const std::optional<Site_point>& wall(const Cell& c, int side) { return side ? c.right : c.left; }

// Visits the nodes of top's subtree whose cell has its wall on `side` at w,
// top down: the nodes along that wall, those LeftShave visits (seed 003,
// section 3.1.2). `visit` may change the wall of the node it is given.
template <class Tree, class Visit>
void along_wall(Tree& tree, std::size_t top, int side, const Site_point& w, const Visit& visit) {
  std::vector<std::size_t> stack{top};
  while (!stack.empty()) {
    const std::size_t x = stack.back();
    stack.pop_back();
    const Bsp_node& q = tree.nodes[x];
    if (wall(q.cell, side) != w) continue;
    if (q.kind != Cut_kind::leaf)
      for (const std::int32_t c : q.child) stack.push_back(static_cast<std::size_t>(c));
    visit(x);
  }
}

// The cuts a cell is bounded by: its walls as point cuts, its floor and
// roof as edge cuts (for the keys a step would decide against them).
inline std::vector<Bsp_node> cell_sides(const Cell& c) {
  std::vector<Bsp_node> sides;
  for (const std::optional<Site_point>& w : {c.left, c.right})
    if (w) {
      sides.emplace_back().kind = Cut_kind::vertex;
      sides.back().point = *w;
    }
  for (const std::optional<std::uint32_t>& j : {c.floor, c.roof})
    if (j) {
      sides.emplace_back().kind = Cut_kind::edge;
      sides.back().segment = *j;
    }
  return sides;
}

// The cell of child `side` of a cut (0: left or below, 1: right or above)
// whose own cell is `c`: the cut's line becomes the child's wall, floor or
// roof.
inline Cell child_cell(Cell c, const Bsp_node& cut, int side) {
  if (cut.kind == Cut_kind::edge) (side ? c.floor : c.roof) = cut.segment;
  else (side ? c.left : c.right) = cut.point;
  return c;
}

struct Bsp_counts {
  std::size_t vertex_cuts = 0, intersection_cuts = 0, edge_cuts = 0;
  std::size_t nodes = 0, leaves = 0;
  std::size_t height = 0;  // nodes on the longest root-to-leaf path
};

// The tree. A kinetic run edits it in place, so slots of `nodes` may be
// unused: everything here walks from the root.
class Cylindrical_bsp {
public:
  std::vector<Bsp_node> nodes;  // nodes[0] is the root

  Bsp_counts counts() const;
  // The subtree of `root` as nested parentheses, pre-order, children
  // left/below first: "(V s3.0 L R)" a vertex cut through endpoint 0 of
  // segment 3, "(I s1xs4 L R)" an intersection cut, "(E s2 B A)" an edge
  // cut, and "." a leaf. Golden tests compare this text.
  std::string text(std::size_t root = 0) const;
  // The nodes of the subtree of `root`, pre-order.
  std::vector<std::size_t> preorder(std::size_t root = 0) const;
  // The nodes of the edge cuts of segment s (its fragments).
  std::vector<std::size_t> fragments(std::size_t s) const;
  // The same tree with its nodes numbered in pre-order, no unused slot.
  Cylindrical_bsp compacted() const;
};

// The signs a construction decided contradict each other: a point located
// into the region its own cut bounds, or a crossing found below a node that
// it does not reach from the root. A bug in the exact kernel; rounding in the
// floating-point ones, which Kinetic_segment_bsp repairs.
struct Bsp_contradiction : std::logic_error {
  using std::logic_error::logic_error;
};

template <class K>
Cylindrical_bsp build_cylindrical_bsp(const Segment_predicates<K>& pred, const typename K::Time& t);

// A cell at t: a proper trapezoid (the left wall left of the right one, the
// roof above the floor at each wall, or meeting it there at their crossing,
// but not at both walls), or how it is not.
enum class Cell_shape { proper, walls_crossed, roof_below_floor, pinched };

template <class K>
Cell_shape cell_shape(const Cell& c, const Segment_predicates<K>& pred, const typename K::Time& t);

// Violations of the BSP's invariants at t, checked against the tree without
// its construction's reasoning: every cell a non-empty trapezoid whose walls
// and floor and roof are those its ancestors' cuts give it; every fragment
// crossing its cell from wall to wall between floor and roof; the fragments
// of each segment tiling it in x order from one endpoint to the other; no
// segment meeting the interior of a leaf. Empty when the tree is sound.
template <class K>
std::vector<std::string> bsp_violations(const Cylindrical_bsp& bsp, const Segment_predicates<K>& pred,
                                        const typename K::Time& t);

}  // namespace kvd::segments
