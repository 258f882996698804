// The triangle priority order (thesis 5.3.2; the scene format's "Priority
// order"), with the project's own documented generator.
//
// SplitMix64 (Steele, Lea, Flood 2014): state += 0x9e3779b97f4a7c15;
// z = state; z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9;
// z = (z ^ (z >> 27)) * 0x94d049bb133111eb; return z ^ (z >> 31).
// The shuffle is Fisher–Yates from the back: for i = n-1 down to 1,
// j = next() mod (i + 1), swap(a[i], a[j]). (The modulo's bias is below
// n / 2^64 and, more to the point, it is part of the definition: any
// implementation following these lines gets the same order.)
#pragma once

#include <cstdint>
#include <vector>

namespace kvd::scene {

class Split_mix64 {
public:
  explicit Split_mix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  // A random integer in [lo, hi]: lo + next() mod (hi - lo + 1), by definition.
  long between(long lo, long hi);

private:
  std::uint64_t state_;
};

// The ids 0..n-1 shuffled as documented above.
std::vector<std::size_t> shuffled_ids(std::size_t n, std::uint64_t seed);

}  // namespace kvd::scene
