#include "tree_table.hpp"

#include <functional>

namespace kvd::view {

std::vector<int> Tree_table::add(const tree::Kvd_tree& tree) {
  std::vector<int> entry(tree.nodes.size(), -1);
  const std::function<int(int)> visit = [&](int i) {
    if (i < 0) return -1;
    const tree::Node& n = tree.nodes[static_cast<std::size_t>(i)];
    const int left = visit(n.left), right = visit(n.right);
    return entry[static_cast<std::size_t>(i)] =
               intern({symbolic::to_string(n.cut), tree::to_string(n.fragment), left, right});
  };
  visit(tree.root);
  return entry;
}

int Tree_table::add(const segments::Cylindrical_bsp& tree) {
  using segments::Cut_kind;
  // Children before parents: the preorder backwards (no recursion, as
  // degenerate trees may be deep).
  const std::vector<std::size_t> order = tree.preorder();
  std::vector<int> entry(tree.nodes.size(), -1);
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const segments::Bsp_node& n = tree.nodes[*it];
    Entry e{segments::cut_name(n), "", -1, -1};
    if (n.kind != Cut_kind::leaf) {
      e.left = entry[segments::child(n, 0)];
      e.right = entry[segments::child(n, 1)];
    }
    entry[*it] = intern(std::move(e));
  }
  return entry[order.front()];
}

int Tree_table::intern(Entry e) {
  const auto [it, fresh] =
      ids_.try_emplace(std::tuple(e.cut, e.fragment, e.left, e.right), static_cast<int>(entries_.size()));
  if (fresh) entries_.push_back(std::move(e));
  return it->second;
}

}  // namespace kvd::view
