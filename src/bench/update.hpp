// kvd bench update: the runs it makes, and their report (update_report.cpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report.hpp"

namespace kvd::bench::update_suite {

// One simulation of one generated scene in one configuration.
struct Run {
  std::string configuration;  // "local", "rebuild", "local, double", "local, --upkeep all", ...
  bool exact = true;
  std::size_t batches = 0;
  cli::Update_costs costs;
  cli::Recomputed recomputed;
  cli::Touched touched;  // zero with the rebuild
  std::string structure;  // the structure hash at the end
  // Why a floating-point run could not start (its build found triangles
  // meeting by rounding); empty when it ran. The numbers are then zero.
  std::string failure;
};

struct Size {
  std::size_t triangles = 0;
  std::vector<Run> runs;  // "local" first
  double peak_rss_mib = 0;  // of the process, after this size's runs
  const Run* find(const std::string& configuration) const;
  // Whether every exact run ends in the tree of the first (the local one).
  bool same_tree() const;
};

struct Config {
  std::vector<std::size_t> sizes{100, 200, 400, 800, 1600, 3200};
  std::size_t events = 100;
  std::size_t rebuild_up_to = 800;
  std::size_t upkeep_all_up_to = 100;
  std::string out = "bench-out";
};

std::string csv(const std::vector<Size>& sizes);
std::string markdown(const Config& c, const std::vector<Size>& sizes, bool plotted);
// The plot's data (update-plot.dat) and the gnuplot script writing update.svg.
std::string plot_data(const std::vector<Size>& sizes);
std::string gnuplot_script(const Config& c);
// The least-squares slope of log y against log x over the points with y > 0
// (none with fewer than two).
std::optional<double> growth_exponent(const std::vector<std::pair<double, double>>& points);

}  // namespace kvd::bench::update_suite
