// kvd bench aeg-cost: the runs it makes (aeg_cost.cpp), and their report
// (aeg_cost_report.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "kvd/segments/aeg_phases.hpp"

namespace kvd::bench::aeg_cost_suite {

// One run over the first failures of one scene: its cost per batch in
// signs decided, nodes made and time.
struct Run_row {
  std::string family = "random";  // the scenes': "random" (no flips) or "rotating" (flips)
  std::string run;  // "local": the kept set's local update; "paper": the run on the paper's certificates
  std::size_t n = 0, m = 0, k = 0;  // segments, moving ones, crossings at the start
  std::size_t nodes = 0;            // the tree's at the start
  std::size_t batches = 0, failures = 0;
  // Per batch: the signs the update decided (every rule but held), those it
  // read from the certificates in force (held), the nodes it made again.
  // The signs it asked again, answered from their first decision in the
  // batch (the run on the paper's set remembers its instant; the kept run
  // does not: 0).
  double signs_median = 0, signs_mean = 0, signs_p90 = 0, signs_max = 0, held_mean = 0, repeated_mean = 0;
  double nodes_made_median = 0, nodes_made_mean = 0, nodes_made_max = 0;
  // The run on the paper's set only (`phased`): where its signs were decided
  // per batch (Aeg_kinetic_bsp::Batch::phases), means by phase_names, and
  // the worst batch of the guard over other segments' steps.
  bool phased = false;
  std::array<double, segments::Aeg_phases::count> phase_means{};  // in the order of Aeg_phases::named
  double other_guard_max = 0;
  double mean_ms = 0, median_ms = 0, max_ms = 0;
  // The batches of one flip (in the paper's set, with the transient cells
  // it closes): their count, those turned in place (the paper's set only),
  // and per batch the nodes made again or edited in place, the signs
  // decided, the time.
  std::size_t lone_flips = 0, flips_in_place = 0;
  double flip_nodes_median = 0, flip_nodes_max = 0, flip_signs_median = 0, flip_signs_max = 0, flip_median_ms = 0;
};

struct Config {
  std::vector<std::size_t> sizes{100, 200, 400, 800, 1600, 3200, 6400, 12800};
  // The rotating scenes' (all moving), for the cost of a flip.
  std::vector<std::size_t> flip_sizes{25, 50, 100, 200, 400, 800, 1600};
  std::size_t events = 2000;
  std::string out = "bench-out";
};

std::string csv(const std::vector<Run_row>& rows);
std::string markdown(const Config& c, const std::vector<Run_row>& rows, bool plotted);
// The plot's data (aeg-cost.dat) and the gnuplot script writing aeg-cost.svg.
std::string plot_data(const Config& c, const std::vector<Run_row>& rows);
std::string gnuplot_script(const Config& c);

}  // namespace kvd::bench::aeg_cost_suite
