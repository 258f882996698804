// kvd diff SCENE --kernel double|mpfr:BITS: the differential harness, the
// exact simulation against a floating-point one, event by event.
#include <iostream>

#include "cli.hpp"
#include "json_out.hpp"
#include "kvd/kinetic/differential.hpp"
#include "report.hpp"

namespace kvd::cli {

namespace {
const char* const diff_help =
    "usage: kvd diff SCENE --kernel double|mpfr:BITS|exact [--events N] [--epsilon E]\n"
    "                [--seed S] [--json]\n"
    "\n"
    "Runs the exact kinetic KVD for N certificate failures (default 100) and the\n"
    "same simulation in the chosen kernel over the same span of time (the\n"
    "floating-point one with its recovery, without validation), and compares\n"
    "them event by event. Events match by certificate type and symbolic features\n"
    "and by occurrence (the k-th failure of a certificate in one run with its\n"
    "k-th in the other). Per exact event: the matched inexact event or missed,\n"
    "whether it is in order (same batch as the previous matched event in both\n"
    "runs, or a later one in both), whether the trees just after the two batches\n"
    "are equal, and the absolute and relative error of its time (exact\n"
    "distances, three digits). Inexact events without a match are spurious.\n"
    "--kernel exact compares the exact simulation with a second exact run.\n"
    "\n"
    "  --json   {\"scene\": FILE, \"kernel\": K, \"events\": [{\"event\": I, \"certificate\": C,\n"
    "           \"nodes\": F, \"exact_time\": EXACT, \"exact_approx\": DECIMAL,\n"
    "           \"inexact_event\": J|null, \"inexact_time\": DECIMAL|null,\n"
    "           \"in_order\": BOOL, \"structure_equal\": BOOL, \"time_error\": X|null,\n"
    "           \"relative_time_error\": X|null}, ...], \"spurious\": [{\"inexact_event\": J,\n"
    "           \"certificate\": C, \"nodes\": F, \"inexact_time\": DECIMAL}, ...],\n"
    "           \"events_compared\": N, \"first_divergence_event\": I|null,\n"
    "           \"order_mismatches\": N, \"missed_events\": N, \"spurious_events\": N,\n"
    "           \"structure_mismatches\": N, \"max_time_error\": X,\n"
    "           \"max_relative_time_error\": X, \"seconds_exact\": X,\n"
    "           \"seconds_inexact\": X, \"recovery\": {...}}\n"
    "\n"
    "first_divergence_event is the first exact event (from 0) that is missed,\n"
    "out of order, followed by another tree, or preceded by a spurious event;\n"
    "events_compared when the runs differ only after the last exact event.\n"
    "Divergence is a finding: exit status 0, or 2 on bad input.\n";

// An exact error in scientific notation, or null.
Json error_json(const std::optional<mpq_class>& q) { return q ? decimal(scientific(*q)) : Json(nullptr); }

void print_json(const std::string& scene, const std::string& kernel, const kinetic::Differential& d,
                const kinetic::Simulation<Exact_time>& exact) {
  Json events = Json::array();
  for (std::size_t i = 0; i < d.events.size(); ++i) {
    const auto& m = d.events[i];
    const Exact_time& t = exact.batches[m.exact_batch].time;
    events.push_back({{"event", i},
                      {"certificate", kinetic::to_string(m.failure.type)},
                      {"nodes", kinetic::features(m.failure)},
                      {"exact_time", t.to_string()},
                      {"exact_approx", approx(t.to_double())},
                      {"inexact_event", m.inexact_event ? Json(*m.inexact_event) : Json(nullptr)},
                      {"inexact_time", m.inexact_event ? Json(d.inexact[*m.inexact_event].time) : Json(nullptr)},
                      {"in_order", m.in_order},
                      {"structure_equal", m.structure_equal},
                      {"time_error", m.inexact_event ? decimal(scientific(m.time_error)) : Json(nullptr)},
                      {"relative_time_error", error_json(m.relative_time_error)}});
  }
  Json spurious = Json::array();
  for (std::size_t j = 0; j < d.inexact.size(); ++j)
    if (!d.inexact[j].exact_event)
      spurious.push_back({{"inexact_event", j},
                          {"certificate", kinetic::to_string(d.inexact[j].failure.type)},
                          {"nodes", kinetic::features(d.inexact[j].failure)},
                          {"inexact_time", d.inexact[j].time}});
  const Json report = {
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
      {"seconds_exact", decimal(fixed(d.seconds_exact, 6))},
      {"seconds_inexact", decimal(fixed(d.seconds_inexact, 6))},
      {"recovery", recovery_json(d.recovery)}};
  std::cout << json_lines(report) << "\n";
}

void print_text(const char* kernel, const kinetic::Differential& d, const kinetic::Simulation<Exact_time>& exact) {
  for (std::size_t i = 0; i < d.events.size(); ++i) {
    const auto& m = d.events[i];
    std::cout << "event " << i << " " << kinetic::to_string(m.failure.type) << " " << kinetic::features(m.failure) << " at "
              << approx(exact.batches[m.exact_batch].time.to_double()) << ": ";
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
      std::cout << kernel << " event " << j << " " << kinetic::to_string(d.inexact[j].failure.type) << " "
                << kinetic::features(d.inexact[j].failure) << " at " << d.inexact[j].time << ": spurious\n";
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
            << "seconds:              exact " << fixed(d.seconds_exact, 3) << ", " << kernel << " "
            << fixed(d.seconds_inexact, 3) << "\n"
            << "recovery (" << kernel << "): " << recovery_text(d.recovery) << "\n";
}

}  // namespace

int diff(Args& args) {
  Scene_args sa;
  std::size_t events = 100;
  std::optional<std::string> kernel;
  std::optional<mpq_class> epsilon;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << diff_help;
      return 0;
    }
    if (a == "--events") events = args.unsigned_value(a);
    else if (a == "--kernel") kernel = args.value(a);
    else if (a == "--epsilon") epsilon = exact_option("diff", a, args.value(a));
    else if (!sa.take(args, a)) args.unknown(a);
  }
  if (!kernel) throw Usage_error("kvd diff: missing --kernel double|mpfr:BITS (see kvd diff --help)");
  const scene::Scene s = sa.load_scene("diff");
  const auto progress = [](const char* which) { return progress_every_few_seconds(std::string("kvd diff: ") + which + " run"); };
  // Validate the kernel name before the exact run.
  with_kernel(
      "diff", *kernel,
      [&](const auto& k) {
        require_representable(*sa.path, s, k);
        return 0;
      },
      epsilon);
  const kinetic::Exact_run exact =
      with_disjoint_triangles("diff", *sa.path, [&] { return kinetic::run_exact(s, events, progress("exact")); });
  return with_kernel(
      "diff", *kernel,
      [&](const auto& k) {
        const char* name = std::decay_t<decltype(k)>::name;
        const auto d = kinetic::compare_with(exact, k, s, progress(name));
        if (sa.json) print_json(*sa.path, *kernel, d, exact.sim);
        else print_text(kernel->c_str(), d, exact.sim);
        return 0;
      },
      epsilon);
}

}  // namespace kvd::cli
