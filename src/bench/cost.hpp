// kvd bench cost: the runs it makes (cost.cpp), and their report
// (cost_report.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "kvd/kernel/filter_statistics.hpp"

namespace kvd::bench::cost_suite {

struct Size {
  std::size_t triangles = 0;
  std::size_t nodes = 0;  // of the exact tree at the start
  // Medians over the repetitions, ms.
  double build_exact = 0, build_unfiltered = 0, build_double = 0;
  // The simulations' whole update time per certificate failure, ms
  // (medians over the repetitions).
  double event_exact = 0, event_double = 0;
  std::size_t events = 0, batches = 0;  // of the exact run
  Filter_statistics build_stages, simulate_stages;  // of one exact build and one exact simulation
  // The distinct certificate polynomials the exact simulation put in force.
  std::size_t polynomials = 0, linear_polynomials = 0;
  int max_degree = 0;
  double next_root_us = 0;  // per call, median over the repetitions
  // Why the double kernel could not start (its first build found triangles
  // meeting by rounding); empty when it ran.
  std::string double_failure;
};

struct Config {
  std::vector<std::size_t> sizes{25, 50, 100, 200, 400, 800};
  std::size_t events = 200;
  int repeats = 3;
  std::string out = "bench-out";
};

std::string csv(const std::vector<Size>& sizes);
std::string markdown(const Config& c, const std::vector<Size>& sizes, bool plotted);
// The plot's data (cost-plot.dat) and the gnuplot script writing cost.svg.
std::string plot_data(const std::vector<Size>& sizes);
std::string gnuplot_script(const Config& c);

}  // namespace kvd::bench::cost_suite
