// The definition of kinetic::compare_events (differential.hpp), included by
// the files that instantiate it for their kind of failure:
// src/kinetic/differential.cpp (the KVD's) and
// src/segments/segment_differential.cpp (the segment BSP's).
#pragma once

#include <map>

#include "kvd/kernel/mpfr_number.hpp"
#include "kvd/kinetic/differential.hpp"

namespace kvd::kinetic {

// |t - e| for an inexact (or exact) time t, an exact distance to about three
// significant digits, from e's canonical interval so that it does not depend
// on how far comparisons have refined e (src/kinetic/differential.cpp).
mpq_class time_distance(const Exact_time& e, double t);
mpq_class time_distance(const Exact_time& e, const Mpfr_number& t);
mpq_class time_distance(const Exact_time& e, const Exact_time& t);
// |e| to the same accuracy; e != 0.
mpq_class time_magnitude(const Exact_time& e);
// A time as the report prints it: 17 significant digits, an exact time in full.
std::string time_text(double t);
std::string time_text(const Mpfr_number& t);
std::string time_text(const Exact_time& t);

namespace detail {

template <class F>
struct Listed {
  F failure;
  std::size_t batch;
};

template <class F, class Time>
std::vector<Listed<F>> events_of(const Run_events<F, Time>& run) {
  std::vector<Listed<F>> out;
  for (std::size_t b = 0; b < run.batches.size(); ++b)
    for (const F& f : run.batches[b].failing) out.push_back({f, b});
  return out;
}

// For each event of `a`, the event of `b` with the same failure and occurrence.
template <class F>
std::vector<std::optional<std::size_t>> match(const std::vector<Listed<F>>& a, const std::vector<Listed<F>>& b) {
  std::map<F, std::vector<std::size_t>> occurrences;
  for (std::size_t j = 0; j < b.size(); ++j) occurrences[b[j].failure].push_back(j);
  std::map<F, std::size_t> seen;
  std::vector<std::optional<std::size_t>> out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto it = occurrences.find(a[i].failure);
    const std::size_t k = seen[a[i].failure]++;
    if (it != occurrences.end() && k < it->second.size()) out[i] = it->second[k];
  }
  return out;
}

inline bool is_zero(const Exact_time& e) { return e.is_rational() && e.rational() == 0; }

}  // namespace detail

template <class F, class Time>
Differential_of<F> compare_events(const Run_events<F, Exact_time>& exact, const Run_events<F, Time>& inexact) {
  Differential_of<F> d;
  const auto xs = detail::events_of(exact), ys = detail::events_of(inexact);
  const auto matched = detail::match(xs, ys);
  for (const auto& y : ys) d.inexact.push_back({y.failure, y.batch, time_text(inexact.batches[y.batch].time), std::nullopt});
  for (std::size_t i = 0; i < xs.size(); ++i)
    if (matched[i]) d.inexact[*matched[i]].exact_event = i;
  std::optional<std::size_t> first_spurious_batch;
  for (const auto& y : d.inexact)
    if (!y.exact_event) {
      ++d.spurious_events;
      if (!first_spurious_batch) first_spurious_batch = y.batch;
    }
  std::optional<std::pair<std::size_t, std::size_t>> previous;  // batches of the previous matched event
  for (std::size_t i = 0; i < xs.size(); ++i) {
    Event_match_of<F> m;
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
      m.time_error = time_distance(te, inexact.batches[by].time);
      if (!detail::is_zero(te)) m.relative_time_error = m.time_error / time_magnitude(te);
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
  return d;
}

}  // namespace kvd::kinetic
