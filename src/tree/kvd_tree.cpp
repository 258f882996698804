#include "kvd/tree/kvd_tree.hpp"

#include <algorithm>
#include <utility>

namespace kvd::tree {

Tree_statistics Kvd_tree::statistics() const {
  Tree_statistics s;
  s.nodes = nodes.size();
  for (const auto& n : nodes) {
    switch (n.cut.kind) {
      case Symbolic_plane::Kind::P: ++s.p_nodes; break;
      case Symbolic_plane::Kind::E: ++s.e_nodes; break;
      case Symbolic_plane::Kind::T: ++s.t_nodes; break;
    }
  }
  // Depth-first with an explicit stack: trees can be deep.
  std::vector<std::pair<int, std::size_t>> stack;
  if (root >= 0) stack.emplace_back(root, 1);
  while (!stack.empty()) {
    const auto [i, depth] = stack.back();
    stack.pop_back();
    s.height = std::max(s.height, depth);
    const Node& n = nodes[static_cast<std::size_t>(i)];
    if (n.left >= 0) stack.emplace_back(n.left, depth + 1);
    if (n.right >= 0) stack.emplace_back(n.right, depth + 1);
  }
  return s;
}

}  // namespace kvd::tree
