// The augmented BSP (kvd/segments/augmented_bsp.hpp): written from a
// cylindrical BSP at an instant, and read back.
#include "kvd/segments/augmented_bsp.hpp"

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/segments/bsp_builder.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

namespace {

// The side (0 left, 1 right) of an intersection cut's point where the
// earlier segment's marked endpoint lies: the crossing lies on that segment
// between its endpoints, so it is the marked endpoint's side of the other.
template <class K>
int marked_side(const Segment_predicates<K>& pred, std::uint32_t s, const typename K::Time& t) {
  return pred.compare_x(Site_point::endpoint(2 * s), Site_point::endpoint(2 * s + 1), t).sign > 0 ? 1 : 0;
}

// The earlier in priority of a crossing's two segments.
std::uint32_t earlier(const Site_point& p, const std::vector<std::size_t>& rank) {
  return rank[p.a] < rank[p.b] ? p.a : p.b;
}

void write(const Augmented_bsp& a, std::size_t n, std::string& out) {
  const Augmented_node& node = a.nodes[n];
  switch (node.kind) {
    case Augmented_kind::leaf: out += '.'; return;
    case Augmented_kind::ternary: out += "(T " + point_name(node.point) + " " + point_name(node.second); break;
    case Augmented_kind::vertex: out += "(V " + point_name(node.point); break;
    case Augmented_kind::intersection: out += "(I " + point_name(node.point); break;
    case Augmented_kind::edge: out += "(E s" + std::to_string(node.segment); break;
  }
  for (const std::int32_t c : node.child)
    if (c >= 0) {
      out += ' ';
      write(a, static_cast<std::size_t>(c), out);
    }
  out += ')';
}

}  // namespace

std::string Augmented_bsp::text() const {
  std::string out;
  write(*this, 0, out);
  return out;
}

Augmented_counts Augmented_bsp::counts() const {
  Augmented_counts c;
  for (const Augmented_node& n : nodes) switch (n.kind) {
      case Augmented_kind::leaf: ++c.leaves; break;
      case Augmented_kind::ternary: ++c.ternary; break;
      case Augmented_kind::vertex:
      case Augmented_kind::intersection: ++c.binary_point_cuts; break;
      case Augmented_kind::edge: ++c.edge_cuts; break;
    }
  return c;
}

template <class K>
Augmented_bsp augment(const Cylindrical_bsp& bsp, const Segment_predicates<K>& pred, const typename K::Time& t) {
  const std::vector<std::size_t>& rank = pred.scene().rank;
  Augmented_bsp out;
  // Pre-order through an explicit stack (degenerate trees may be deep): a
  // node of B, and the place in its augmented parent that it fills.
  struct Task {
    std::size_t node;
    std::int32_t parent;
    int slot;
  };
  std::vector<Task> stack{{0, -1, 0}};
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    const Bsp_node& n = bsp.nodes[task.node];
    Augmented_node a;
    std::vector<std::int32_t> children;  // of B, in the augmented node's order
    switch (n.kind) {
      case Cut_kind::leaf: break;
      case Cut_kind::edge:
        a.kind = Augmented_kind::edge;
        a.segment = n.segment;
        children = {n.child[0], n.child[1]};
        break;
      case Cut_kind::vertex:
      case Cut_kind::intersection: {
        a.point = n.point;
        // The segment's second cut in this leaf of B_{i-1}: a point cut
        // child put by the same insertion (it puts at most two there).
        const std::size_t r = point_rank(n.point, rank);
        int d = -1;
        for (int side = 0; side < 2; ++side) {
          const Bsp_node& c = bsp.nodes[static_cast<std::size_t>(n.child[side])];
          if (!point_cut(c) || point_rank(c.point, rank) != r) continue;
          if (d >= 0)  // a third point cut of one insertion in one cell: signs that contradict each other
            throw Bsp_contradiction("augment: both children of the cut through " + point_name(n.point) +
                                    " are cuts of the same insertion");
          d = side;
        }
        if (d >= 0) {
          const Bsp_node& c = bsp.nodes[static_cast<std::size_t>(n.child[d])];
          a.kind = Augmented_kind::ternary;
          a.second = c.point;
          a.segment = static_cast<std::uint32_t>(pred.scene().priority_order[r]);
          children = d == 1 ? std::vector{n.child[0], c.child[0], c.child[1]}
                            : std::vector{c.child[0], c.child[1], n.child[1]};
        } else if (n.kind == Cut_kind::intersection) {
          a.kind = Augmented_kind::intersection;
          a.segment = earlier(n.point, rank);
          const int m = marked_side(pred, a.segment, t);
          children = {n.child[m], n.child[1 - m]};
        } else {
          a.kind = Augmented_kind::vertex;
          children = {n.child[0], n.child[1]};
        }
        break;
      }
    }
    const auto at = static_cast<std::int32_t>(out.nodes.size());
    out.nodes.push_back(a);
    if (task.parent >= 0) out.nodes[static_cast<std::size_t>(task.parent)].child[static_cast<std::size_t>(task.slot)] = at;
    for (std::size_t k = children.size(); k-- > 0;)
      stack.push_back({static_cast<std::size_t>(children[k]), at, static_cast<int>(k)});
  }
  return out;
}

