// How the Python module steps a segment run (KineticSegments, PaperSegments)
// within the bounds its constructor took: `events` failures and the instant
// `until`. advance(), advance_to() and set_motion() keep them alike, as
// Kinetic's do for triangles.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "convert.hpp"

namespace kvd::python {

template <class K>
struct Segment_stepping {
  using Time = typename K::Time;
  std::size_t max_events;
  std::optional<Time> until;
  std::size_t failures = 0;  // of the batches processed (the caller counts them)

  // Whether the batch at `next` (none: no failure left) is processed.
  bool allows(const K& k, const std::optional<Time>& next) const {
    return next && failures < max_events && !(until && k.compare(*next, *until) > 0);
  }

  // Every batch at a time <= t that the bounds allow, each given to `take`;
  // then, when none is left at or before the earlier of t and `until`, the
  // run moves there (not past the span's end). Stopped by the event bound,
  // it stays at the last batch. How many batches.
  template <class Run, class Take>
  std::size_t advance_to(const K& k, Run& run, const Time& t, Take take) const {
    const Time limit = until && k.compare(*until, t) < 0 ? *until : t;
    std::size_t n = 0;
    for (auto next = run.next_event_time(); next && k.compare(*next, limit) <= 0; next = run.next_event_time()) {
      if (!allows(k, next)) return n;
      take(run.advance());
      ++n;
    }
    run.advance_to(limit);
    return n;
  }

  // A flight-plan change's instant `at` (checked not before now and within
  // the span by motion_change): ValueError past `until`, before the run
  // moves; the run is advanced to it, and ValueError when the event bound
  // stopped it before.
  template <class Run, class Take>
  void advance_for_change(const K& k, Run& run, const Time& at, Take take) const {
    if (until && k.compare(at, *until) > 0)
      throw py::value_error("set_motion: at = " + k.to_string(at) + " is after the run's until, " + k.to_string(*until));
    advance_to(k, run, at, take);
    if (k.compare(run.now(), at) != 0)
      throw py::value_error("set_motion: the run stopped at " + k.to_string(run.now()) + " after its " +
                            std::to_string(max_events) + " events, before at = " + k.to_string(at));
  }
};

}  // namespace kvd::python
