// Number formats and record pieces that several kvd commands print.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include "kvd/kernel/kernel.hpp"
#include "kvd/kinetic/simulation.hpp"

namespace kvd::cli {

// 17 significant digits: a double read back exactly.
std::string approx(double d);
// `digits` digits after the point.
std::string fixed(double x, int digits);

// A non-negative rational in scientific notation with `digits` digits after
// the point ("1.25e-310": no underflow), and its base-10 logarithm (-inf for 0).
std::string scientific(const mpq_class& q, int digits = 2);
double log10_of(const mpq_class& q);

// The median of v; 0 for none.
double median(std::vector<double> v);

// The update-cost statistics of the thesis's Figures 8.6 and 8.7, in ms
// per batch (all zero without batches).
struct Update_costs {
  double total = 0, average = 0, max = 0, stddev = 0, certificate_average = 0, tree_share = 0,
         certificate_share = 0;
  double median = 0, tree_median = 0;  // of the whole update, and of its tree part
};
template <class Time>
Update_costs update_costs(const kinetic::Simulation<Time>& sim) {
  Update_costs u;
  if (sim.batches.empty()) return u;
  double squares = 0, tree = 0, certificate = 0;
  std::vector<double> all, trees;
  for (const auto& b : sim.batches) {
    // The whole batch: tree, certificates and queue, and the record of the tree after.
    const double ms = 1000 * (b.tree_seconds + b.certificate_seconds + b.record_seconds);
    all.push_back(ms);
    trees.push_back(1000 * b.tree_seconds);
    u.total += ms;
    squares += ms * ms;
    tree += 1000 * b.tree_seconds;
    certificate += 1000 * b.certificate_seconds;
    u.max = std::max(u.max, ms);
  }
  const double n = static_cast<double>(sim.batches.size());
  u.average = u.total / n;
  u.stddev = std::sqrt(std::max(0.0, squares / n - u.average * u.average));
  u.certificate_average = certificate / n;
  u.tree_share = u.total > 0 ? tree / u.total : 0;
  u.certificate_share = u.total > 0 ? certificate / u.total : 0;
  u.median = median(std::move(all));
  u.tree_median = median(std::move(trees));
  return u;
}

// Nodes touched per batch by the local update (thesis 7.3), and the nodes
// the batch changed (Update_cost::nodes_changed): their ratio measures
// locality. Over
// the batches the local update made.
struct Touched {
  double median = 0;
  double changed_median = 0;
  double changed_mean = 0, changed_max = 0;
  double below_10_share = 0;  // of batches touching fewer than 10 nodes
  std::array<std::size_t, 4> scopes{};  // local updates by kinetic::Update_scope
};
template <class Time>
Touched nodes_touched(const kinetic::Simulation<Time>& sim) {
  std::vector<double> n, changed;
  std::array<std::size_t, 4> scopes{};
  for (const auto& b : sim.batches) {
    ++scopes[static_cast<std::size_t>(b.scope)];
    if (b.moving_sites == 0) continue;  // not a local update: a rebuild, or a floating-point repair's
    n.push_back(static_cast<double>(b.nodes_touched));
    changed.push_back(static_cast<double>(b.nodes_changed));
  }
  const auto below = std::count_if(n.begin(), n.end(), [](double x) { return x < 10; });
  double sum = 0, most = 0;
  for (double x : changed) sum += x, most = std::max(most, x);
  return {median(n),
          median(changed),
          changed.empty() ? 0 : sum / static_cast<double>(changed.size()),
          most,
          n.empty() ? 0 : static_cast<double>(below) / static_cast<double>(n.size()),
          scopes};
}

// Certificates made again after each batch (detail/kinetic/reduced_upkeep.hpp).
struct Recomputed {
  double median = 0;        // certificates per batch
  double nodes_median = 0;  // nodes that made them, per batch
  std::size_t total = 0;
};
template <class Time>
Recomputed certificates_recomputed(const kinetic::Simulation<Time>& sim) {
  std::vector<double> certs, nodes;
  Recomputed r;
  for (const auto& b : sim.batches) {
    certs.push_back(static_cast<double>(b.certificates_recomputed));
    nodes.push_back(static_cast<double>(b.nodes_recomputed));
    r.total += b.certificates_recomputed;
  }
  r.median = median(std::move(certs));
  r.nodes_median = median(std::move(nodes));
  return r;
}

// Why a run stopped, one word for JSON ("events", "limit", "exhausted",
// "collision", "stuck").
const char* stop_name(kinetic::Stop s);
// A floating-point run's recovery counts, in words.
std::string recovery_text(const kinetic::Recovery& r);

}  // namespace kvd::cli
