// The trees of a run's instants as one table of distinct subtrees
// (hash-consing): a subtree that two instants share is one entry, so a page
// stores it once, and the entries of an instant's tree that the instant
// before lacks are the nodes its batch changed (with their ancestors). The
// KVD's trees and the cylindrical BSPs of segments alike (a table holds
// one kind).
#pragma once

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "kvd/segments/cylindrical_bsp.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::view {

class Tree_table {
public:
  struct Entry {
    std::string cut;       // "E(2)"
    std::string fragment;  // "[SV(e2,P1) SV(v0) SE(e2)]"
    int left = -1, right = -1;
  };
  // The entry of each node of `tree`, by node index (-1 for the free
  // slots), adding the subtrees not seen before.
  std::vector<int> add(const tree::Kvd_tree& tree);
  // The entry of the root of a cylindrical BSP, its nodes' cuts as its text
  // writes them ("V s3.0", "I s1xs4", "E s2"; a leaf ".", without
  // children), with no fragment.
  int add(const segments::Cylindrical_bsp& tree);
  const std::vector<Entry>& entries() const { return entries_; }

private:
  int intern(Entry e);

  std::map<std::tuple<std::string, std::string, int, int>, int> ids_;
  std::vector<Entry> entries_;
};

}  // namespace kvd::view
