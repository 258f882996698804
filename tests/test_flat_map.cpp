// The flat hash table of the run's large tables (kvd::detail::Flat_map)
// against std::unordered_map under the same random insertions, erasures,
// lookups and values taken out: the same elements after every step, also
// when every key hashes alike (one run around the whole table) or to a few
// values (runs that wrap past the end of the array and meet).
#include <catch2/catch.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <unordered_map>

#include "kvd/detail/flat_map.hpp"

namespace {

template <int Distinct>
struct Few_hashes {  // Distinct == 0: the key itself
  std::size_t operator()(std::uint64_t k) const { return Distinct == 0 ? k : k % Distinct; }
};

template <class Hash>
void same_as_reference(std::uint64_t key_range, int steps, unsigned seed) {
  kvd::detail::Flat_map<std::uint64_t, int, Hash> flat;
  std::unordered_map<std::uint64_t, int> reference;
  std::mt19937_64 random(seed);
  for (int step = 0; step < steps; ++step) {
    const std::uint64_t key = random() % key_range;
    switch (random() % 5) {
      case 0:
      case 1: {
        const auto [value, fresh] = flat.try_emplace(key);
        const auto [it, made] = reference.try_emplace(key, 0);
        REQUIRE(fresh == made);
        REQUIRE(*value == it->second);
        *value = it->second = step;
        break;
      }
      case 2:
        flat.erase(key);
        reference.erase(key);
        break;
      case 3: {
        const int* value = flat.find(key);
        const auto it = reference.find(key);
        REQUIRE((value != nullptr) == (it != reference.end()));
        if (value) REQUIRE(*value == it->second);
        if (it == reference.end()) REQUIRE_THROWS_AS(flat.at(key), std::out_of_range);
        else REQUIRE(flat.at(key) == it->second);
        break;
      }
      case 4: {  // taken out with its value
        const std::optional<int> value = flat.take(key);
        const auto it = reference.find(key);
        REQUIRE(value.has_value() == (it != reference.end()));
        if (value) {
          REQUIRE(*value == it->second);
          reference.erase(it);
        }
        REQUIRE(!flat.find(key));
        break;
      }
    }
    REQUIRE(flat.size() == reference.size());
  }
  std::map<std::uint64_t, int> all;
  flat.for_each([&](std::uint64_t k, int v) { CHECK(all.emplace(k, v).second); });
  CHECK(all == std::map<std::uint64_t, int>(reference.begin(), reference.end()));
  for (std::uint64_t k = 0; k < key_range; ++k) {
    const int* value = flat.find(k);
    const auto it = reference.find(k);
    REQUIRE((value != nullptr) == (it != reference.end()));
    if (value) CHECK(*value == it->second);
  }
}

}  // namespace

TEST_CASE("flat map: the same elements as std::unordered_map", "[flat_map]") {
  same_as_reference<Few_hashes<0>>(1000, 20000, 1);
  same_as_reference<Few_hashes<0>>(100000, 50000, 2);
}

TEST_CASE("flat map: keys that all hash alike", "[flat_map]") { same_as_reference<Few_hashes<1>>(300, 6000, 3); }

TEST_CASE("flat map: keys on a few hashes, with runs that wrap and meet", "[flat_map]") {
  same_as_reference<Few_hashes<7>>(500, 20000, 4);
  same_as_reference<Few_hashes<61>>(2000, 40000, 5);
}
