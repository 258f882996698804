// kvd bench accuracy: error against run time. For every scene of a fixed set,
// one exact run, then the differential harness (kvd diff) for double, MPFR at
// 24, 53, 113, 256 and 1024 bits, and a second exact run; then the same
// harness on two segment scenes (kvd diff SCENE --kernel K on a
// kvd-segments/1 scene). Writes accuracy.csv (one row per scene and kernel),
// accuracy-segments.csv (the same for the segment scenes), accuracy.md (a
// table per kernel, one per scene, and the segment scenes' table that
// README.md shows) and, when gnuplot is installed, accuracy.svg.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <utility>

#include "bench.hpp"
#include "cli.hpp"
#include "gnuplot.hpp"
#include "kvd/kinetic/differential.hpp"
#include "kvd/segments/segment_differential.hpp"
#include "kvd/segments/segment_io.hpp"
#include "report.hpp"
#include "sweep.hpp"

namespace kvd::bench {

namespace {

const char* const accuracy_help =
    "usage: kvd bench accuracy [--events N] [--scenes A,B,...] [--kernels K1,K2,...]\n"
    "                          [--data DIR] [--out DIR]\n"
    "\n"
    "Error against run time. For every scene, one exact run of N certificate\n"
    "failures (default 100), then kvd diff against each kernel (default double,\n"
    "mpfr:24, mpfr:53, mpfr:113, mpfr:256, mpfr:1024 and exact, a second exact\n"
    "run). Writes DIR/accuracy.csv, DIR/accuracy.md and, with gnuplot on the\n"
    "PATH, DIR/accuracy.svg: the largest relative event-time error and the share\n"
    "of exact events not reproduced (missed, out of order, or another tree after\n"
    "them) against seconds per event, one point per kernel and scene.\n"
    "\n"
    "Then the same on two segment scenes of --data, whatever --scenes, --kernels\n"
    "and --events say: segments/rotating-10 (every event) in double, mpfr:24,\n"
    "mpfr:53 and mpfr:113, and segments/random-100 (300 events) in double and\n"
    "mpfr:24, into DIR/accuracy-segments.csv and accuracy.md's Segment scenes.\n"
    "\n"
    "  --scenes   names under --data (default: random-20, uniform-scale-50,\n"
    "             uniform-density-100, boxes, rotor, viewpoint and the nine\n"
    "             scenes of stiff/)\n"
    "  --data     where the scenes are (default data)\n"
    "  --out      the output directory (default bench-out), created if needed\n"
    "\n"
    "Exit status: 0 on success, 2 on bad input.\n";

const std::vector<std::string> default_scenes{
    "random-20",           "uniform-scale-50",      "uniform-density-100",    "boxes",
    "rotor",               "viewpoint",             "stiff/close-events",     "stiff/simultaneous",
    "stiff/tangential",    "stiff/wide-range",      "stiff/slow-fast",        "stiff/high-degree",
    "stiff/rational-rotation", "stiff/near-degenerate", "stiff/z-near-plane"};
const std::vector<std::string> default_kernels{"double",   "mpfr:24",   "mpfr:53", "mpfr:113",
                                               "mpfr:256", "mpfr:1024", "exact"};

// The segment scenes: the exact run of `events` failures (kvd diff's
// --events; rotating-10 ends before 100) against each kernel.
struct Segment_case {
  std::string scene;
  std::size_t events;
  std::vector<std::string> kernels;
};
const std::vector<Segment_case> segment_cases{
    {"segments/rotating-10", 100, {"double", "mpfr:24", "mpfr:53", "mpfr:113"}},
    {"segments/random-100", 300, {"double", "mpfr:24"}}};

template <class D>
struct Row_of {
  std::string scene, kernel;
  D d;
  // The event count at which the exact run stopped, when it stopped before
  // the scene's end.
  std::optional<std::size_t> cut_at;
  std::size_t events() const { return d.events.size(); }
  double seconds() const { return d.seconds_inexact; }
  // Exact events missed, out of order or followed by another tree.
  std::size_t not_reproduced() const {
    return static_cast<std::size_t>(std::count_if(d.events.begin(), d.events.end(), [](const auto& m) {
      return !m.inexact_event || !m.in_order || !m.structure_equal;
    }));
  }
  double seconds_per_event() const { return events() ? seconds() / static_cast<double>(events()) : 0; }
  double share() const { return events() ? static_cast<double>(not_reproduced()) / static_cast<double>(events()) : 0; }
};
using Row = Row_of<kinetic::Differential>;
using Segment_row = Row_of<segments::Segment_differential>;

// The row of scene and kernel, said on standard error as the suite goes.
template <class D>
Row_of<D> said(const std::string& scene, const std::string& kernel, D d, std::optional<std::size_t> cut_at = {}) {
  Row_of<D> r{scene, kernel, std::move(d), cut_at};
  std::cerr << "kvd bench accuracy: " << r.scene << ", " << r.kernel << ": " << r.events() << " events, "
            << cli::fixed(r.seconds(), 3) << " s, max relative error " << cli::scientific(r.d.max_relative_time_error)
            << ", " << r.not_reproduced() << " not reproduced\n";
  return r;
}

template <class R>
std::string csv(const std::vector<R>& rows) {
  std::string out =
      "scene,kernel,events,seconds,seconds_per_event,max_time_error,max_relative_time_error,"
      "log10_max_relative_time_error,order_mismatches,missed_events,spurious_events,structure_mismatches,"
      "first_divergence_event,not_reproduced_share,failed_builds,refires,rebuilds\n";
  for (const R& r : rows) {
    const auto& d = r.d;
    const std::string log10 = d.max_relative_time_error > 0 ? cli::fixed(cli::log10_of(d.max_relative_time_error), 3) : "NaN";
    out += r.scene + "," + r.kernel + "," + std::to_string(r.events()) + "," + cli::fixed(r.seconds(), 6) + "," +
           cli::approx(r.seconds_per_event()) + "," + cli::scientific(d.max_time_error) + "," +
           cli::scientific(d.max_relative_time_error) + "," + log10 + "," + std::to_string(d.order_mismatches) + "," +
           std::to_string(d.missed_events) + "," + std::to_string(d.spurious_events) + "," +
           std::to_string(d.structure_mismatches) + "," +
           (d.first_divergence_event ? std::to_string(*d.first_divergence_event) : "") + "," +
           cli::fixed(r.share(), 4) + "," + std::to_string(d.recovery.failed_builds) + "," +
           std::to_string(d.recovery.refires) + "," + std::to_string(d.recovery.rebuilds) + "\n";
  }
  return out;
}

// What a kernel gets on a scene, in words: "every event, error ≤ 2.43e-16",
// or "diverges at event 6: 1 missed, 1 followed by another tree; error ≤ ...".
std::string verdict(const Row& r) {
  const std::string error = r.d.max_relative_time_error == 0 ? "no time error"
                                                              : "error ≤ " + cli::scientific(r.d.max_relative_time_error);
  if (!r.d.first_divergence_event) return "every event, " + error;
  std::string parts;
  for (const auto& [n, what] : {std::pair{r.d.missed_events, "missed"}, {r.d.spurious_events, "spurious"},
                                {r.d.order_mismatches, "out of order"}, {r.d.structure_mismatches, "followed by another tree"}})
    if (n) parts += (parts.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  return "diverges at event " + std::to_string(*r.d.first_divergence_event) + (parts.empty() ? "" : ": " + parts) + "; " +
         error;
}

// The scenes of stiff/, one row each: the exact events, then each
// floating-point kernel's verdict (data/stiff/README.md shows this table).
std::string stiff_table(const std::vector<Row>& rows, const std::vector<std::string>& kernels) {
  std::vector<std::string> inexact;
  for (const std::string& k : kernels)
    if (k != "exact") inexact.push_back(k);
  std::string out = "\n## The stiff scenes\n\n| scene | exact events |";
  for (const std::string& k : inexact) out += " " + k + " |";
  out += "\n|---|---:|";
  for (std::size_t i = 0; i < inexact.size(); ++i) out += "---|";
  out += "\n";
  std::vector<std::string> scenes;
  for (const Row& r : rows)
    if (r.scene.rfind("stiff/", 0) == 0 && std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end())
      scenes.push_back(r.scene);
  for (const std::string& scene : scenes) {
    std::string line;
    std::size_t events = 0;
    for (const std::string& k : inexact)
      for (const Row& r : rows)
        if (r.scene == scene && r.kernel == k) {
          events = r.events();
          line += " " + verdict(r) + " |";
        }
    out += "| " + scene.substr(6) + " | " + std::to_string(events) + " |" + line + "\n";
  }
  return out;
}

// Per kernel: median seconds per event, the worst relative error, and how
// many scenes diverged; the stiff scenes in words; then the whole table.
std::string markdown(const std::vector<Row>& rows, const std::vector<std::string>& kernels, std::size_t events) {
  std::string out = "## Per kernel\n\nPer kernel, over " + std::to_string(rows.size() / std::max<std::size_t>(1, kernels.size())) +
                    " scenes of up to " + std::to_string(events) + " exact events each:\n\n"
                    "| kernel | median ms per event | worst relative time error | scenes diverging | "
                    "events not reproduced | missed | spurious | failed builds repaired |\n"
                    "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const std::string& k : kernels) {
    std::vector<double> spe;
    mpq_class worst = 0;
    std::size_t diverging = 0, scenes = 0, not_reproduced = 0, total = 0, missed = 0, spurious = 0, repaired = 0;
    for (const Row& r : rows) {
      if (r.kernel != k) continue;
      ++scenes;
      spe.push_back(1000 * r.seconds_per_event());
      if (r.d.max_relative_time_error > worst) worst = r.d.max_relative_time_error;
      diverging += r.d.first_divergence_event.has_value();
      not_reproduced += r.not_reproduced();
      total += r.events();
      missed += r.d.missed_events;
      spurious += r.d.spurious_events;
      repaired += r.d.recovery.failed_builds;
    }
    out += "| " + k + " | " + cli::fixed(cli::median(spe), 3) + " | " + cli::scientific(worst) + " | " +
           std::to_string(diverging) + " of " + std::to_string(scenes) + " | " + std::to_string(not_reproduced) +
           " of " + std::to_string(total) + " | " + std::to_string(missed) + " | " + std::to_string(spurious) + " | " +
           std::to_string(repaired) + " |\n";
  }
  out += stiff_table(rows, kernels);
  out += "\n## Per scene and kernel\n\n"
         "| scene | kernel | events | ms per event | max relative time error | first divergence | "
         "order | missed | spurious | structure |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows)
    out += "| " + r.scene + " | " + r.kernel + " | " + std::to_string(r.events()) + " | " +
           cli::fixed(1000 * r.seconds_per_event(), 3) + " | " + cli::scientific(r.d.max_relative_time_error) + " | " +
           (r.d.first_divergence_event ? std::to_string(*r.d.first_divergence_event) : "-") + " | " +
           std::to_string(r.d.order_mismatches) + " | " + std::to_string(r.d.missed_events) + " | " +
           std::to_string(r.d.spurious_events) + " | " + std::to_string(r.d.structure_mismatches) + " |\n";
  return out;
}

// The segment scenes, one row per kernel, as README.md shows them: the
// relative error to two significant digits; builds repaired are the failed
// builds the run made again at a later instant (Recovery::failed_builds).
std::string segment_table(const std::vector<Segment_row>& rows) {
  std::string out =
      "\n## Segment scenes\n\n"
      "| scene | kernel | events | first divergence | missed | another tree after | max relative time error | "
      "builds repaired |\n|---|---|---:|---:|---:|---:|---:|---:|\n";
  std::string previous;
  for (const Segment_row& r : rows) {
    const std::string scene =
        r.scene == previous ? "" : r.scene + (r.cut_at ? ", " + std::to_string(*r.cut_at) + " events" : "");
    previous = r.scene;
    out += "| " + scene + " | " + r.kernel + " | " + std::to_string(r.events()) + " | " +
           (r.d.first_divergence_event ? std::to_string(*r.d.first_divergence_event) : "none") + " | " +
           std::to_string(r.d.missed_events) + " | " + std::to_string(r.d.structure_mismatches) + " | " +
           cli::scientific(r.d.max_relative_time_error, 1) + " | " + std::to_string(r.d.recovery.failed_builds) +
           " |\n";
  }
  return out;
}

// Column numbers refer to csv() above.
std::string gnuplot_script(const std::string& csv_path, const std::string& svg_path,
                           const std::vector<std::string>& kernels, std::size_t events) {
  // The exact kernel's error is zero, which a log axis cannot show: it is
  // only in the right-hand panel.
  std::string list, inexact;
  for (const auto& k : kernels) {
    list += (list.empty() ? "" : " ") + k;
    if (k != "exact") inexact += (inexact.empty() ? "" : " ") + k;
  }
  return "set terminal svg size 1100,460 dynamic enhanced font 'sans,12'\n"
         "set output '" + svg_path + "'\n"
         "set datafile separator ','\n"
         "set datafile missing 'NaN'\n"
         "kernels = '" + list + "'\n"
         "inexact = '" + inexact + "'\n"
         "set multiplot layout 1,2 title 'Floating-point kernels against the exact kernel (" + std::to_string(events) +
         " exact events per scene, one point per kernel and scene)'\n"
         "set logscale x\n"
         "set format x '10^{%L}'\n"
         "set grid\n"
         "set xlabel 'seconds per event (log)'\n"
         "set key bottom left\n"
         "set ylabel 'log10 of the largest relative event-time error'\n"
         "plot for [i=1:words(inexact)] '" + csv_path + "' skip 1 using "
         "(strcol(2) eq word(inexact, i) ? column(5) : NaN):(column(8)) with points pt i ps 1.2 title word(inexact, i)\n"
         "set ylabel 'share of exact events not reproduced'\n"
         "set yrange [-0.05:1.05]\n"
         "set key top right\n"
         "plot for [i=1:words(kernels)] '" + csv_path + "' skip 1 using "
         "(strcol(2) eq word(kernels, i) ? column(5) : NaN):(column(14)) with points pt i ps 1.2 title word(kernels, i)\n"
         "unset multiplot\n";
}

}  // namespace

int accuracy(cli::Args& args) {
  std::size_t events = 100;
  std::vector<std::string> scenes = default_scenes, kernels = default_kernels;
  std::string data = "data", out = "bench-out";
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << accuracy_help;
      return 0;
    }
    if (a == "--events") events = args.unsigned_value(a);
    else if (a == "--scenes") scenes = cli::comma_list(args.value(a));
    else if (a == "--kernels") kernels = cli::comma_list(args.value(a));
    else if (a == "--data") data = args.value(a);
    else if (a == "--out") out = args.value(a);
    else args.unknown(a);
  }
  // Check every name before the first run, so bad input costs nothing.
  check_out("accuracy", out);
  for (const std::string& k : kernels) cli::with_kernel("bench accuracy", k, [](const auto&) { return 0; });
  std::vector<scene::Scene> loaded;
  for (const std::string& s : scenes) loaded.push_back(scene::load_scene(data + "/" + s + ".json"));
  std::vector<segments::Segment_scene> segment_scenes;
  for (const Segment_case& c : segment_cases) segment_scenes.push_back(segments::load_segments(data + "/" + c.scene + ".json"));
  make_out("accuracy", out);

  std::vector<Row> rows;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const kinetic::Exact_run exact = kinetic::run_exact(loaded[i], events);
    for (const std::string& name : kernels)
      rows.push_back(said(scenes[i], name, cli::with_kernel("bench accuracy", name, [&](const auto& k) {
                            return kinetic::compare_with(exact, k, loaded[i]);
                          })));
  }
  std::vector<Segment_row> segment_rows;
  for (std::size_t i = 0; i < segment_cases.size(); ++i) {
    const Segment_case& c = segment_cases[i];
    const segments::Segment_exact_run exact = segments::run_exact(segment_scenes[i], c.events);
    const std::optional<std::size_t> cut_at = exact.stopped_at ? std::optional(c.events) : std::nullopt;
    for (const std::string& name : c.kernels)
      segment_rows.push_back(said(c.scene, name, cli::with_kernel("bench accuracy", name, [&](const auto& k) {
                                    return segments::compare_with(exact, k, segment_scenes[i]);
                                  }), cut_at));
  }
  const std::string csv_path = out + "/accuracy.csv", svg_path = out + "/accuracy.svg";
  const std::string md = markdown(rows, kernels, events) + segment_table(segment_rows);
  cli::write_atomically("bench accuracy", csv_path, csv(rows));
  cli::write_atomically("bench accuracy", out + "/accuracy-segments.csv", csv(segment_rows));
  cli::write_atomically("bench accuracy", out + "/accuracy.md", md);
  std::cout << md;
  // The script stays beside the data, to re-plot by hand.
  if (!run_gnuplot("accuracy", out + "/accuracy.gp", gnuplot_script(csv_path, svg_path, kernels, events), {svg_path}))
    return 0;
  std::cerr << "kvd bench accuracy: wrote " << csv_path << ", " << out << "/accuracy-segments.csv, " << out
            << "/accuracy.md, " << svg_path << "\n";
  return 0;
}

}  // namespace kvd::bench
