// A run of the exact kinetic KVD kept for pictures (kvd view, kvd animate):
// its batches, the features of each failing certificate, and the tree in
// force at any rational instant of the run. That tree is a fresh build under
// the motions in force at the instant: validation shows it equal to the tree
// the run kept.
#pragma once

#include <gmpxx.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kinetic/certificate.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/scene/scene.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::view {

struct Failing_certificate {
  kinetic::Certificate_type type;
  std::string features;  // "SV(v3) P(7)"
  std::vector<symbolic::Symbolic_vertex> vertices;
  std::vector<symbolic::Symbolic_plane> planes;
};

struct Recorded_run {
  scene::Scene scene;
  kinetic::Simulation<Exact_time> sim;
  std::vector<std::vector<Failing_certificate>> failing;  // per batch, in the batch's order
};

// Runs the exact simulation with `options` (validation as they say).
Recorded_run record_run(const scene::Scene& s, const kinetic::Options& options);

// The KVD just after a rational instant t, under the motions in force then.
class Instant {
public:
  Instant(const Recorded_run& run, const mpq_class& t);
  const mpq_class& time() const { return t_; }
  const scene::Scene& scene() const { return *scene_; }
  const predicates::Classifier<Exact_kernel>& classifier() const { return *classifier_; }
  const tree::Kvd_tree& tree() const { return tree_; }
  // The Euclidean position of a symbolic vertex at the instant, in double.
  std::array<double, 3> position(const symbolic::Symbolic_vertex& v) const;

private:
  mpq_class t_;
  std::unique_ptr<scene::Scene> scene_;  // the classifier keeps its address
  Exact_kernel kernel_;
  std::unique_ptr<predicates::Classifier<Exact_kernel>> classifier_;
  tree::Kvd_tree tree_;
};

// Where a failing certificate's features are at an instant: its symbolic
// vertices and each P-site's vertex as points, each E-site's edge as a
// segment, each T-site's triangle.
struct Feature_shapes {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::array<double, 3>, 2>> segments;
  std::vector<std::array<std::array<double, 3>, 3>> triangles;
};
Feature_shapes feature_shapes(const Failing_certificate& f, const Instant& in);

// The intervals of the run between consecutive instants, in order: from the
// start to the first batch, then from each batch to the next one, or after
// the last to the next failure or the time limit, or else none.
struct Interval {
  Exact_time from;
  std::optional<Exact_time> to;
};
std::vector<Interval> intervals(const Recorded_run& run);

// The KVD at a rational strictly inside the interval: its midpoint, or for an
// open end one time unit on, moved closer to `from` while triangles would
// meet there (the run stopped before an event it did not process). An
// interval from the time limit is drawn at the limit (the tree at an
// instant is the one just after it).
Instant inside(const Recorded_run& run, const Interval& i);

}  // namespace kvd::view
