// kvd bench aeg-cost: the cost of an event of the kinetic BSP of segments
// (seed 003, section 3.1) against n, counted in what does not depend on the
// machine (the signs an update decides, the nodes it makes again) beside its
// time: the local update on the kept certificate set, and the run on the
// paper's set. Generated segments-random scenes, seed 1, all and half
// moving; then segments-rotating, all turning, for the cost of a flip. Writes aeg-cost.csv, aeg-cost.md and, with gnuplot, aeg-cost.svg.
#include "aeg_cost.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "bench.hpp"
#include "cli.hpp"
#include "gnuplot.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "kvd/segments/segment_crossings.hpp"
#include "report.hpp"
#include "sweep.hpp"

namespace kvd::bench {

namespace {

using namespace aeg_cost_suite;

const char* const aeg_cost_help =
    "usage: kvd bench aeg-cost [--sizes N,N,...] [--events N] [--out DIR]\n"
    "\n"
    "The cost of an event of the kinetic BSP of segments (seed 003, section\n"
    "3.1) against n, on kvd generate segments-random --n N --moving M --seed 1\n"
    "(M = N and N/2), exact kernel, up to the batch holding the N-th\n"
    "certificate failure (--events, default 2000), without validation. Two\n"
    "runs of each scene: the local update on the kept certificate set (one\n"
    "certificate per sign of the construction), and the run on the paper's\n"
    "certificates (transient cells, endpoints' neighbours, flips). Per batch:\n"
    "the signs the update decided (by any rule: identity, the interval filter,\n"
    "exact arithmetic, the perturbation), the signs it read from the\n"
    "certificates in force, the signs it asked again and answered from their\n"
    "first decision in the batch (the run on the paper's set only), the nodes\n"
    "it made again, and its time. The counts are the same on any machine; the\n"
    "times are this one's. Then both runs of kvd generate segments-rotating\n"
    "--n N --seed 1 (all turning, so that segments flip), for the cost of a\n"
    "batch whose one failure is a flip.\n"
    "\n"
    "Writes aeg-cost.csv, aeg-cost.md and, when gnuplot is installed,\n"
    "aeg-cost.svg (the plot's data in aeg-cost.dat) to --out.\n"
    "\n"
    "options:\n"
    "  --sizes            segments (default 100,200,400,800,1600,3200,6400,12800)\n"
    "  --flip-sizes       rotating segments (default 25,50,100,200,400,800,1600)\n"
    "  --events N         failures per run (default 2000)\n"
    "  --out              the output directory (default bench-out), created if\n"
    "                     needed\n"
    "\n"
    "Exit status: 0 on success, 2 on bad input.\n";

// The smallest value at or above 90% of the batches.
double p90(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::ceil(0.9 * static_cast<double>(v.size()))) - 1];
}

// `run` advanced up to the batch holding the `events`-th failure, or the
// span's end; the row's run, n, m, k and nodes are the caller's.
template <class Run>
void measure(Run& run, std::size_t events, const std::string& label, Run_row& row) {
  const auto progress = cli::progress_every_few_seconds(label);
  std::vector<double> signs, held, repeated, made, ms, flip_nodes, flip_signs, flip_ms;
  std::array<std::vector<double>, segments::Aeg_phases::count> phases;
  while (row.failures < events && run.next_event_time()) {
    const auto b = run.advance();
    ++row.batches;
    row.failures += b.failing.size();
    std::size_t touched = b.nodes_rebuilt;
    bool flip = false;
    if constexpr (requires { b.phases; }) {  // the run on the paper's set
      // A flip fails with the transient cells between the segment's points,
      // which close as it turns vertical.
      using Kind = segments::Aeg_certificate_kind;
      flip = std::count_if(b.failing.begin(), b.failing.end(), [](const auto& f) { return f.kind == Kind::flip; }) == 1 &&
             std::all_of(b.failing.begin(), b.failing.end(), [](const auto& f) { return f.kind != Kind::endpoint; });
      touched += b.nodes_edited;
      row.flips_in_place += flip && b.flipped_in_place > 0;
    } else {
      // A flip fails with the other x orders of the segment's points that
      // its turning changes, all flips (event_in_batch); one segment's own
      // endpoints' x order among them makes it one flip.
      const auto own = [](const segments::Segment_certificate_key& key) {
        using Point = segments::Site_point;
        return key.kind == segments::Segment_certificate_key::Kind::x_order && key.p.kind == Point::Kind::endpoint &&
               key.q.kind == Point::Kind::endpoint && key.p.a / 2 == key.q.a / 2;
      };
      flip = b.events[static_cast<std::size_t>(segments::Segment_event::flip)] == b.failing.size() &&
             std::count_if(b.failing.begin(), b.failing.end(), own) == 1;
    }
    if (flip) {
      ++row.lone_flips;
      flip_nodes.push_back(static_cast<double>(touched));
      flip_signs.push_back(static_cast<double>(b.signs));
      flip_ms.push_back(1e3 * b.update_seconds);
    }
    signs.push_back(static_cast<double>(b.signs));
    held.push_back(static_cast<double>(b.held));
    repeated.push_back(static_cast<double>(b.repeated));
    if constexpr (requires { b.phases; }) {  // the run on the paper's set
      const auto named = b.phases.named();
      for (std::size_t i = 0; i < named.size(); ++i) phases[i].push_back(static_cast<double>(named[i].second));
      row.other_guard_max = std::max(row.other_guard_max, static_cast<double>(b.phases.other_guard));
    }
    made.push_back(static_cast<double>(b.nodes_rebuilt));
    ms.push_back(1e3 * b.update_seconds);
    progress(row.batches, row.failures);
  }
  row.signs_median = cli::median(signs);
  row.signs_mean = mean_of(signs);
  row.signs_p90 = p90(signs);
  row.signs_max = max_of(signs);
  row.held_mean = mean_of(held);
  row.repeated_mean = mean_of(repeated);
  row.phased = !phases[0].empty();
  for (std::size_t i = 0; i < phases.size(); ++i) row.phase_means[i] = mean_of(phases[i]);
  row.nodes_made_median = cli::median(made);
  row.nodes_made_mean = mean_of(made);
  row.nodes_made_max = max_of(made);
  row.mean_ms = mean_of(ms);
  row.median_ms = cli::median(ms);
  row.max_ms = max_of(ms);
  row.flip_nodes_median = cli::median(flip_nodes);
  row.flip_nodes_max = max_of(flip_nodes);
  row.flip_signs_median = cli::median(flip_signs);
  row.flip_signs_max = max_of(flip_signs);
  row.flip_median_ms = cli::median(flip_ms);
  std::cerr << label << ": " << row.batches << " batches, " << row.failures << " failures, signs decided a batch: mean "
            << cli::fixed(row.signs_mean, 1) << ", nodes made: mean " << cli::fixed(row.nodes_made_mean, 1) << ", "
            << cli::fixed(row.mean_ms, 3) << " ms\n";
}

