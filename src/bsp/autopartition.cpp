#include "kvd/bsp/autopartition.hpp"

#include <algorithm>
#include <utility>

namespace kvd::bsp {

namespace {

// Newell's normal: exact for a planar polygon, whatever its collinear corners.
std::array<mpq_class, 4> plane_of(const Polygon& p) {
  V3 n{0, 0, 0};
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const V3& a = p.points[i];
    const V3& b = p.points[(i + 1) % p.points.size()];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return {n[0], n[1], n[2], -(n[0] * p.points[0][0] + n[1] * p.points[0][1] + n[2] * p.points[0][2])};
}

int side(const std::array<mpq_class, 4>& h, const V3& x) {
  return sgn(mpq_class(h[0] * x[0] + h[1] * x[1] + h[2] * x[2] + h[3]));
}

// The part of p on side `keep` of h (corners on the plane kept; new corners
// where edges cross, the new edge along h marked).
Polygon clip(const Polygon& p, const std::vector<int>& s, int keep, const std::array<mpq_class, 4>& h) {
  Polygon out{p.triangle, {}, {}};
  const std::size_t n = p.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const int si = s[i] * keep, sj = s[j] * keep;
    auto crossing = [&] {
      const mpq_class fi = h[0] * p.points[i][0] + h[1] * p.points[i][1] + h[2] * p.points[i][2] + h[3];
      const mpq_class fj = h[0] * p.points[j][0] + h[1] * p.points[j][1] + h[2] * p.points[j][2] + h[3];
      const mpq_class u = fi / (fi - fj);
      V3 x;
      for (std::size_t k = 0; k < 3; ++k) x[k] = p.points[i][k] + u * (p.points[j][k] - p.points[i][k]);
      return x;
    };
    if (si >= 0) {
      out.points.push_back(p.points[i]);
      out.marked.push_back(sj < 0 && si == 0 ? true : bool(p.marked[i]));
      if (si > 0 && sj < 0) {
        out.points.push_back(crossing());
        out.marked.push_back(true);
      }
    } else if (sj > 0) {
      out.points.push_back(crossing());
      out.marked.push_back(p.marked[i]);
    }
  }
  return out;
}

class Builder {
public:
  explicit Builder(Tree& t) : t_(t) {}

  int build(std::vector<Polygon> list) {
    if (list.empty()) return -1;
    // A free split if there is one, else the first in priority order.
    std::size_t pick = 0;
    for (std::size_t i = 0; i < list.size(); ++i)
      if (std::all_of(list[i].marked.begin(), list[i].marked.end(), [](bool m) { return m; })) {
        pick = i;
        break;
      }
    Node node;
    node.plane = plane_of(list[pick]);
    std::vector<Polygon> neg, pos;
    for (auto& p : list) {
      std::vector<int> s;
      bool any_neg = false, any_pos = false;
      for (const auto& x : p.points) {
        s.push_back(side(node.plane, x));
        any_neg = any_neg || s.back() < 0;
        any_pos = any_pos || s.back() > 0;
      }
      if (!any_neg && !any_pos) node.polygons.push_back(std::move(p));
      else if (!any_pos) neg.push_back(std::move(p));
      else if (!any_neg) pos.push_back(std::move(p));
      else {
        neg.push_back(clip(p, s, -1, node.plane));
        pos.push_back(clip(p, s, +1, node.plane));
      }
    }
    t_.nodes.push_back(std::move(node));
    const int i = static_cast<int>(t_.nodes.size()) - 1;
    const int l = build(std::move(neg));
    const int r = build(std::move(pos));
    t_.nodes[static_cast<std::size_t>(i)].left = l;
    t_.nodes[static_cast<std::size_t>(i)].right = r;
    return i;
  }

private:
  Tree& t_;
};

}  // namespace

std::size_t Tree::fragments() const {
  std::size_t n = 0;
  for (const auto& node : nodes) n += node.polygons.size();
  return n;
}

std::size_t Tree::height() const {
  std::size_t h = 0;
  std::vector<std::pair<int, std::size_t>> stack;
  if (root >= 0) stack.emplace_back(root, 1);
  while (!stack.empty()) {
    const auto [i, d] = stack.back();
    stack.pop_back();
    h = std::max(h, d);
    const Node& n = nodes[static_cast<std::size_t>(i)];
    if (n.left >= 0) stack.emplace_back(n.left, d + 1);
    if (n.right >= 0) stack.emplace_back(n.right, d + 1);
  }
  return h;
}

Tree autopartition(const scene::Scene& s, const mpq_class& t) {
  std::vector<Polygon> list;
  for (std::size_t tri : s.priority_order) {
    Polygon p{tri, {}, {false, false, false}};
    for (std::size_t v : s.triangles[tri]) {
      const auto x = s.position_at(v, t);
      p.points.push_back({x[0] / x[3], x[1] / x[3], x[2] / x[3]});
    }
    list.push_back(std::move(p));
  }
  Tree tree;
  tree.root = Builder(tree).build(std::move(list));
  return tree;
}

std::vector<const Polygon*> back_to_front(const Tree& tree, const V3& view) {
  std::vector<const Polygon*> out;
  std::vector<std::pair<int, bool>> stack;
  if (tree.root >= 0) stack.emplace_back(tree.root, false);
  while (!stack.empty()) {
    const auto [i, expanded] = stack.back();
    stack.pop_back();
    const Node& n = tree.nodes[static_cast<std::size_t>(i)];
    if (expanded) {
      for (const auto& p : n.polygons) out.push_back(&p);
      continue;
    }
    const int s = side(n.plane, view);
    const int near = s > 0 ? n.right : n.left, far = s > 0 ? n.left : n.right;
    if (near >= 0) stack.emplace_back(near, false);
    stack.emplace_back(i, true);
    if (far >= 0) stack.emplace_back(far, false);
  }
  return out;
}

}  // namespace kvd::bsp