template <class K>
Cylindrical_bsp expand(const Augmented_bsp& a, const Segment_predicates<K>& pred, const typename K::Time& t) {
  Cylindrical_bsp b;
  const auto make = [&b](std::int32_t parent, const Cell& cell) {
    Bsp_node x;
    x.parent = parent;
    x.cell = cell;
    b.nodes.push_back(x);
    return b.nodes.size() - 1;
  };
  // Gives the leaf `at` a cut and two leaf children: those children.
  const auto cut = [&](std::size_t at, Cut_kind kind, const Site_point& p, std::uint32_t s) {
    b.nodes[at].kind = kind;
    b.nodes[at].point = p;
    b.nodes[at].segment = s;
    // make may move the nodes: no reference is held across it.
    const std::size_t l = make(static_cast<std::int32_t>(at), child_cell(b.nodes[at].cell, b.nodes[at], 0));
    const std::size_t r = make(static_cast<std::int32_t>(at), child_cell(b.nodes[at].cell, b.nodes[at], 1));
    b.nodes[at].child[0] = static_cast<std::int32_t>(l);
    b.nodes[at].child[1] = static_cast<std::int32_t>(r);
    return std::array<std::size_t, 2>{l, r};
  };
  // Cuts the leaf `at` with the vertical line through p.
  const auto split = [&](std::size_t at, const Site_point& p) {
    return cut(at, p.kind == Site_point::Kind::endpoint ? Cut_kind::vertex : Cut_kind::intersection, p, 0);
  };
  make(-1, Cell{});
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, 0}};  // an augmented node, the leaf of B it fills
  while (!stack.empty()) {
    const std::size_t i = stack.back().first, at = stack.back().second;
    stack.pop_back();
    const Augmented_node& n = a.nodes[i];
    const auto fill = [&](std::size_t k, std::size_t slot) { stack.emplace_back(static_cast<std::size_t>(n.child[k]), slot); };
    switch (n.kind) {
      case Augmented_kind::leaf: break;
      case Augmented_kind::edge: {
        const auto s = cut(at, Cut_kind::edge, {}, n.segment);
        fill(0, s[0]);
        fill(1, s[1]);
        break;
      }
      case Augmented_kind::vertex: {
        const auto s = split(at, n.point);
        fill(0, s[0]);
        fill(1, s[1]);
        break;
      }
      case Augmented_kind::intersection: {
        const int m = marked_side(pred, n.segment, t);
        const auto s = split(at, n.point);
        fill(0, s[static_cast<std::size_t>(m)]);
        fill(1, s[static_cast<std::size_t>(1 - m)]);
        break;
      }
      case Augmented_kind::ternary: {
        const int d = pred.compare_x(n.second, n.point, t).sign > 0 ? 1 : 0;
        const auto s = split(at, n.point);
        const auto c = split(s[static_cast<std::size_t>(d)], n.second);
        fill(0, d == 1 ? s[0] : c[0]);
        fill(1, d == 1 ? c[0] : c[1]);
        fill(2, d == 1 ? c[1] : s[1]);
        break;
      }
    }
  }
  return b.compacted();
}

#define KVD_INSTANTIATE_AUGMENTED_BSP(K)                                                                             \
  template Augmented_bsp augment<K>(const Cylindrical_bsp&, const Segment_predicates<K>&, const typename K::Time&); \
  template Cylindrical_bsp expand<K>(const Augmented_bsp&, const Segment_predicates<K>&, const typename K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_AUGMENTED_BSP)

}  // namespace kvd::segments
