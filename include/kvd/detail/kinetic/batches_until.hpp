// A run's batches up to an instant, for the advance_to of the segment runs
// (Kinetic_segment_bsp, Aeg_kinetic_bsp): any class with next_event_time()
// and advance().
#pragma once

#include <optional>
#include <vector>

namespace kvd::kinetic {

// Processes every batch of `run` at a time <= t, in order, then moves `now`
// to t if later, but not past the span's `end` (when bounded): no
// certificate fails in (now, t], so their failure times stay. Returns the
// batches.
template <class Run, class K>
std::vector<typename Run::Batch> batches_until(Run& run, const K& k, const typename K::Time& t, typename K::Time& now,
                                               const std::optional<typename K::Time>& end) {
  std::vector<typename Run::Batch> batches;
  while (const auto next = run.next_event_time()) {
    if (k.compare(*next, t) > 0) break;
    batches.push_back(run.advance());
  }
  const typename K::Time& to = end && k.compare(*end, t) < 0 ? *end : t;
  if (k.compare(now, to) < 0) now = to;
  return batches;
}

}  // namespace kvd::kinetic
