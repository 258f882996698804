#include "kvd/segments/segment_differential.hpp"

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/kinetic/compare_events.hpp"
#include "kvd/detail/kinetic/stopwatch.hpp"
#include "kvd/detail/tree/digest.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"

namespace kvd::segments {

namespace {

// Runs kin while the next batch is at or before `until` (when given) and
// fewer than max_failures failures are processed, recording each batch.
// Returns whether it stopped at the failure count.
template <class K>
bool record_run(Kinetic_segment_bsp<K>& kin, const K& k, std::size_t max_failures,
                const std::optional<typename K::Time>& until, kinetic::Run_events<Segment_certificate_key, typename K::Time>& out,
                std::size_t& failures, const kinetic::Progress& progress) {
  while (const auto next = kin.next_event_time()) {
    if (until && k.compare(*next, *until) > 0) return false;
    if (failures >= max_failures) return true;
    auto b = kin.advance();
    failures += b.failing.size();
    out.batches.push_back({std::move(b.time), std::move(b.failing), tree::sha256_hex(kin.tree().text())});
    if (progress) progress(out.batches.size(), failures);
  }
  return false;
}

}  // namespace

Segment_exact_run run_exact(const Segment_scene& s, std::size_t events, const kinetic::Progress& progress) {
  const kinetic::Stopwatch watch;
  const Exact_kernel k;
  Kinetic_segment_bsp<Exact_kernel> kin(k, s, false);
  Segment_exact_run x;
  if (record_run(kin, k, events, std::nullopt, x.run, x.failures, progress) && !x.run.batches.empty())
    x.stopped_at = x.run.batches.back().time;
  x.seconds = watch.seconds();
  return x;
}

template <class K>
Segment_differential compare_with(const Segment_exact_run& exact, const K& k, const Segment_scene& s,
                                  const kinetic::Progress& progress) {
  const kinetic::Stopwatch watch;
  Kinetic_segment_bsp<K> kin(k, s, false);
  std::optional<typename K::Time> until;
  if (exact.stopped_at) until = k.time(from_rational<typename K::FT>(exact.stopped_at->upper()));
  kinetic::Run_events<Segment_certificate_key, typename K::Time> run;
  std::size_t failures = 0;
  const bool at_count = record_run(kin, k, 2 * exact.failures + 100, until, run, failures, progress);
  const double seconds = watch.seconds();
  Segment_differential d = kinetic::compare_events(exact.run, run);
  d.recovery = kin.recovery();
  d.inexact_stopped = kin.stuck()                ? kinetic::Stop::stuck
                      : at_count                 ? kinetic::Stop::events
                      : kin.next_event_time()    ? kinetic::Stop::limit
                                                 : kinetic::Stop::exhausted;
  d.seconds_exact = exact.seconds;
  d.seconds_inexact = seconds;
  return d;
}

#define KVD_INSTANTIATE_SEGMENT_DIFFERENTIAL(K)                                                              \
  template Segment_differential compare_with<K>(const Segment_exact_run&, const K&, const Segment_scene&,     \
                                                const kinetic::Progress&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SEGMENT_DIFFERENTIAL)

}  // namespace kvd::segments

namespace kvd::kinetic {
#define KVD_INSTANTIATE_SEGMENT_EVENTS(K)                                                                        \
  template segments::Segment_differential compare_events<segments::Segment_certificate_key, K::Time>(          \
      const Run_events<segments::Segment_certificate_key, Exact_time>&,                                        \
      const Run_events<segments::Segment_certificate_key, K::Time>&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SEGMENT_EVENTS)
}  // namespace kvd::kinetic
