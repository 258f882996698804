// What a cylindrical BSP says about itself: counts, text, fragments.
#include <algorithm>
#include <string>

#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

Bsp_counts Cylindrical_bsp::counts() const {
  Bsp_counts c;
  c.nodes = nodes.size();
  for (const Bsp_node& n : nodes) {
    switch (n.kind) {
      case Cut_kind::leaf: ++c.leaves; break;
      case Cut_kind::vertex: ++c.vertex_cuts; break;
      case Cut_kind::intersection: ++c.intersection_cuts; break;
      case Cut_kind::edge: ++c.edge_cuts; break;
    }
  }
  // Depth first with an explicit stack: degenerate trees may be deep.
  std::vector<std::pair<std::size_t, std::size_t>> stack{{0, 1}};
  while (!stack.empty()) {
    const auto [n, depth] = stack.back();
    stack.pop_back();
    c.height = std::max(c.height, depth);
    if (nodes[n].kind == Cut_kind::leaf) continue;
    for (const auto k : nodes[n].child) stack.emplace_back(static_cast<std::size_t>(k), depth + 1);
  }
  return c;
}

namespace {

void write(const Cylindrical_bsp& b, std::size_t n, std::string& out) {
  const Bsp_node& node = b.nodes[n];
  switch (node.kind) {
    case Cut_kind::leaf: out += '.'; return;
    case Cut_kind::vertex:
      out += "(V s" + std::to_string(node.point.a / 2) + "." + std::to_string(node.point.a % 2);
      break;
    case Cut_kind::intersection:
      out += "(I s" + std::to_string(node.point.a) + "xs" + std::to_string(node.point.b);
      break;
    case Cut_kind::edge: out += "(E s" + std::to_string(node.segment); break;
  }
  for (const auto k : node.child) {
    out += ' ';
    write(b, static_cast<std::size_t>(k), out);
  }
  out += ')';
}

}  // namespace

std::string Cylindrical_bsp::text() const {
  std::string out;
  write(*this, 0, out);
  return out;
}

std::vector<std::size_t> Cylindrical_bsp::fragments(std::size_t s) const {
  std::vector<std::size_t> r;
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (nodes[n].kind == Cut_kind::edge && nodes[n].segment == s) r.push_back(n);
  return r;
}

}  // namespace kvd::segments
