// The two stores a kinetic run keeps beside its certificates: the root cache
// (kvd/detail/kinetic/root_cache.hpp) and the time heap
// (kvd/detail/kinetic/time_heap.hpp). Both must stay within a constant of
// the certificates in force however long the run, and neither may change
// what the run sees: the cache's roots are the kernel's, the heap's order
// of live entries is by time.
#include <catch2/catch.hpp>
#include <algorithm>
#include <random>

#include "kernels.hpp"
#include "kvd/detail/kinetic/root_cache.hpp"
#include "kvd/detail/kinetic/time_heap.hpp"

namespace {

// A kernel that counts its root isolations.
template <class K>
struct Counting : K {
  mutable std::size_t isolations = 0;
  std::optional<typename K::Time> next_root(const typename K::Poly& p, const typename K::Time& t) const {
    ++isolations;
    return K::next_root(p, t);
  }
};

// (t - i/8)(t - i/8 - 1)(t - i/8 - 2): distinct for distinct i, with roots
// on both sides of 5/8 for i = 5; of degree 3, since the exact kernel's
// closed forms for degrees 1 and 2 are not cached.
template <class K>
typename K::Poly three_roots(long i) {
  using FT = typename K::FT;
  const FT r = FT(i) / FT(8);
  typename K::Poly p(std::vector<FT>{-r, FT(1)});
  for (const int d : {1, 2}) p *= typename K::Poly(std::vector<FT>{-(r + FT(d)), FT(1)});
  return p;
}

}  // namespace

TEMPLATE_TEST_CASE("the root cache gives the kernel's roots and keeps two generations", "[kinetic][roots]",
                   KVD_ALL_KERNELS) {
  using K = TestType;
  const Counting<K> k;
  const K plain;
  constexpr long generation = 256;  // the least, with fewer certificates in force
  kvd::kinetic::Root_cache<Counting<K>> cache(generation);
  const auto now = k.time(typename K::FT(0));
  cache.bound(10);
  // Three generations' worth of distinct polynomials: each isolated once,
  // its root the kernel's.
  for (long i = 1; i <= 3 * generation; ++i) {
    const auto& r = cache.next_root(k, three_roots<K>(i), now);
    REQUIRE(r);
    REQUIRE(k.compare(*r, *plain.next_root(three_roots<K>(i), now)) == 0);
  }
  CHECK(k.isolations == static_cast<std::size_t>(3 * generation));
  CHECK(cache.size() <= static_cast<std::size_t>(2 * generation));
  // The last generation asked is held; the first was dropped.
  const std::size_t before = k.isolations;
  for (long i = 3 * generation; i > 2 * generation + 10; --i) (void)cache.next_root(k, three_roots<K>(i), now);
  CHECK(k.isolations == before);
  (void)cache.next_root(k, three_roots<K>(1), now);
  CHECK(k.isolations == before + 1);
  // A root no longer ahead is isolated again: the next one after it.
  const auto later = k.time(typename K::FT(5) / typename K::FT(8));
  const auto& r = cache.next_root(k, three_roots<K>(5), later);
  REQUIRE(r);
  CHECK(k.compare(*r, *plain.next_root(three_roots<K>(5), later)) == 0);
  CHECK(k.compare(*r, later) > 0);
  // More certificates in force, larger generations: nothing asked since the
  // bound rose is dropped before that many more are asked.
  cache.bound(4 * generation);
  const std::size_t at = k.isolations;
  for (long i = 1; i <= 4 * generation; ++i) (void)cache.next_root(k, three_roots<K>(10 * generation + i), now);
  for (long i = 1; i <= 4 * generation; i += 7) (void)cache.next_root(k, three_roots<K>(10 * generation + i), now);
  CHECK(k.isolations == at + static_cast<std::size_t>(4 * generation));
}

TEMPLATE_TEST_CASE("trimming the time heap drops the stale entries a few at a time and keeps the order of the live ones",
                   "[kinetic][queue]", KVD_ALL_KERNELS) {
  using K = TestType;
  const K k;
  struct Entry {
    typename K::Time time;
    int id;
  };
  kvd::kinetic::Time_heap<K, Entry> heap(k);
  std::mt19937 rng(7);
  std::vector<bool> stale;
  std::vector<long> at;
  for (int id = 0; id < 5000; ++id) {
    at.push_back(static_cast<long>(rng() % 1000));
    stale.push_back(rng() % 4 != 0);  // three in four go stale, as certificates made again do
    heap.push({k.time(typename K::FT(at.back()) / typename K::FT(7)), id});
  }
  std::size_t looked = 0;  // entries a trim asked about
  const auto is_stale = [&](const Entry& e) {
    ++looked;
    return static_cast<bool>(stale[static_cast<std::size_t>(e.id)]);
  };
  const std::size_t live = static_cast<std::size_t>(std::count(stale.begin(), stale.end(), false));
  REQUIRE(live > 1024);
  // The entries pushed before the first call are not swept for then.
  heap.trim(is_stale);
  CHECK(looked == 0);
  CHECK(heap.size() == 5000);
  // Each call looks at twice the entries pushed since the last: never a
  // pass over the whole heap at once. Going round, the sweep drops the
  // stale entries of the start, and keeps up with those pushed.
  for (int i = 0; i < 5000; ++i) {
    stale.push_back(true);
    heap.push({k.time(typename K::FT(i % 1000) / typename K::FT(7)), static_cast<int>(stale.size() - 1)});
    looked = 0;
    heap.trim(is_stale);
    REQUIRE(looked <= 2);
  }
  // (A round of n entries takes n / 2 pushes: at most n / 2 went stale since.)
  CHECK(heap.size() <= 2 * live);
  // The live entries come off in time order, every one of them, the stale
  // ones left dropped when they reach the top.
  std::vector<int> seen;
  long last = -1;
  while (heap.next(is_stale)) {
    const Entry e = heap.top();
    heap.pop();
    REQUIRE_FALSE(is_stale(e));
    REQUIRE(at[static_cast<std::size_t>(e.id)] >= last);
    last = at[static_cast<std::size_t>(e.id)];
    seen.push_back(e.id);
  }
  CHECK(seen.size() == live);
}
