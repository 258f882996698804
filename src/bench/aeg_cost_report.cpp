// The report of kvd bench aeg-cost: CSV, Markdown and the plot of the cost
// per batch against n.
#include <cmath>

#include "aeg_cost.hpp"
#include "gnuplot.hpp"
#include "report.hpp"

namespace kvd::bench::aeg_cost_suite {

namespace {

const Run_row* find(const std::vector<Run_row>& rows, const std::string& run, std::size_t n, std::size_t m) {
  for (const Run_row& r : rows)
    if (r.family == "random" && r.run == run && r.n == n && r.m == m) return &r;
  return nullptr;
}

// signs / log2 n; empty for one segment.
std::string per_log(const Run_row& r) {
  return r.n > 1 ? cli::fixed(r.signs_mean / std::log2(static_cast<double>(r.n)), 2) : "";
}

// The run on the paper's set's phases, as CSV fields ending in a comma;
// empty for the kept run.
std::string phases_csv(const Run_row& r) {
  if (!r.phased) return std::string(segments::Aeg_phases::count + 1, ',');
  std::string out;
  for (const double v : r.phase_means) out += cli::fixed(v, 3) + ",";
  return out + cli::approx(r.other_guard_max) + ",";
}

// Where the run on the paper's set decides its signs, per batch.
std::string phases_table(const std::vector<Run_row>& rows) {
  std::string out =
      "| n | m | signs decided: mean | own steps' guard | other steps' guard | ties | certificates | endpoints' "
      "leaves | walls renamed | the rest | other steps' guard: max |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Run_row& r : rows)
    if (r.phased && r.family == "random") {
      double rest = r.signs_mean;
      out += "| " + std::to_string(r.n) + " | " + std::to_string(r.m) + " | " + cli::fixed(r.signs_mean, 1) + " | ";
      for (const double v : r.phase_means) {
        out += cli::fixed(v, 1) + " | ";
        rest -= v;
      }
      out += cli::fixed(rest, 1) + " | " + cli::fixed(r.other_guard_max, 0) + " |\n";
    }
  return out;
}

std::string table(const std::vector<Run_row>& rows, const std::string& run) {
  std::string out =
      "| n | m | k | tree nodes | batches | signs decided: mean | median | p90 | max | mean / log2 n | signs held: "
      "mean | signs repeated: mean | nodes made: mean | median | max | ms: mean | median | max |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Run_row& r : rows)
    if (r.run == run && r.family == "random")
      out += "| " + std::to_string(r.n) + " | " + std::to_string(r.m) + " | " + std::to_string(r.k) + " | " +
             std::to_string(r.nodes) + " | " + std::to_string(r.batches) + " | " + cli::fixed(r.signs_mean, 1) +
             " | " + cli::fixed(r.signs_median, 1) + " | " + cli::fixed(r.signs_p90, 0) + " | " +
             cli::fixed(r.signs_max, 0) + " | " + per_log(r) + " | " + cli::fixed(r.held_mean, 1) + " | " +
             cli::fixed(r.repeated_mean, 1) + " | " +
             cli::fixed(r.nodes_made_mean, 1) + " | " + cli::fixed(r.nodes_made_median, 1) + " | " +
             cli::fixed(r.nodes_made_max, 0) + " | " +
             cli::fixed(r.mean_ms, 3) + " | " + cli::fixed(r.median_ms, 3) + " | " + cli::fixed(r.max_ms, 1) + " |\n";
  return out;
}

// The cost of a batch of one flip, on the rotating scenes.
std::string flips_table(const std::vector<Run_row>& rows) {
  std::string out =
      "| n | k | tree nodes | run | batches | batches of one flip | turned in place | nodes made or edited: median | max | "
      "signs decided: median | max | ms: median |\n"
      "|---:|---:|---:|:---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Run_row& r : rows)
    if (r.family == "rotating")
      out += "| " + std::to_string(r.n) + " | " + std::to_string(r.k) + " | " + std::to_string(r.nodes) + " | " +
             (r.run == "paper" ? "the paper's set" : "kept set, local update") + " | " + std::to_string(r.batches) +
             " | " + std::to_string(r.lone_flips) + " | " + (r.phased ? std::to_string(r.flips_in_place) : "") +
             " | " + cli::fixed(r.flip_nodes_median, 1) + " | " + cli::fixed(r.flip_nodes_max, 0) + " | " +
             cli::fixed(r.flip_signs_median, 1) + " | " + cli::fixed(r.flip_signs_max, 0) + " | " +
             cli::fixed(r.flip_median_ms, 3) + " |\n";
  return out;
}

}  // namespace

std::string csv(const std::vector<Run_row>& rows) {
  std::string out =
      "family,run,n,m,k,nodes,batches,failures,signs_median,signs_mean,signs_p90,signs_max,held_mean,repeated_mean,"
      "nodes_made_median,"
      "nodes_made_mean,nodes_made_max,";
  for (const auto& [name, signs] : segments::Aeg_phases{}.named()) out += std::string(name) + "_mean,";
  out += "other_guard_max,lone_flips,flips_in_place,flip_nodes_median,flip_nodes_max,flip_signs_median,"
         "flip_signs_max,mean_ms,median_ms,max_ms,flip_median_ms\n";
  for (const Run_row& r : rows)
    out += r.family + "," + r.run + "," + std::to_string(r.n) + "," + std::to_string(r.m) + "," + std::to_string(r.k) + "," +
           std::to_string(r.nodes) + "," + std::to_string(r.batches) + "," + std::to_string(r.failures) + "," +
           cli::approx(r.signs_median) + "," + cli::fixed(r.signs_mean, 3) + "," + cli::approx(r.signs_p90) + "," +
           cli::approx(r.signs_max) + "," + cli::fixed(r.held_mean, 3) + "," + cli::fixed(r.repeated_mean, 3) + "," +
           cli::approx(r.nodes_made_median) +
           "," + cli::fixed(r.nodes_made_mean, 3) + "," + cli::approx(r.nodes_made_max) + "," + phases_csv(r) +
           std::to_string(r.lone_flips) + "," + std::to_string(r.flips_in_place) + "," +
           cli::approx(r.flip_nodes_median) + "," + cli::approx(r.flip_nodes_max) + "," +
           cli::approx(r.flip_signs_median) + "," + cli::approx(r.flip_signs_max) + "," + cli::fixed(r.mean_ms, 4) +
           "," + cli::fixed(r.median_ms, 4) + "," + cli::fixed(r.max_ms, 3) + "," + cli::fixed(r.flip_median_ms, 4) +
           "\n";
  return out;
}

std::string markdown(const Config& c, const std::vector<Run_row>& rows, bool plotted) {
  std::string out =
      "## Setting\n\n"
      "`kvd generate segments-random --n N --moving M --seed 1` (short segments, k = O(n); M = N and N/2), exact "
      "kernel, no validation, each run up to the batch holding its failure number " +
      std::to_string(c.events) +
      " (the two sets fail at different instants, so the runs cover different stretches of time). Per batch: the "
      "signs the update decided (by any rule: identity, the interval filter, exact arithmetic, the perturbation), "
      "the signs it read from the certificates in force (rule *held*), the signs it asked again and answered from "
      "their first decision in the batch (*repeated*: only the run on the paper's set remembers them), the nodes it "
      "made again, and its time in ms (this machine's). The counts do not depend on the machine.\n"
      "\n## The local update on the kept set\n\n"
      "The kept set holds a certificate for every sign of the construction, so an update reads the signs of the "
      "certificates in force instead of deciding them.\n\n" +
      table(rows, "local") +
      "\n## The run on the paper's set\n\n"
      "The paper's set holds only the transient cells, the endpoints' neighbours and the flips, so an update "
      "decides at the instant the signs it reads, and those its guards ask (which segment's steps changed, and that "
      "no other sign vanishes there). It remembers the signs of the batch's instant, so a key asked again is not "
      "decided again (*repeated*).\n\n" +
      table(rows, "paper") +
      "\n## Where the paper's set decides its signs\n\n"
      "The means per batch of the signs the run on the paper's set decided, by what asked them: the guards over "
      "the changing segments' own steps (above the nodes a reroute starts from, above a collinear endpoint's "
      "leaves, between nested frontiers), the guard over other segments' steps at the nodes where a changed key "
      "is decided (and its worst batch), the ties on the paths above the nodes made again, the certificates (read "
      "at the instant, and made), the endpoints' leaves found again, the checks that an old subtree keeps its "
      "signs with a moved wall renamed; the rest made the cuts again and checked flips and collinear "
      "endpoints.\n\n" +
      phases_table(rows) +
      "\n## Flips\n\n"
      "`kvd generate segments-rotating --n N --seed 1`: every segment turns about its midpoint, so that segments "
      "turn through vertical. Both runs, as above, each up to the batch holding its failure number " +
      std::to_string(c.events) +
      " or to the span's end: the two sets fail at different instants, and the paper's fails more certificates "
      "at a flip, so the runs meet different flips. Per batch of one flip (one segment's own endpoints changing "
      "their x order, and only failures of that flip; in the paper's set, with the transient cells between the "
      "segment's points, which close as it turns vertical), "
      "the nodes the update made again or, for a flip the paper's set turned in place (its section 3.1.4), "
      "edited in place, the signs it decided, its time. Neither run keeps the paper's augmented BSP, under which a "
      "flip would change no node: this is what a flip costs on the plain tree.\n\n" +
      flips_table(rows);
  if (plotted)
    out += "\n## Plot\n\nAbove, the mean signs per batch against n (log scales: a straight line is a power of n); "
           "below, the mean nodes made per batch (log scale in n only: a straight line is growth in log n).\n\n"
           "![cost per batch against n](aeg-cost.svg)\n";
  return out;
}

std::string plot_data(const Config& c, const std::vector<Run_row>& rows) {
  std::string out =
      "# n; mean signs decided a batch: local m = n, local m = n/2, paper m = n, paper m = n/2; mean signs held: "
      "local m = n, local m = n/2; mean nodes made: local m = n, local m = n/2, paper m = n, paper m = n/2 (NaN: "
      "not run)\n";
  const auto value = [&](const std::string& run, std::size_t n, std::size_t m, double Run_row::*field) {
    const Run_row* r = find(rows, run, n, m);
    return r ? cli::approx(r->*field) : std::string("NaN");
  };
  for (const std::size_t n : c.sizes) {
    out += std::to_string(n);
    for (double Run_row::*field : {&Run_row::signs_mean, &Run_row::held_mean, &Run_row::nodes_made_mean})
      for (const char* run : {"local", "paper"}) {
        if (field == &Run_row::held_mean && std::string(run) == "paper") continue;  // the paper's set holds none
        for (const std::size_t m : {n, n / 2}) out += " " + value(run, n, m, field);
      }
    out += "\n";
  }
  return out;
}

std::string gnuplot_script(const Config& c) {
  Line_plot signs, nodes;
  for (Line_plot* p : {&signs, &nodes}) {
    p->xlabel = "segments (log)";
    p->sizes = c.sizes;
    p->data = c.out + "/aeg-cost.dat";
  }
  signs.title = "Signs per batch, first " + std::to_string(c.events) + " failures";
  signs.ylabel = "signs per batch (log)";
  signs.series = {"decided: local, m = n",  "decided: local, m = n/2", "decided: paper, m = n",
                  "decided: paper, m = n/2", "held: local, m = n", "held: local, m = n/2"};
  nodes.title = "Nodes made again per batch";
  nodes.ylabel = "nodes per batch";
  nodes.log_y = false;
  nodes.first_column = 8;
  nodes.series = {"local, m = n", "local, m = n/2", "paper, m = n", "paper, m = n/2"};
  return bench::gnuplot_script(c.out + "/aeg-cost.svg", {signs, nodes});
}

}  // namespace kvd::bench::aeg_cost_suite
