#include "kvd/kinetic/differential.hpp"

#include <map>

#include "kvd/kernel/convert.hpp"
#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/kinetic/stopwatch.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::kinetic {

namespace {

// Refinement stops when the interval is 2^-10 of the distance or less.
constexpr int distance_bits = 10;

// |f - e|, with a relative error of at most 2^-(distance_bits + 1). The
// interval of e is refined until it is narrow against its distance from f,
// which ends because f is rational and, when e is not, differs from it.
mpq_class distance(const Exact_time& e, const mpq_class& f) {
  for (;;) {
    if (e.is_rational()) return abs(f - e.rational());
    const mpq_class lo = e.lower(), hi = e.upper();
    if (lo < f && f < hi) {
      e.compare_refining(f);
      continue;
    }
    const mpq_class gap = f <= lo ? mpq_class(lo - f) : mpq_class(f - hi);
    if (((hi - lo) << distance_bits) <= gap) return gap + (hi - lo) / 2;
    e.refine();
  }
}

// Two exact times: zero when equal, otherwise refined apart as above, from
// their canonical intervals.
mpq_class distance(const Exact_time& e, const Exact_time& f) {
  if (Exact_kernel().compare(e, f) == 0) return 0;
  const Exact_time a = e.canonical(), b = f.canonical();
  for (;;) {
    const bool below = a.upper() < b.lower();
    const mpq_class gap = below ? mpq_class(b.lower() - a.upper()) : mpq_class(a.lower() - b.upper());
    const mpq_class width = (a.upper() - a.lower()) + (b.upper() - b.lower());
    if (gap > 0 && (width << distance_bits) <= gap) return gap + width / 2;
    a.refine();
    b.refine();
  }
}
// From the canonical interval, so that the result does not depend on how far
// comparisons have refined e.
mpq_class distance(const Exact_time& e, double f) { return distance(e.canonical(), to_rational(f)); }
mpq_class distance(const Exact_time& e, const Mpfr_number& f) { return distance(e.canonical(), to_rational(f)); }

// |e| to the same relative accuracy; e != 0.
mpq_class magnitude(const Exact_time& e) { return distance(e.canonical(), mpq_class(0)); }

std::string text(double t) { return Double_kernel().to_string(t); }
std::string text(const Mpfr_number& t) { return t.to_string(17); }
std::string text(const Exact_time& t) { return t.to_string(); }

bool is_zero(const Exact_time& e) { return e.is_rational() && e.rational() == 0; }

struct Listed {
  Failure failure;
  std::size_t batch;
};

template <class Time>
std::vector<Listed> events_of(const Simulation<Time>& sim) {
  std::vector<Listed> out;
  for (std::size_t b = 0; b < sim.batches.size(); ++b)
    for (const Failure& f : sim.batches[b].failing) out.push_back({f, b});
  return out;
}

// For each event of `a`, the event of `b` with the same failure and occurrence.
std::vector<std::optional<std::size_t>> match(const std::vector<Listed>& a, const std::vector<Listed>& b) {
  std::map<Failure, std::vector<std::size_t>> occurrences;
  for (std::size_t j = 0; j < b.size(); ++j) occurrences[b[j].failure].push_back(j);
  std::map<Failure, std::size_t> seen;
  std::vector<std::optional<std::size_t>> out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto it = occurrences.find(a[i].failure);
    const std::size_t k = seen[a[i].failure]++;
    if (it != occurrences.end() && k < it->second.size()) out[i] = it->second[k];
  }
  return out;
}

}  // namespace

template <class Time>
Differential compare_runs(const Simulation<Exact_time>& exact, const Simulation<Time>& inexact) {
  Differential d;
  const std::vector<Listed> xs = events_of(exact), ys = events_of(inexact);
  const auto matched = match(xs, ys);
  for (const Listed& y : ys) d.inexact.push_back({y.failure, y.batch, text(inexact.batches[y.batch].time), std::nullopt});
  for (std::size_t i = 0; i < xs.size(); ++i)
    if (matched[i]) d.inexact[*matched[i]].exact_event = i;
  std::optional<std::size_t> first_spurious_batch;
  for (const Inexact_event& y : d.inexact)
    if (!y.exact_event) {
      ++d.spurious_events;
      if (!first_spurious_batch) first_spurious_batch = y.batch;
    }
  std::optional<std::pair<std::size_t, std::size_t>> previous;  // batches of the previous matched event
  for (std::size_t i = 0; i < xs.size(); ++i) {
    Event_match m;
    m.failure = xs[i].failure;
    m.exact_batch = xs[i].batch;
    m.inexact_event = matched[i];
    bool diverges = !m.inexact_event;
    if (m.inexact_event) {
      const std::size_t bx = xs[i].batch, by = ys[*m.inexact_event].batch;
      if (previous) m.in_order = bx == previous->first ? by == previous->second : by > previous->second;
      previous.emplace(bx, by);
      m.structure_equal = exact.batches[bx].structure == inexact.batches[by].structure;
      const Exact_time& te = exact.batches[bx].time;
      m.time_error = distance(te, inexact.batches[by].time);
      if (!is_zero(te)) m.relative_time_error = m.time_error / magnitude(te);
      d.order_mismatches += !m.in_order;
      d.structure_mismatches += !m.structure_equal;
      if (m.time_error > d.max_time_error) d.max_time_error = m.time_error;
      if (m.relative_time_error && *m.relative_time_error > d.max_relative_time_error)
        d.max_relative_time_error = *m.relative_time_error;
      diverges = !m.in_order || !m.structure_equal || (first_spurious_batch && *first_spurious_batch <= by);
    } else {
      ++d.missed_events;
    }
    if (diverges && !d.first_divergence_event) d.first_divergence_event = i;
    d.events.push_back(std::move(m));
  }
  if (!d.first_divergence_event && d.spurious_events) d.first_divergence_event = xs.size();
  d.recovery = inexact.recovery;
  return d;
}

Exact_run run_exact(const scene::Scene& s, std::size_t events, const Progress& progress) {
  Options o;
  o.max_events = events;
  o.progress = progress;
  o.validate = Validation::none;
  const Stopwatch watch;
  Exact_run run{simulate(Exact_kernel(), s, o)};
  run.seconds = watch.seconds();
  return run;
}

template <class K>
Differential compare_with(const Exact_run& exact, const K& k, const scene::Scene& s, const Progress& progress) {
  Options o;
  o.progress = progress;
  o.max_events = 2 * exact.sim.failures + 100;
  o.validate = Validation::none;
  // The exact run's span: to its last instant when it stopped early, to its
  // limit when it ran out of time, and as far as events go when it ran out
  // of events.
  const Simulation<Exact_time>& x = exact.sim;
  if (x.stopped == Stop::events || x.stopped == Stop::collision) o.until = x.time_reached.upper();
  else o.until = x.limit;
  const Stopwatch watch;
  const auto sim = simulate(k, s, o);
  const double seconds = watch.seconds();
  Differential d = compare_runs(exact.sim, sim);
  d.inexact_stopped = sim.stopped;
  d.seconds_exact = exact.seconds;
  d.seconds_inexact = seconds;
  return d;
}

#define KVD_INSTANTIATE_DIFFERENTIAL(K)                                                          \
  template Differential compare_runs<K::Time>(const Simulation<Exact_time>&, const Simulation<K::Time>&); \
  template Differential compare_with<K>(const Exact_run&, const K&, const scene::Scene&, const Progress&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_DIFFERENTIAL)

}  // namespace kvd::kinetic
