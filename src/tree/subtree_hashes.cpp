#include "kvd/detail/tree/subtree_hashes.hpp"

#include <cstddef>
#include <utility>

#include "kvd/detail/tree/slot_room.hpp"
#include "kvd/detail/tree/digest.hpp"
#include "kvd/tree/compare.hpp"

namespace kvd::tree {

namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

}  // namespace

void Subtree_hashes::reset(const Kvd_tree& t) {
  room_for(hash_, t.nodes.size());
  hash_.assign(t.nodes.size(), {});
  // Every slot is stale; released ones are never reached from the root.
  rehash(t, t.root, [](std::size_t) { return true; });
}

void Subtree_hashes::update(const Kvd_tree& t, const Tree_links& links, const std::vector<int>& changed) {
  hash_.resize(t.nodes.size());
  for (int n : changed)
    if (links.live(n)) links.mark_path(n, stale_);
  rehash(t, t.root, [&](std::size_t slot) { return stale_[slot]; });
  stale_.clear();
}

template <class Stale>
void Subtree_hashes::rehash(const Kvd_tree& t, int from, const Stale& stale) {
  // Iterative post-order through the stale nodes only: the stale set holds
  // every ancestor of its nodes, so each is reached from the root.
  std::vector<std::pair<int, bool>> stack;
  if (from >= 0 && stale(at(from))) stack.emplace_back(from, false);
  while (!stack.empty()) {
    auto [n, children_done] = stack.back();
    stack.pop_back();
    const Node& node = t.nodes[at(n)];
    if (!children_done) {
      stack.emplace_back(n, true);
      for (int c : {node.right, node.left})
        if (c >= 0 && stale(at(c))) stack.emplace_back(c, false);
      continue;
    }
    hash_[at(n)] = node_hash(node, node.left >= 0 ? hash_[at(node.left)] : std::string(),
                             node.right >= 0 ? hash_[at(node.right)] : std::string());
  }
  root_ = t.root >= 0 ? hash_[at(t.root)] : sha256_hex("");
}

const std::string& Subtree_hashes::root() const { return root_; }

}  // namespace kvd::tree
