// kvd bench aeg: the cylindrical BSP of intersecting segments against the
// bounds of Agarwal, Erickson and Guibas (seed 003): size O(n log n + k) and
// depth O(log n) of the static tree (Theorem 2.3), and the events of the
// kinetic one (Lemmas 3.2-3.6) with the cost of a batch, local update
// against rebuild. Generated segments-random scenes, seed 1. Writes aeg.csv,
// aeg.md and, with gnuplot, aeg.svg.
#include "aeg.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <limits>
#include <optional>
#include <tuple>

#include "bench.hpp"
#include "cli.hpp"
#include "gnuplot.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kernel/float_kernel.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "kvd/segments/segment_crossings.hpp"
#include "kvd/segments/segment_generators.hpp"
#include "report.hpp"
#include "sweep.hpp"

namespace kvd::bench {

namespace {

using namespace aeg_suite;
using segments::Crossings;
using segments::Segment_family;

const char* const aeg_help =
    "usage: kvd bench aeg [--sizes N,N,...] [--quadratic-up-to N] [--kinetic-sizes N,N,...]\n"
    "                     [--subtree-up-to N] [--rebuild-up-to N] [--kinetic-quadratic-up-to N]\n"
    "                     [--events N] [--rotating N] [--rotating-long N,N,...] [--repeats N]\n"
    "                     [--out DIR]\n"
    "\n"
    "The cylindrical BSP of intersecting segments (seed 003) against the paper's\n"
    "bounds, on the scenes of kvd generate segments-random --n N --seed 1:\n"
    "  static    for each size, short segments (--crossings linear: k = O(n))\n"
    "            and, up to --quadratic-up-to segments (default 400), long ones\n"
    "            (--crossings quadratic: k = Theta(n^2)), none moving: k counted\n"
    "            exactly, the tree's nodes, cuts by kind and height, nodes /\n"
    "            (n log2 n + k) and height / log2 n (Theorem 2.3), and the build\n"
    "            time, exact and double, interleaved and repeated (--repeats,\n"
    "            default 3; medians)\n"
    "  kinetic   for each kinetic size n, all and half of the segments moving\n"
    "            linearly (m = n, n/2), short segments and, up to\n"
    "            --kinetic-quadratic-up-to segments (default 200), long ones,\n"
    "            up to the batch holding\n"
    "            the N-th certificate failure (--events, default 50); and a\n"
    "            scene of --rotating segments (default 20, 0: none) turning\n"
    "            through vertical (segments-rotating, flip events) over its\n"
    "            whole span, and one of long segments for each --rotating-long\n"
    "            size (default 30,60, 0: none; --crossings quadratic; no rebuild:\n"
    "            thousands of batches): the exact kinetic BSP without\n"
    "            validation, its\n"
    "            local update, its subtree update (up to --subtree-up-to\n"
    "            segments, default 3200) and its rebuild (up to\n"
    "            --rebuild-up-to, default 800) run batch by batch in turn;\n"
    "            failures by event kind (vertex, edge, intersection, flip) and\n"
    "            their rates per unit of time over m n (flips: over m), the\n"
    "            mean and max update per batch of each, the nodes the local\n"
    "            and the subtree update made again, the share of failures the\n"
    "            frontier replay handled, and whether all had the same batches\n"
    "            and end in the same tree (they must)\n"
    "Writes DIR/aeg.csv, DIR/aeg.md (also to stdout) and, with gnuplot on the\n"
    "PATH, DIR/aeg.svg (the two ratios and the update time against n);\n"
    "progress goes to stderr.\n"
    "\n"
    "  --sizes            segments of the static part (default\n"
    "                     100,200,400,800,1600,3200,6400,12800)\n"
    "  --kinetic-sizes    segments of the kinetic part (default\n"
    "                     100,200,400,800,1600,3200,6400,12800)\n"
    "  --out              the output directory (default bench-out), created if\n"
    "                     needed\n"
    "\n"
    "Exit status: 0 on success, 1 when the updates differ,\n"
    "2 on bad input.\n";

// The build at the scene's start in ms, and the tree's counts.
template <class K>
std::pair<double, segments::Bsp_counts> build(const K& k, const segments::Segment_scene& s) {
  const auto start = std::chrono::steady_clock::now();
  const segments::Segment_predicates<K> pred(k, s);
  const segments::Cylindrical_bsp b =
      segments::build_cylindrical_bsp(pred, k.time(from_rational<typename K::FT>(s.start)));
  return {ms_since(start), b.counts()};
}

Static_row measure_static(std::size_t n, Crossings crossings, const Config& c) {
  Static_row row;
  row.crossings = crossings == Crossings::linear ? "linear" : "quadratic";
  row.n = n;
  const segments::Segment_scene s = generated_segments("aeg", Segment_family::random, n, 0, crossings);
  row.k = segments::count_crossings(s, s.start);
  std::vector<double> exact, dbl;
  for (int r = 0; r < c.repeats; ++r) {
    double ms = 0;
    std::tie(ms, row.counts) = build(Exact_kernel(), s);
    exact.push_back(ms);
    dbl.push_back(build(Double_kernel(), s).first);
    std::cerr << "kvd bench aeg: " << n << " segments, " << row.crossings << " crossings (k = " << row.k
              << "), repetition " << r + 1 << " of " << c.repeats << ": " << row.counts.nodes << " nodes, build exact "
              << cli::fixed(exact.back(), 1) << " ms, double " << cli::fixed(dbl.back(), 1) << " ms\n";
  }
  row.build_exact_ms = cli::median(exact);
  row.build_double_ms = cli::median(dbl);
  return row;
}

// Up to the batch holding the `events`-th failure, or the span's end.
Kinetic_row measure_kinetic(Segment_family family, std::size_t n, std::size_t m, std::size_t events,
                            const Config& c, Crossings crossings = Crossings::linear) {
  Kinetic_row row;
  row.family = family == Segment_family::rotating ? "rotating" : "random";
  row.crossings = crossings == Crossings::linear ? "linear" : "quadratic";
  row.n = n;
  row.m = m;
  const segments::Segment_scene s = generated_segments("aeg", family, n, m, crossings);
  row.k = segments::count_crossings(s, s.start);
  using Kinetic = segments::Kinetic_segment_bsp<Exact_kernel>;
  const Exact_kernel k;
  Kinetic local(k, s, false, segments::Segment_update::local);
  std::optional<Kinetic> subtree, rebuild;
  row.subtree_run = n <= c.subtree_up_to;
  // The long rotating scenes have thousands of batches: no rebuild there.
  row.rebuild_run = n <= c.rebuild_up_to && !(family == Segment_family::rotating && crossings == Crossings::quadratic);
  {
    const segments::Cylindrical_bsp tree = local.tree();
    row.nodes = tree.counts().nodes;
    row.certificates = local.certificates();
    row.aeg = segments::aeg_certificate_counts(tree, n);
  }
  if (row.subtree_run) subtree.emplace(k, s, false, segments::Segment_update::subtree);
  if (row.rebuild_run) rebuild.emplace(k, s, false, segments::Segment_update::rebuild);
  const std::string label =
      "kvd bench aeg: " + row.family + (row.crossings == "linear" ? "" : ", long segments") +
      ", n = " + std::to_string(n) + ", m = " + std::to_string(m);
  const auto progress = cli::progress_every_few_seconds(label);
  std::vector<double> local_ms, subtree_ms, rebuild_ms, nodes, subtree_nodes;
  std::vector<std::size_t> flips;  // the batches holding a flip failure
  std::size_t frontier = 0, replays = 0;
  // The reference updates run batch by batch with the local one, and must
  // process the same batches.
  const auto follow = [&](std::optional<Kinetic>& other, const Kinetic::Batch& a, std::vector<double>& ms,
                          std::vector<double>* made) {
    if (!other) return;
    if (!other->next_event_time()) {
      row.same = false;
      return;
    }
    const Kinetic::Batch b = other->advance();
    row.same = row.same && k.compare(a.time, b.time) == 0 && a.failing == b.failing;
    ms.push_back(1e3 * b.update_seconds);
    if (made) made->push_back(static_cast<double>(b.nodes_rebuilt));
  };
  while (row.failures < events && local.next_event_time()) {
    const Kinetic::Batch a = local.advance();
    follow(subtree, a, subtree_ms, &subtree_nodes);
    follow(rebuild, a, rebuild_ms, nullptr);
    frontier += a.frontier_replays;
    replays += a.frontier_replays + a.subtree_replays;
    ++row.batches;
    row.failures += a.failing.size();
    row.changed += a.changed;
    for (std::size_t e = 0; e < row.events.size(); ++e) row.events[e] += a.events[e];
    if (a.events[static_cast<std::size_t>(segments::Segment_event::flip)] > 0) {
      flips.push_back(local_ms.size());
      row.flip_whole += a.subtree_replays;
    }
    local_ms.push_back(1e3 * a.update_seconds);
    nodes.push_back(static_cast<double>(a.nodes_rebuilt));
    progress(row.batches, row.failures);
  }
  const std::string tree = local.tree().text();
  for (auto* other : {&subtree, &rebuild})
    if (*other)
      row.same = row.same && (*other)->tree().text() == tree &&
                 (*other)->next_event_time().has_value() == local.next_event_time().has_value();
  // A run that reached the span's end saw all of it (generated scenes have one).
  row.time = (local.next_event_time() ? k.to_double(local.now()) : s.end->get_d()) - s.start.get_d();
  row.local_mean_ms = mean_of(local_ms);
  row.local_max_ms = max_of(local_ms);
  row.subtree_mean_ms = mean_of(subtree_ms);
  row.subtree_max_ms = max_of(subtree_ms);
  row.rebuild_mean_ms = mean_of(rebuild_ms);
  row.rebuild_max_ms = max_of(rebuild_ms);
  row.nodes_rebuilt_median = cli::median(nodes);
  row.subtree_nodes_median = cli::median(subtree_nodes);
  row.frontier_share = replays ? static_cast<double>(frontier) / static_cast<double>(replays) : 0;
  // The flip batches apart (the subtree update ran the same batches, in turn).
  const auto pick = [&](const std::vector<double>& all, bool in) {
    std::vector<double> out;
    for (std::size_t i = 0, f = 0; i < all.size(); ++i) {
      const bool flip = f < flips.size() && flips[f] == i;
      f += flip;
      if (flip == in) out.push_back(all[i]);
    }
    return out;
  };
  const std::vector<double> flip_ms = pick(local_ms, true), flip_subtree_ms = pick(subtree_ms, true);
  const std::vector<double> flip_nodes = pick(nodes, true), flip_subtree_nodes = pick(subtree_nodes, true);
  row.flip_batches = flips.size();
  row.flip_local_mean_ms = mean_of(flip_ms);
  row.flip_local_max_ms = max_of(flip_ms);
  row.flip_nodes_median = cli::median(flip_nodes);
  row.flip_nodes_max = max_of(flip_nodes);
  row.flip_subtree_mean_ms = mean_of(flip_subtree_ms);
  row.flip_subtree_max_ms = max_of(flip_subtree_ms);
  row.flip_subtree_nodes_median = cli::median(flip_subtree_nodes);
  row.flip_subtree_nodes_max = max_of(flip_subtree_nodes);
  row.other_local_mean_ms = mean_of(pick(local_ms, false));
  std::cerr << label << ": " << row.batches << " batches, " << row.failures << " failures, update mean local "
            << cli::fixed(row.local_mean_ms, 2) << " ms"
            << (row.subtree_run ? ", subtree " + cli::fixed(row.subtree_mean_ms, 2) + " ms" : std::string())
            << (row.rebuild_run ? ", rebuild " + cli::fixed(row.rebuild_mean_ms, 2) + " ms" : std::string())
            << (row.same ? "" : "; the updates differ") << "\n";
  return row;
}

}  // namespace

int aeg(cli::Args& args) {
  Config c;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << aeg_help;
      return 0;
    }
    if (a == "--sizes") c.sizes = sizes_option("aeg", args.value(a), a, "segments");
    else if (a == "--quadratic-up-to") c.quadratic_up_to = args.unsigned_value(a);
    else if (a == "--kinetic-sizes") c.kinetic_sizes = sizes_option("aeg", args.value(a), a, "segments");
    else if (a == "--subtree-up-to") c.subtree_up_to = args.unsigned_value(a);
    else if (a == "--rebuild-up-to") c.rebuild_up_to = args.unsigned_value(a);
    else if (a == "--kinetic-quadratic-up-to") c.kinetic_quadratic_up_to = args.unsigned_value(a);
    else if (a == "--events") c.events = args.unsigned_value(a);
    else if (a == "--rotating") c.rotating = args.unsigned_value(a);
    else if (a == "--rotating-long") {
      const std::string& v = args.value(a);
      c.rotating_long = v == "0" ? std::vector<std::size_t>{} : sizes_option("aeg", v, a, "segments");
    }
    else if (a == "--repeats") {
      const std::size_t r = args.unsigned_value(a);
      if (r < 1 || r > 100) throw cli::Usage_error("kvd bench aeg: --repeats must be between 1 and 100");
      c.repeats = static_cast<int>(r);
    } else if (a == "--out") c.out = args.value(a);
    else args.unknown(a);
  }
  make_out("aeg", c.out);

  std::vector<Static_row> statics;
  for (Crossings crossings : {Crossings::linear, Crossings::quadratic})
    for (std::size_t n : c.sizes)
      if (crossings == Crossings::linear || n <= c.quadratic_up_to) statics.push_back(measure_static(n, crossings, c));
  std::vector<Kinetic_row> kinetics;
  for (std::size_t n : c.kinetic_sizes)
    for (std::size_t m : {n, n / 2})
      if (m > 0) kinetics.push_back(measure_kinetic(Segment_family::random, n, m, c.events, c));
  for (std::size_t n : c.kinetic_sizes)
    for (std::size_t m : {n, n / 2})
      if (m > 0 && n <= c.kinetic_quadratic_up_to)
        kinetics.push_back(measure_kinetic(Segment_family::random, n, m, c.events, c, Crossings::quadratic));
  // The rotating scenes run over their whole span.
  constexpr std::size_t the_span = std::numeric_limits<std::size_t>::max();
  if (c.rotating > 0)
    kinetics.push_back(measure_kinetic(Segment_family::rotating, c.rotating, c.rotating, the_span, c, Crossings::linear));
  for (const std::size_t n : c.rotating_long)
    kinetics.push_back(measure_kinetic(Segment_family::rotating, n, n, the_span, c, Crossings::quadratic));

  cli::write_atomically("bench aeg", c.out + "/aeg.csv", csv(statics, kinetics));
  cli::write_atomically("bench aeg", c.out + "/aeg-static.dat", static_plot_data(statics));
  cli::write_atomically("bench aeg", c.out + "/aeg-kinetic.dat", kinetic_plot_data(kinetics));
  const bool plotted = run_gnuplot("aeg", c.out + "/aeg.gp", gnuplot_script(c), {c.out + "/aeg.svg"});
  const std::string md = markdown(c, statics, kinetics, plotted);
  cli::write_atomically("bench aeg", c.out + "/aeg.md", md);
  std::cout << md;
  std::cerr << "kvd bench aeg: wrote " << c.out << "/aeg.md, " << c.out << "/aeg.csv"
            << (plotted ? ", " + c.out + "/aeg.svg" : std::string()) << "\n";
  if (!std::ranges::all_of(kinetics, &Kinetic_row::same)) {
    std::cerr << "kvd bench aeg: the updates differ\n";
    return 1;
  }
  return 0;
}

}  // namespace kvd::bench
