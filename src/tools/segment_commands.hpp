// kvd build, simulate and certify on segment scenes (kvd-segments/1): the
// cylindrical BSP of seed 003 and its kinetic version. The commands read the
// file once and come here when its "format" says so.
#pragma once

#include <gmpxx.h>

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "left_at_exit.hpp"

namespace kvd::cli {

// What kvd build prints of a segment scene's tree instead of its counts:
// nothing, the tree (--tree), or seed 003's augmented form (--augmented).
enum class Segment_tree_text { none, tree, augmented };

int segment_build(const Scene_args& sa, const std::string& text, const std::string& kernel, bool filter,
                  Segment_tree_text tree);

struct Segment_run_options {
  std::size_t max_events = 100;
  std::optional<mpq_class> until;
  bool validate = true;
  std::string kernel = "exact";
  std::optional<mpq_class> epsilon;
  bool filter = true;
  bool list = false;
  segments::Segment_update update = segments::Segment_update::local;
  // The run on seed 003's certificate set (Aeg_kinetic_bsp) instead.
  bool paper = false;
};

int segment_simulate(const Scene_args& sa, const std::string& text, const Segment_run_options& o);
// The same with o.paper (src/tools/segment_simulate_paper.cpp).
int segment_simulate_paper(const Scene_args& sa, const segments::Segment_scene& s, const Segment_run_options& o);

// How run_batches stopped ("limit", "events" or "exhausted"), after how
// many batches and certificate failures, and the time reached: the last
// batch's, or the limit (the earlier of the scene's end and --until) when
// the run stopped there or ran out of failures before it.
template <class Time>
struct Batches_run {
  std::string stopped;
  std::size_t batches = 0, failures = 0;
  Time time_reached;
};

// A run made with `args` and kept to the exit (left_at_exit), with the
// milliseconds its construction took: the tree and its certificates (some
// 16 s for 12,800 segments on the kept set, which holds 1.4 million).
template <class Run>
struct Started_run {
  Run& run;
  double construction_ms;
};
template <class Run, class... Args>
Started_run<Run> start_run(Args&&... args) {
  const auto start = std::chrono::steady_clock::now();
  Run& run = left_at_exit<Run>(std::forward<Args>(args)...);
  return {run, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()};
}

// Advances `run` (a kinetic segment BSP of kernel k) batch by batch up to
// o.until or the batch holding the o.max_events-th failure, handing each
// batch to take(batch) (a run's batches are not kept: their record would
// grow with the run), with progress on stderr.
template <class Run, class K, class Take>
Batches_run<typename K::Time> run_batches(Run& run, const K& k, const Segment_run_options& o, Take take) {
  const auto progress = progress_every_few_seconds("kvd simulate");
  const std::optional<mpq_class> limit = run.scene().limit(o.until);
  std::optional<typename K::Time> until;
  if (o.until) until = k.time(from_rational<typename K::FT>(*o.until));
  const auto at_limit = [&](Batches_run<typename K::Time>& r, const char* why) {
    r.stopped = why;
    r.time_reached = limit ? k.time(from_rational<typename K::FT>(*limit)) : run.now();
    return r;
  };
  Batches_run<typename K::Time> r;
  while (const auto next = run.next_event_time()) {
    if (until && k.compare(*next, *until) > 0) return at_limit(r, "limit");
    if (r.failures >= o.max_events) {
      r.stopped = "events";
      r.time_reached = run.now();
      return r;
    }
    typename Run::Batch b = run.advance();
    r.failures += b.failing.size();
    take(std::move(b));
    progress(++r.batches, r.failures);
  }
  return at_limit(r, "exhausted");
}

struct Segment_certify_options {
  std::string out;
  std::size_t max_events = 100;
  std::optional<mpq_class> until;
  bool validate = false;
};

// The exact run's event-order certificate, kvd-segment-event-order/1, written to o.out.
int segment_certify(const Scene_args& sa, const std::string& text, const Segment_certify_options& o);

// kvd diff: the exact run for `events` failures against the same run in
// `kernel`, printed as kvd diff prints the KVD's (diff_report.hpp).
int segment_diff(const Scene_args& sa, const std::string& text, const std::string& kernel, std::size_t events,
                 const std::optional<mpq_class>& epsilon);

// Scene_error naming the first segment with a number the field FT cannot
// hold (1e400 is infinite in double): "a number that is not finite in "
// `where`.
template <class FT>
void require_finite_in(const std::string& path, const segments::Segment_scene& s, const std::string& where) {
  for (std::size_t e = 0; e < s.endpoint_count(); ++e)
    for (const auto& c : s.endpoint(e))
      for (const auto& q : c.coefficients())
        if (!is_finite(from_rational<FT>(q)))
          throw scene::Scene_error(path + ": /segments/" + std::to_string(e / 2) + ": a number that is not finite in " +
                                   where);
}
// The same for K's field; the exact kernel holds all.
template <class K>
void require_representable(const std::string& path, const segments::Segment_scene& s, const K& k) {
  require_finite_in<typename K::FT>(path, s, "the " + kernel_label(k) + " kernel; use --kernel exact or mpfr:BITS");
}

// Usage_error naming the flags given that only triangle scenes take.
void refuse_triangle_flags(const std::string& command, const std::vector<std::string>& given);

}  // namespace kvd::cli
