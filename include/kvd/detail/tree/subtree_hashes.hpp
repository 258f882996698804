// The structure hash kept per subtree (tree/compare.hpp defines it): each
// node's hash covers its subtree, so after an edit only the nodes it
// changed and their paths to the root are hashed again.
#pragma once

#include <string>
#include <vector>

#include "kvd/detail/tree/tree_links.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::tree {

class Subtree_hashes {
public:
  Subtree_hashes() = default;
  // Every node of t hashed afresh.
  explicit Subtree_hashes(const Kvd_tree& t) { reset(t); }
  void reset(const Kvd_tree& t);
  // t after edits that re-cut, relinked or created exactly the nodes
  // `changed` (released slots may be listed too), from the tree these
  // hashes were of, `links` being t's already: their hashes and their
  // ancestors' are made again.
  void update(const Kvd_tree& t, const Tree_links& links, const std::vector<int>& changed);
  // The structure hash of the tree: tree::structure_hash(t).
  const std::string& root() const;

private:
  // Hashes the nodes under `from` for which stale(slot) holds, children first.
  template <class Stale>
  void rehash(const Kvd_tree& t, int from, const Stale& stale);

  std::vector<std::string> hash_;  // per node slot, of its subtree (lowercase hex)
  std::string root_;
  Slot_marks stale_;  // update's, cleared after each
};

}  // namespace kvd::tree
