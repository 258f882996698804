// The differential harness: the exact simulation and a floating-point one on
// the same scene, event by event.
//
// Events are certificate failures, listed in batch order (within a batch in
// the order of (type, features)). An exact event and an inexact one match
// when they have the same type and symbolic features and the same
// occurrence: the k-th failure of a certificate in one run matches its k-th
// failure in the other. Unmatched exact events are missed, unmatched inexact
// ones spurious. A matched event is in order when it relates to the previous
// matched exact event as it does in the exact run: in the same batch there,
// in the same batch here; in a later batch there, in a later batch here. Its
// structure is equal when the trees just after the two batches holding it
// have the same structure hash. Time errors are exact distances from the
// inexact time (a rational) to the exact algebraic time, to about three
// significant digits.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kvd/kernel/exact_time.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/scene.hpp"

namespace kvd::kinetic {

// The comparison for any kind of failure F (a Certificate_key here, a
// Segment_certificate_key for the segment BSP): ordered, as map keys.
template <class F>
struct Event_match_of {
  F failure;
  std::size_t exact_batch = 0;
  std::optional<std::size_t> inexact_event;  // index in Differential::inexact; none: missed
  bool in_order = true;
  bool structure_equal = true;
  mpq_class time_error;                         // |t_inexact - t_exact|, when matched
  std::optional<mpq_class> relative_time_error;  // time_error / |t_exact|, when matched and t_exact != 0
};

template <class F>
struct Inexact_event_of {
  F failure;
  std::size_t batch = 0;
  std::string time;  // 17 significant digits (an exact time in full)
  std::optional<std::size_t> exact_event;  // none: spurious
};

template <class F>
struct Differential_of {
  std::vector<Event_match_of<F>> events;     // the exact run's events
  std::vector<Inexact_event_of<F>> inexact;  // the inexact run's events
  std::size_t order_mismatches = 0, missed_events = 0, spurious_events = 0, structure_mismatches = 0;
  // The first exact event at which the runs differ (missed, out of order,
  // another structure, or preceded by a spurious event); events.size() when
  // they differ only after the last exact event; none when they never do.
  std::optional<std::size_t> first_divergence_event;
  mpq_class max_time_error;
  mpq_class max_relative_time_error;
  double seconds_exact = 0, seconds_inexact = 0;
  Recovery recovery;  // of the inexact run
  Stop inexact_stopped = Stop::exhausted;  // why the inexact run stopped
};

// A run as the comparison sees it: per batch its time, the failures in it
// (in the run's order) and the structure of the tree just after it (equal
// strings for equal structures).
template <class F, class Time>
struct Run_events {
  struct Batch {
    Time time;
    std::vector<F> failing;
    std::string structure;
  };
  std::vector<Batch> batches;
};

using Event_match = Event_match_of<Failure>;
using Inexact_event = Inexact_event_of<Failure>;
using Differential = Differential_of<Failure>;

// The exact run the comparisons share, with its wall time.
struct Exact_run {
  Simulation<Exact_time> sim;
  double seconds = 0;
};

using Progress = std::function<void(std::size_t batches, std::size_t failures)>;

// Runs the exact simulation for `events` failures, without validation.
Exact_run run_exact(const scene::Scene& s, std::size_t events, const Progress& progress = {});

// Runs kernel k on the scene over the exact run's time span (up to the exact
// run's last batch, or its limit), without validation and for at most
// 2 * events + 100 failures, and compares the two runs.
template <class K>
Differential compare_with(const Exact_run& exact, const K& k, const scene::Scene& s, const Progress& progress = {});

// The comparison itself, for two records.
template <class Time>
Differential compare_runs(const Simulation<Exact_time>& exact, const Simulation<Time>& inexact);

// The same for any kind of failure; the recovery, the stop and the seconds
// are the caller's to fill.
template <class F, class Time>
Differential_of<F> compare_events(const Run_events<F, Exact_time>& exact, const Run_events<F, Time>& inexact);

}  // namespace kvd::kinetic
