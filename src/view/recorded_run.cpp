#include "recorded_run.hpp"

#include <map>

#include "kvd/tree/build.hpp"

namespace kvd::view {

namespace {

// Keeps the features of the certificates in force, to name those that fail.
class Failing_recorder : public kinetic::Observer<Exact_kernel> {
public:
  explicit Failing_recorder(std::vector<std::vector<Failing_certificate>>& out) : out_(out) {}
  void in_force(const Exact_time&, const std::vector<kinetic::Certificate<Exact_kernel::Poly>>& certs) override {
    current_.clear();
    for (const auto& c : certs)
      current_.try_emplace(c.key, Failing_certificate{c.key.type, kinetic::features(c.key), c.vertices, c.planes});
  }
  void batch(const kinetic::Batch<Exact_time>& b, bool) override {
    std::vector<Failing_certificate> failing;
    for (const auto& f : b.failing) {
      const auto it = current_.find(f);
      failing.push_back(it != current_.end() ? it->second : Failing_certificate{f.type, kinetic::features(f), {}, {}});
    }
    out_.push_back(std::move(failing));
  }

private:
  std::vector<std::vector<Failing_certificate>>& out_;
  std::map<kinetic::Certificate_key, Failing_certificate> current_;
};

}  // namespace

Recorded_run record_run(const scene::Scene& s, const kinetic::Options& options) {
  Recorded_run run{s, {}, {}};
  Failing_recorder recorder(run.failing);
  run.sim = kinetic::simulate(Exact_kernel(), s, options, &recorder);
  run.failing.resize(run.sim.batches.size());  // a collision batch that stopped the run is not a batch
  return run;
}

Instant::Instant(const Recorded_run& run, const mpq_class& t)
    : t_(t), scene_(std::make_unique<scene::Scene>(kinetic::motions_at(run.scene, run.sim.motion_changes, t))),
      classifier_(std::make_unique<predicates::Classifier<Exact_kernel>>(kernel_, *scene_)),
      tree_(tree::build(*classifier_, Exact_time(t))) {}

std::array<double, 3> Instant::position(const symbolic::Symbolic_vertex& v) const {
  const auto p = classifier_->position_after(v, t_);  // the tree's: defined where its cuts degenerate at t
  if (p[3] == 0) return {0, 0, 0};  // a direction: no place to draw
  return {mpq_class(p[0] / p[3]).get_d(), mpq_class(p[1] / p[3]).get_d(), mpq_class(p[2] / p[3]).get_d()};
}

Feature_shapes feature_shapes(const Failing_certificate& f, const Instant& in) {
  const scene::Scene& s = in.scene();
  const auto at = [&](std::size_t v) { return in.position(symbolic::Symbolic_vertex::endpoint(v)); };
  Feature_shapes out;
  for (const auto& v : f.vertices) out.points.push_back(in.position(v));
  for (const auto& p : f.planes) {
    switch (p.kind) {
      case symbolic::Symbolic_plane::Kind::P: out.points.push_back(at(p.id)); break;
      case symbolic::Symbolic_plane::Kind::E: out.segments.push_back({at(s.edges[p.id][0]), at(s.edges[p.id][1])}); break;
      case symbolic::Symbolic_plane::Kind::T: {
        const auto& t = s.triangles[p.id];
        out.triangles.push_back({at(t[0]), at(t[1]), at(t[2])});
        break;
      }
    }
  }
  return out;
}

std::vector<Interval> intervals(const Recorded_run& run) {
  std::vector<Interval> out;
  Exact_time from(run.scene.start);
  for (const auto& b : run.sim.batches) {
    out.push_back({from, b.time});
    from = b.time;
  }
  const Exact_kernel k;
  std::optional<Exact_time> to = run.sim.next_failure;
  if (run.sim.limit && k.compare(from, Exact_time(*run.sim.limit)) < 0 &&
      (!to || k.compare(Exact_time(*run.sim.limit), *to) < 0))
    to = Exact_time(*run.sim.limit);
  out.push_back({from, to});
  return out;
}

Instant inside(const Recorded_run& run, const Interval& i) {
  // A batch at the time limit: the tree at an instant is the one just after
  // it (a run stopped for its events there still has its next failure).
  if (run.sim.limit && Exact_kernel().compare(i.from, Exact_time(*run.sim.limit)) >= 0)
    return Instant(run, *run.sim.limit);
  if (i.to) return Instant(run, kinetic::rational_between(i.from, *i.to));
  mpq_class step(1);
  for (int tries = 0;; ++tries, step /= 2) {
    while (!i.from.is_rational() && i.from.upper() - i.from.lower() > step) i.from.refine();
    const mpq_class t = (i.from.is_rational() ? i.from.rational() : i.from.upper()) + step;
    try {
      return Instant(run, t);
    } catch (const tree::Build_error&) {
      if (tries == 60) throw;
    }
  }
}

}  // namespace kvd::view
