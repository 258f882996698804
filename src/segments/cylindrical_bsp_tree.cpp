// What a cylindrical BSP says about itself: counts, text, fragments.
#include <algorithm>
#include <string>

#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

std::vector<std::size_t> Cylindrical_bsp::preorder(std::size_t root) const {
  // An explicit stack: degenerate trees may be deep.
  std::vector<std::size_t> order, stack{root};
  while (!stack.empty()) {
    const std::size_t n = stack.back();
    stack.pop_back();
    order.push_back(n);
    if (nodes[n].kind == Cut_kind::leaf) continue;
    stack.push_back(static_cast<std::size_t>(nodes[n].child[1]));
    stack.push_back(static_cast<std::size_t>(nodes[n].child[0]));
  }
  return order;
}

Bsp_counts Cylindrical_bsp::counts() const {
  Bsp_counts c;
  std::vector<std::size_t> depth(nodes.size(), 0);
  for (const std::size_t n : preorder()) {
    ++c.nodes;
    depth[n] = nodes[n].parent < 0 ? 1 : depth[static_cast<std::size_t>(nodes[n].parent)] + 1;
    c.height = std::max(c.height, depth[n]);
    switch (nodes[n].kind) {
      case Cut_kind::leaf: ++c.leaves; break;
      case Cut_kind::vertex: ++c.vertex_cuts; break;
      case Cut_kind::intersection: ++c.intersection_cuts; break;
      case Cut_kind::edge: ++c.edge_cuts; break;
    }
  }
  return c;
}

namespace {

void write(const Cylindrical_bsp& b, std::size_t n, std::string& out) {
  const Bsp_node& node = b.nodes[n];
  if (node.kind == Cut_kind::leaf) {
    out += '.';
    return;
  }
  out += "(" + cut_name(node);
  for (const auto k : node.child) {
    out += ' ';
    write(b, static_cast<std::size_t>(k), out);
  }
  out += ')';
}

}  // namespace

std::string cut_name(const Bsp_node& n) {
  switch (n.kind) {
    case Cut_kind::leaf: return ".";
    case Cut_kind::vertex: return "V s" + std::to_string(n.point.a / 2) + "." + std::to_string(n.point.a % 2);
    case Cut_kind::intersection: return "I s" + std::to_string(n.point.a) + "xs" + std::to_string(n.point.b);
    case Cut_kind::edge: return "E s" + std::to_string(n.segment);
  }
  return ".";
}

std::string Cylindrical_bsp::text(std::size_t root) const {
  std::string out;
  write(*this, root, out);
  return out;
}

std::vector<std::size_t> Cylindrical_bsp::fragments(std::size_t s) const {
  std::vector<std::size_t> r;
  for (const std::size_t n : preorder())
    if (nodes[n].kind == Cut_kind::edge && nodes[n].segment == s) r.push_back(n);
  return r;
}

Cylindrical_bsp Cylindrical_bsp::compacted() const {
  const std::vector<std::size_t> order = preorder();
  std::vector<std::int32_t> id(nodes.size(), -1);
  for (std::size_t i = 0; i < order.size(); ++i) id[order[i]] = static_cast<std::int32_t>(i);
  Cylindrical_bsp c;
  for (const std::size_t n : order) {
    Bsp_node node = nodes[n];
    if (node.parent >= 0) node.parent = id[static_cast<std::size_t>(node.parent)];
    if (node.kind != Cut_kind::leaf)
      for (auto& k : node.child) k = id[static_cast<std::size_t>(k)];
    c.nodes.push_back(node);
  }
  return c;
}

}  // namespace kvd::segments
