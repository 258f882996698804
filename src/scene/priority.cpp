#include "kvd/detail/scene/priority.hpp"

#include <numeric>
#include <utility>

namespace kvd::scene {

std::uint64_t Split_mix64::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

long Split_mix64::between(long lo, long hi) {
  return lo + static_cast<long>(next() % static_cast<std::uint64_t>(hi - lo + 1));
}

std::vector<std::size_t> shuffled_ids(std::size_t n, std::uint64_t seed) {
  std::vector<std::size_t> a(n);
  std::iota(a.begin(), a.end(), std::size_t(0));
  Split_mix64 g(seed);
  for (std::size_t i = n; i-- > 1;) std::swap(a[i], a[g.next() % (i + 1)]);
  return a;
}

}  // namespace kvd::scene
