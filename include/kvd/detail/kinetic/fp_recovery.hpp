// Recovery in the floating-point kernels (kinetic/simulation.hpp): the
// later instants at which a run that rounding has led astray picks up a
// fresh tree. Never used by the exact kernel.
#pragma once

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "kvd/detail/kinetic/builder.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/tree/compare.hpp"

namespace kvd::kinetic {

template <class K>
class Fp_recovery {
  using Time = typename K::Time;
  using FT = typename K::FT;

public:
  Fp_recovery(const K& k, Builder<K>& builder, Recovery& counts) : k_(k), builder_(builder), counts_(counts) {}

  // A build at `at` failed: the first of the instants at + 2^i epsilon,
  // i = 1, ..., recovery_steps, whose build succeeds, with its tree.
  std::optional<std::pair<Time, tree::Kvd_tree>> build_later(const Time& at) {
    ++counts_.failed_builds;
    auto later = step_forward(at, [](const tree::Kvd_tree&) { return true; });
    if (later) ++counts_.rebuilds;
    return later;
  }

  // A batch `b` that repeats the previous one's failures without changing
  // the tree is rounding firing one event again.
  static bool refires(const Batch<Time>& b, const Batch<Time>* previous) {
    return !b.changed && previous && previous->failing == b.failing;
  }

  // After a refire at `now`, the run moves on to the first later instant
  // whose tree differs from `in_force`. (A certificate cannot fail in the
  // past: each is oriented positive just after the instant it is made, and
  // its failure time is a root later than that instant by more than
  // epsilon.) When no nearby tree differs, the certificate is firing inside
  // its own rounding zone (around a root of high multiplicity, rounded
  // values change sign anywhere within about epsilon^(1/m)), and the run
  // steps past the zone of the polynomials `fired`. None when it cannot:
  // the run stops there rather than repeat the batch without advancing.
  std::optional<std::pair<Time, tree::Kvd_tree>> move_past(const Time& now, const tree::Kvd_tree& in_force,
                                                           const std::vector<typename K::Poly>& fired) {
    ++counts_.refires;
    auto later =
        step_forward(now, [&](const tree::Kvd_tree& t) { return tree::first_difference(in_force, t).has_value(); });
    if (!later) later = step_past(now, fired);
    if (!later) ++counts_.unrepaired;
    return later;
  }

private:
  // The first of the instants base + 2^i epsilon, i = 1, ..., recovery_steps,
  // whose build succeeds and is accepted, with its tree.
  template <class Accept>
  std::optional<std::pair<Time, tree::Kvd_tree>> step_forward(const Time& base, Accept accept) {
    FT step = k_.epsilon();
    for (int i = 1; i <= recovery_steps; ++i) {
      step = step * FT(2);
      Time later = base + step;
      Tree_after t = builder_.build(later);
      if (t.tree && accept(*t.tree)) return std::pair{std::move(later), std::move(*t.tree)};
    }
    return std::nullopt;
  }

  // The first instant base + 2^i epsilon (i = 1, 2, ..., while the step is
  // below 1) from which none of `fired` changes sign again within the step,
  // with its tree: past the zone where rounding makes them fire again.
  std::optional<std::pair<Time, tree::Kvd_tree>> step_past(const Time& base, const std::vector<typename K::Poly>& fired) {
    for (FT step = k_.epsilon() * FT(2); step < FT(1); step = step * FT(2)) {
      const Time later = base + step;
      const bool clear = std::ranges::none_of(fired, [&](const typename K::Poly& p) {
        const auto r = k_.next_root(p, later);
        return r && k_.compare(*r, later + step) <= 0;
      });
      if (!clear) continue;
      if (Tree_after t = builder_.build(later); t.tree) {
        ++counts_.zones_skipped;
        return std::pair{later, std::move(*t.tree)};
      }
    }
    return std::nullopt;
  }

  const K& k_;
  Builder<K>& builder_;
  Recovery& counts_;
};

}  // namespace kvd::kinetic
