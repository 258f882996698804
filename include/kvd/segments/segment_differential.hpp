// The differential harness on segment scenes: the exact kinetic segment BSP
// against the same run in another kernel, event by event, by the comparison
// the KVD's harness uses (kinetic/differential.hpp: events match by
// certificate and occurrence; order, structure and time errors). The
// structure after a batch is the SHA-256 of the tree's text (Cylindrical_bsp::text).
// What rounding gets wrong shows as missed, spurious or out-of-order events
// and other trees; the floating-point run's repairs of contradicting signs
// (Kinetic_segment_bsp::recovery) are reported with it.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <optional>

#include "kvd/kernel/exact_time.hpp"
#include "kvd/kinetic/differential.hpp"
#include "kvd/segments/segment_predicates.hpp"
#include "kvd/segments/segment_scene.hpp"

namespace kvd::segments {

using Segment_differential = kinetic::Differential_of<Segment_certificate_key>;

struct Segment_exact_run {
  kinetic::Run_events<Segment_certificate_key, Exact_time> run;
  std::size_t failures = 0;
  // When the run stopped at its event count: the last batch's time, up to
  // which the other run goes; otherwise that run goes to the scene's end.
  std::optional<Exact_time> stopped_at;
  double seconds = 0;
};

// The exact run for `events` failures (the batch holding the last one
// included, as kvd simulate counts), without validation.
Segment_exact_run run_exact(const Segment_scene& s, std::size_t events, const kinetic::Progress& progress = {});

// Kernel k's run over the exact run's span, for at most 2 * failures + 100
// failures, compared with it.
template <class K>
Segment_differential compare_with(const Segment_exact_run& exact, const K& k, const Segment_scene& s,
                                  const kinetic::Progress& progress = {});

}  // namespace kvd::segments
