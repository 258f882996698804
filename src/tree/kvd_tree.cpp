#include "kvd/tree/kvd_tree.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

namespace kvd::tree {

Tree_statistics Kvd_tree::statistics(int subtree) const {
  // Depth-first with an explicit stack: trees can be deep.
  Tree_statistics s;
  std::vector<std::pair<int, std::size_t>> stack;
  if (subtree >= 0) stack.emplace_back(subtree, 1);
  while (!stack.empty()) {
    const auto [i, depth] = stack.back();
    stack.pop_back();
    const Node& n = nodes[static_cast<std::size_t>(i)];
    ++s.nodes;
    switch (n.cut.kind) {
      case Symbolic_plane::Kind::P: ++s.p_nodes; break;
      case Symbolic_plane::Kind::E: ++s.e_nodes; break;
      case Symbolic_plane::Kind::T: ++s.t_nodes; break;
    }
    s.height = std::max(s.height, depth);
    if (n.left >= 0) stack.emplace_back(n.left, depth + 1);
    if (n.right >= 0) stack.emplace_back(n.right, depth + 1);
  }
  return s;
}

std::string to_string(const Fragment& f) {
  if (const auto* v = std::get_if<Symbolic_vertex>(&f)) return "[" + symbolic::to_string(*v) + "]";
  if (const auto* e = std::get_if<Edge_fragment>(&f))
    return "[" + symbolic::to_string(e->a) + " " + symbolic::to_string(e->b) + " " + symbolic::to_string(e->edge) + "]";
  const auto& t = std::get<Triangle_fragment>(f);
  std::string r = "[";
  for (std::size_t i = 0; i < t.corners.size(); ++i)
    r += (i ? ", " : "") + symbolic::to_string(t.corners[i]) + " " + symbolic::to_string(t.sides[i]);
  return r + "]";
}

std::string Kvd_tree::describe() const {
  std::string out;
  std::vector<std::tuple<int, std::size_t, char>> stack;
  if (root >= 0) stack.emplace_back(root, 0, ' ');
  while (!stack.empty()) {
    const auto [i, depth, mark] = stack.back();
    stack.pop_back();
    const Node& n = nodes[static_cast<std::size_t>(i)];
    out += std::string(2 * depth, ' ') + (depth ? std::string(1, mark) + " " : "") + symbolic::to_string(n.cut) + " " +
           to_string(n.fragment) + "\n";
    if (n.right >= 0) stack.emplace_back(n.right, depth + 1, '+');
    if (n.left >= 0) stack.emplace_back(n.left, depth + 1, '-');
  }
  return out;
}

}  // namespace kvd::tree