std::vector<Run_row> measure_scene(segments::Segment_family family, std::size_t n, std::size_t m, const Config& c) {
  const segments::Segment_scene s = generated_segments("aeg-cost", family, n, m, segments::Crossings::linear);
  const Exact_kernel k;
  Run_row base;
  base.family = family == segments::Segment_family::rotating ? "rotating" : "random";
  base.n = n;
  base.m = m;
  base.k = segments::count_crossings(s, s.start);
  const std::string label =
      "kvd bench aeg-cost: " + base.family + ", n = " + std::to_string(n) + ", m = " + std::to_string(m);
  std::vector<Run_row> rows(2, base);
  {
    segments::Kinetic_segment_bsp<Exact_kernel> local(k, s, false, segments::Segment_update::local);
    rows[0].run = "local";
    rows[0].nodes = local.tree().counts().nodes;
    measure(local, c.events, label + ", local update", rows[0]);
  }
  segments::Aeg_kinetic_bsp<Exact_kernel> paper(k, s, false);
  rows[1].run = "paper";
  rows[1].nodes = paper.tree().counts().nodes;
  measure(paper, c.events, label + ", the paper's set", rows[1]);
  return rows;
}

}  // namespace

int aeg_cost(cli::Args& args) {
  Config c;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << aeg_cost_help;
      return 0;
    }
    if (a == "--sizes") c.sizes = sizes_option("aeg-cost", args.value(a), a, "segments");
    else if (a == "--flip-sizes") c.flip_sizes = sizes_option("aeg-cost", args.value(a), a, "segments");
    else if (a == "--events") {
      c.events = args.unsigned_value(a);
      if (c.events < 1) throw cli::Usage_error("kvd bench aeg-cost: --events must be at least 1");
    }
    else if (a == "--out") c.out = args.value(a);
    else args.unknown(a);
  }
  check_out("aeg-cost", c.out);
  make_out("aeg-cost", c.out);
  std::vector<Run_row> rows;
  for (const std::size_t n : c.sizes)
    for (const std::size_t m : {n, n / 2})
      if (m > 0)
        for (Run_row& r : measure_scene(segments::Segment_family::random, n, m, c)) rows.push_back(std::move(r));
  for (const std::size_t n : c.flip_sizes)
    for (Run_row& r : measure_scene(segments::Segment_family::rotating, n, n, c)) rows.push_back(std::move(r));
  cli::write_atomically("bench aeg-cost", c.out + "/aeg-cost.csv", csv(rows));
  cli::write_atomically("bench aeg-cost", c.out + "/aeg-cost.dat", plot_data(c, rows));
  const bool plotted = run_gnuplot("aeg-cost", c.out + "/aeg-cost.gp", gnuplot_script(c), {c.out + "/aeg-cost.svg"});
  const std::string md = markdown(c, rows, plotted);
  cli::write_atomically("bench aeg-cost", c.out + "/aeg-cost.md", md);
  std::cout << md;
  std::cerr << "kvd bench aeg-cost: wrote " << c.out << "/aeg-cost.md, " << c.out << "/aeg-cost.csv"
            << (plotted ? ", " + c.out + "/aeg-cost.svg" : std::string()) << "\n";
  return 0;
}

}  // namespace kvd::bench
