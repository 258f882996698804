// Arrays indexed by node slot grow with the tree. Sized exactly when a tree
// is built (assign leaves no spare capacity), the first node a batch adds
// would move the whole array, and that batch would pay for the size of the
// tree: room for half as many slots again is taken where such an array is
// sized for a whole tree. Later growth is the vector's own, geometric.
#pragma once

#include <cstddef>
#include <vector>

namespace kvd::tree {

template <class T>
void room_for(std::vector<T>& v, std::size_t slots) {
  if (slots > v.capacity()) v.reserve(slots + slots / 2);
}

}  // namespace kvd::tree
