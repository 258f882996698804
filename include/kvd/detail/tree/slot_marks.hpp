// Flags per node slot for one pass over a few nodes of a large tree: set
// sparsely, and cleared in the time of the flags set, so that a batch pays
// for the nodes it looks at, not for the size of the tree.
#pragma once

#include <cstddef>
#include <vector>

namespace kvd::tree {

class Slot_marks {
public:
  bool operator[](std::size_t slot) const { return slot < flags_.size() && flags_[slot]; }
  // Sets the mark; whether it was unset.
  bool set(std::size_t slot) {
    if (slot >= flags_.size()) flags_.resize(slot + 1 + slot / 2);
    if (flags_[slot]) return false;
    flags_[slot] = 1;
    set_.push_back(slot);
    return true;
  }
  // The slots marked since the last clear, in the order they were set.
  const std::vector<std::size_t>& marked() const { return set_; }
  void clear() {
    for (std::size_t slot : set_) flags_[slot] = 0;
    set_.clear();
  }

private:
  std::vector<char> flags_;
  std::vector<std::size_t> set_;
};

}  // namespace kvd::tree
