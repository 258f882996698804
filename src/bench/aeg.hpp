// kvd bench aeg: the runs it makes (aeg.cpp), and their report
// (aeg_report.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "kvd/segments/aeg_certificates.hpp"
#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::bench::aeg_suite {

// The static cylindrical BSP of one generated scene at t = 0.
struct Static_row {
  std::string crossings;  // the generator's regime: "linear" or "quadratic"
  std::size_t n = 0;
  std::size_t k = 0;  // proper crossings, counted exactly
  segments::Bsp_counts counts;
  double build_exact_ms = 0, build_double_ms = 0;  // medians over the repetitions
  // nodes / (n log2 n + k) and height / log2 n (Theorem 2.3); 0 where the
  // bound is 0 (one segment).
  double size_over_bound() const;
  double height_over_log() const;
};

// One kinetic scene run with the local update and with the rebuild, batch
// by batch in turn.
struct Kinetic_row {
  std::string family;  // "random" (linear motion) or "rotating"
  std::string crossings = "linear";  // random: short segments (k = O(n)) or long ones ("quadratic": k = Θ(n²))
  std::size_t n = 0, m = 0;
  std::size_t k = 0;  // crossings at the start
  // At the start: the tree's nodes, the certificates the run keeps, and the
  // paper's (Lemma 3.1) for the same tree.
  std::size_t nodes = 0, certificates = 0;
  segments::Aeg_certificate_counts aeg;
  std::size_t batches = 0, failures = 0, changed = 0;  // changed: batches that changed the tree
  std::array<std::size_t, 4> events{};  // failures by segments::Segment_event
  double time = 0;  // from the start to the last batch, or to the span's end when the run reached it
  double local_mean_ms = 0, local_max_ms = 0, subtree_mean_ms = 0, subtree_max_ms = 0, rebuild_mean_ms = 0,
         rebuild_max_ms = 0;
  double nodes_rebuilt_median = 0, subtree_nodes_median = 0;  // of the local and the subtree update
  // The failures' topmost nodes that the local update handled by the
  // frontier replay, over all of them.
  double frontier_share = 0;
  // The batches holding a flip failure: how many, the local and the subtree
  // update's mean and max over them (ms) and the nodes each made again
  // (median); and the local update's mean over the other batches.
  std::size_t flip_batches = 0, flip_whole = 0;  // flip_whole: their topmost nodes the local update replayed whole
  double flip_local_mean_ms = 0, flip_local_max_ms = 0, flip_subtree_mean_ms = 0, flip_subtree_max_ms = 0;
  double flip_nodes_median = 0, flip_subtree_nodes_median = 0, other_local_mean_ms = 0;
  double flip_nodes_max = 0, flip_subtree_nodes_max = 0;
  bool subtree_run = false, rebuild_run = false;  // within --subtree-up-to and --rebuild-up-to
  bool same = true;  // the updates run had the same batches (times, failing certificates) and end in the same tree
  // Failures of `event` per unit of time, over m n (flips: over m); 0
  // without time or moving segments.
  double rate(std::size_t event) const;
};

struct Config {
  std::vector<std::size_t> sizes{100, 200, 400, 800, 1600, 3200, 6400, 12800};
  std::size_t quadratic_up_to = 400;
  std::vector<std::size_t> kinetic_sizes{100, 200, 400, 800, 1600, 3200, 6400, 12800};
  std::size_t subtree_up_to = 3200, rebuild_up_to = 800;  // the reference updates, up to these sizes
  std::size_t kinetic_quadratic_up_to = 200;              // kinetic runs of long segments, up to this size
  std::size_t rotating = 20;  // segments of the rotating scene (run over its span), 0: none
  std::vector<std::size_t> rotating_long{30, 60};  // the same with long segments (k = Θ(n²)), one scene per size
  std::size_t events = 50;
  int repeats = 3;
  std::string out = "bench-out";
};

std::string csv(const std::vector<Static_row>& statics, const std::vector<Kinetic_row>& kinetics);
std::string markdown(const Config& c, const std::vector<Static_row>& statics, const std::vector<Kinetic_row>& kinetics,
                     bool plotted);
// The plots' data (aeg-static.dat, aeg-kinetic.dat) and the gnuplot script
// writing aeg.svg.
std::string static_plot_data(const std::vector<Static_row>& statics);
std::string kinetic_plot_data(const std::vector<Kinetic_row>& kinetics);
std::string gnuplot_script(const Config& c);

}  // namespace kvd::bench::aeg_suite
