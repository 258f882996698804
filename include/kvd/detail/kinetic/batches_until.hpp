// A run's batches up to an instant, for the advance_to of the segment runs
// (Kinetic_segment_bsp, Aeg_kinetic_bsp): any class with next_event_time()
// and advance().
#pragma once

#include <vector>

namespace kvd::kinetic {

// Processes every batch of `run` at a time <= t, in order; returns them.
template <class Run, class K>
std::vector<typename Run::Batch> batches_until(Run& run, const K& k, const typename K::Time& t) {
  std::vector<typename Run::Batch> batches;
  while (const auto next = run.next_event_time()) {
    if (k.compare(*next, t) > 0) break;
    batches.push_back(run.advance());
  }
  return batches;
}

}  // namespace kvd::kinetic
