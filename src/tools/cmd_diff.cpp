// kvd diff SCENE --kernel double|mpfr:BITS: the differential harness, the
// exact simulation against a floating-point one, event by event.
#include <iostream>

#include "cli.hpp"
#include "diff_report.hpp"
#include "kvd/kinetic/differential.hpp"
#include "kvd/segments/segment_io.hpp"
#include "report.hpp"
#include "segment_commands.hpp"

namespace kvd::cli {

namespace {
const char* const diff_help =
    "usage: kvd diff SCENE --kernel double|mpfr:BITS|exact [--events N] [--epsilon E]\n"
    "                [--seed S] [--json]\n"
    "                [--allow-intersecting]\n"
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
    "           \"max_relative_time_error\": X,\n"
    "           \"inexact_stopped\": \"events\"|\"limit\"|\"exhausted\"|\"collision\"|\"stuck\",\n"
    "           \"seconds_exact\": X, \"seconds_inexact\": X, \"recovery\": {...}}\n"
    "  --allow-intersecting\n"
    "           accept triangles that intersect at the start time\n"
    "\n"
    "A segment scene (kvd-segments/1) runs the kinetic segment BSP the same way.\n"
    "Its events are the certificates of kvd certify: in place of \"certificate\" and\n"
    "\"nodes\", \"certificate\": \"x_order\"|\"side\"|\"order_at\", \"event_kind\": the\n"
    "paper's vertex|edge|intersection|flip, \"features\": \"s0.1 s2xs3\". Its trees\n"
    "are compared by their text. Its floating-point recovery repairs only\n"
    "builds whose signs contradict each other (failed_builds, rebuilds,\n"
    "unrepaired), by building again at now + 2^i epsilon.\n"
    "\n"
    "first_divergence_event is the first exact event (from 0) that is missed,\n"
    "out of order, followed by another tree, or preceded by a spurious event;\n"
    "events_compared when the runs differ only after the last exact event.\n"
    "inexact_stopped says why the floating-point run ended: limit when it reached\n"
    "the exact run's last batch (where --events stopped that) or the scene's end;\n"
    "exhausted when no certificate was left to fail; events at its own cap of\n"
    "2N + 100 failures; stuck when it could not advance (kvd simulate exits 1\n"
    "there), every exact event after that then missed.\n"
    "Divergence is a finding, a stuck run included: exit status 0; 1 when the\n"
    "floating-point run cannot start because its rounding makes triangles cross\n"
    "that the exact kernel keeps apart; 2 on bad input.\n";

Diff_view<kinetic::Failure> view(const kinetic::Differential& d, const kinetic::Simulation<Exact_time>& exact) {
  return {d,
          [&exact](std::size_t b) -> const Exact_time& { return exact.batches[b].time; },
          [](const kinetic::Failure& f) {
            return Json{{"certificate", kinetic::to_string(f.type)}, {"nodes", kinetic::features(f)}};
          },
          [](const kinetic::Failure& f) { return std::string(kinetic::to_string(f.type)) + " " + kinetic::features(f); },
          d.recovery};
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
  const std::string text = sa.read_text("diff");
  if (segments::scene_format(text) == "kvd-segments/1") {
    if (sa.load.allow_intersecting) refuse_triangle_flags("diff", {"--allow-intersecting"});
    return segment_diff(sa, text, *kernel, events, epsilon);
  }
  const scene::Scene s = sa.read_scene("diff", text);
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
        const auto d = with_disjoint_triangles_in("diff", *sa.path, k, s, s.start,
                                                  [&] { return kinetic::compare_with(exact, k, s, progress(name)); });
        if (sa.json) print_diff_json(*sa.path, *kernel, view(d, exact.sim));
        else print_diff_text(*kernel, view(d, exact.sim));
        return 0;
      },
      epsilon);
}

}  // namespace kvd::cli
