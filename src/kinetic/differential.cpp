#include "kvd/kinetic/differential.hpp"

#include "kvd/kernel/convert.hpp"
#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/kinetic/compare_events.hpp"
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

template <class Time>
Run_events<Failure, Time> events_of(const Simulation<Time>& sim) {
  Run_events<Failure, Time> run;
  for (const auto& b : sim.batches) run.batches.push_back({b.time, b.failing, b.structure});
  return run;
}

}  // namespace

mpq_class time_distance(const Exact_time& e, double t) { return distance(e.canonical(), to_rational(t)); }
mpq_class time_distance(const Exact_time& e, const Mpfr_number& t) { return distance(e.canonical(), to_rational(t)); }
mpq_class time_distance(const Exact_time& e, const Exact_time& t) { return distance(e, t); }
mpq_class time_magnitude(const Exact_time& e) { return distance(e.canonical(), mpq_class(0)); }
std::string time_text(double t) { return Double_kernel().to_string(t); }
std::string time_text(const Mpfr_number& t) { return t.to_string(17); }
std::string time_text(const Exact_time& t) { return t.to_string(); }

template <class Time>
Differential compare_runs(const Simulation<Exact_time>& exact, const Simulation<Time>& inexact) {
  Differential d = compare_events(events_of(exact), events_of(inexact));
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
  template Differential compare_events<Failure, K::Time>(const Run_events<Failure, Exact_time>&,            \
                                                        const Run_events<Failure, K::Time>&);              \
  template Differential compare_runs<K::Time>(const Simulation<Exact_time>&, const Simulation<K::Time>&); \
  template Differential compare_with<K>(const Exact_run&, const K&, const scene::Scene&, const Progress&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_DIFFERENTIAL)

}  // namespace kvd::kinetic
