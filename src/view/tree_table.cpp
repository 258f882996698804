#include "tree_table.hpp"

#include <functional>

namespace kvd::view {

std::vector<int> Tree_table::add(const tree::Kvd_tree& tree) {
  std::vector<int> entry(tree.nodes.size(), -1);
  const std::function<int(int)> visit = [&](int i) {
    if (i < 0) return -1;
    const tree::Node& n = tree.nodes[static_cast<std::size_t>(i)];
    const int left = visit(n.left), right = visit(n.right);
    Entry e{symbolic::to_string(n.cut), tree::to_string(n.fragment), left, right};
    const auto [it, fresh] = ids_.try_emplace(std::tuple(e.cut, e.fragment, left, right), static_cast<int>(entries_.size()));
    if (fresh) entries_.push_back(std::move(e));
    return entry[static_cast<std::size_t>(i)] = it->second;
  };
  visit(tree.root);
  return entry;
}

}  // namespace kvd::view
