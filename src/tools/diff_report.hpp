// What kvd diff prints, for the KVD's certificates and the segment BSP's
// alike: the comparison (kinetic::Differential_of<F>) with F's own words.
#pragma once

#include <functional>
#include <iostream>
#include <optional>
#include <string>

#include "json_out.hpp"
#include "kvd/kinetic/differential.hpp"
#include "report.hpp"

namespace kvd::cli {

template <class F>
struct Diff_view {
  const kinetic::Differential_of<F>& d;
  std::function<const Exact_time&(std::size_t batch)> exact_time;  // of an exact batch
  std::function<Json(const F&)> fields;          // the failure's members in an event's JSON
  std::function<std::string(const F&)> label;    // the failure in the text report
  std::optional<kinetic::Recovery> recovery;     // the inexact run's, when it has one
};

namespace diff_detail {
// An exact error in scientific notation, or null.
inline Json error_json(const std::optional<mpq_class>& q) { return q ? decimal(scientific(*q)) : Json(nullptr); }
// {"event" or "inexact_event": i} followed by the failure's fields.
template <class F>
Json head(const char* name, std::size_t i, const Diff_view<F>& v, const F& f) {
  Json j = {{name, i}};
  const Json fields = v.fields(f);  // named: items() does not keep a temporary alive
  for (const auto& [key, value] : fields.items()) j[key] = value;
  return j;
}
}  // namespace diff_detail

template <class F>
void print_diff_json(const std::string& scene, const std::string& kernel, const Diff_view<F>& v) {
  const auto& d = v.d;
  Json events = Json::array();
  for (std::size_t i = 0; i < d.events.size(); ++i) {
    const auto& m = d.events[i];
    const Exact_time& t = v.exact_time(m.exact_batch);
    Json e = diff_detail::head("event", i, v, m.failure);
    e["exact_time"] = t.to_string();
    e["exact_approx"] = approx(t.to_double());
    e["inexact_event"] = m.inexact_event ? Json(*m.inexact_event) : Json(nullptr);
    e["inexact_time"] = m.inexact_event ? Json(d.inexact[*m.inexact_event].time) : Json(nullptr);
    e["in_order"] = m.in_order;
    e["structure_equal"] = m.structure_equal;
    e["time_error"] = m.inexact_event ? decimal(scientific(m.time_error)) : Json(nullptr);
    e["relative_time_error"] = diff_detail::error_json(m.relative_time_error);
    events.push_back(std::move(e));
  }
  Json spurious = Json::array();
  for (std::size_t j = 0; j < d.inexact.size(); ++j)
    if (!d.inexact[j].exact_event) {
      Json e = diff_detail::head("inexact_event", j, v, d.inexact[j].failure);
      e["inexact_time"] = d.inexact[j].time;
      spurious.push_back(std::move(e));
    }
  Json report = {
      {"scene", scene},
      {"kernel", kernel},
      {"events", events},
      {"spurious", spurious},
      {"events_compared", d.events.size()},
      {"first_divergence_event", d.first_divergence_event ? Json(*d.first_divergence_event) : Json(nullptr)},
      {"order_mismatches", d.order_mismatches},
      {"missed_events", d.missed_events},
      {"spurious_events", d.spurious_events},
      {"structure_mismatches", d.structure_mismatches},
      {"max_time_error", decimal(scientific(d.max_time_error))},
      {"max_relative_time_error", decimal(scientific(d.max_relative_time_error))},
      {"inexact_stopped", stop_name(d.inexact_stopped)},
      {"seconds_exact", decimal(fixed(d.seconds_exact, 6))},
      {"seconds_inexact", decimal(fixed(d.seconds_inexact, 6))}};
  if (v.recovery) report["recovery"] = recovery_json(*v.recovery);
  std::cout << json_lines(report) << "\n";
}

// After "stuck": a floating-point run that stops there misses every exact
// event after it (kvd simulate, on its own, exits 1).
inline constexpr const char* stuck_note = " (it could not advance; the exact events after that are missed)";

template <class F>
void print_diff_text(const std::string& kernel, const Diff_view<F>& v) {
  const auto& d = v.d;
  for (std::size_t i = 0; i < d.events.size(); ++i) {
    const auto& m = d.events[i];
    std::cout << "event " << i << " " << v.label(m.failure) << " at " << approx(v.exact_time(m.exact_batch).to_double())
              << ": ";
    if (!m.inexact_event) {
      std::cout << "missed\n";
      continue;
    }
    std::cout << kernel << " event " << *m.inexact_event << " at " << d.inexact[*m.inexact_event].time << ", error "
              << scientific(m.time_error) << (m.in_order ? "" : ", out of order")
              << (m.structure_equal ? "" : ", another tree after it") << "\n";
  }
  for (std::size_t j = 0; j < d.inexact.size(); ++j)
    if (!d.inexact[j].exact_event)
      std::cout << kernel << " event " << j << " " << v.label(d.inexact[j].failure) << " at " << d.inexact[j].time
                << ": spurious\n";
  std::cout << "events compared:      " << d.events.size() << "\n"
            << "first divergence:     "
            << (d.first_divergence_event ? "event " + std::to_string(*d.first_divergence_event) : std::string("none"))
            << "\n"
            << "order mismatches:     " << d.order_mismatches << "\n"
            << "missed events:        " << d.missed_events << "\n"
            << "spurious events:      " << d.spurious_events << "\n"
            << "structure mismatches: " << d.structure_mismatches << "\n"
            << "max time error:       " << scientific(d.max_time_error) << " (relative "
            << scientific(d.max_relative_time_error) << ")\n"
            << "stopped:              " << kernel << " run " << stop_name(d.inexact_stopped)
            << (d.inexact_stopped == kinetic::Stop::stuck ? stuck_note : "") << "\n"
            << "seconds:              exact " << fixed(d.seconds_exact, 3) << ", " << kernel << " "
            << fixed(d.seconds_inexact, 3) << "\n";
  if (v.recovery) std::cout << "recovery (" << kernel << "): " << recovery_text(*v.recovery) << "\n";
}

}  // namespace kvd::cli
