// Validation of a run (kinetic/simulation.hpp): the tree in force between
// two consecutive batches must equal a fresh build at a time strictly
// between them, made by a classifier of the validator's own (no cache
// shared with the run). A difference means an event was missed.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "kvd/kinetic/simulation.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"

namespace kvd::kinetic {

// A time strictly between a < b: a rational in the exact kernel, the
// midpoint in the floating-point ones.
inline Exact_time between(const Exact_kernel&, const Exact_time& a, const Exact_time& b) {
  return Exact_time(rational_between(a, b));
}
template <class K>
typename K::Time between(const K&, const typename K::Time& a, const typename K::Time& b) {
  return (a + b) / typename K::FT(2);
}

template <class K>
class Validator {
  using Time = typename K::Time;

public:
  // `scene` holds the motions in force and outlives the validator.
  Validator(const K& k, const scene::Scene& scene, Validation mode) : k_(k), scene_(scene), mode_(mode) {
    motions_changed();
  }
  void motions_changed() { oracle_ = std::make_unique<const predicates::Classifier<K>>(k_, scene_); }

  // Validation::every: checks before each batch.
  bool every() const { return mode_ == Validation::every; }

  // Checks the tree in force on (from, to), counting in `sim` and keeping
  // the first failure in words. The instant and the fresh tree when they
  // differ.
  std::optional<std::pair<Time, tree::Kvd_tree>> check(const Time& from, const Time& to, const tree::Kvd_tree& in_force,
                                                       Simulation<Time>& sim) const {
    Time mid = between(k_, from, to);
    ++sim.validations;
    std::optional<std::string> diff;
    std::optional<tree::Kvd_tree> fresh;
    try {
      fresh = tree::build(*oracle_, mid);
      diff = tree::first_difference(in_force, *fresh);
      if (diff) diff = "the tree in force differs from a fresh build: " + *diff;
    } catch (const tree::Build_error& e) {
      diff = std::string("the fresh build failed: ") + e.what();
    }
    if (!diff) return std::nullopt;
    if (sim.validation_failures++ == 0)
      sim.failure = "between " + k_.to_string(from) + " and " + k_.to_string(to) + ", at " + k_.to_string(mid) + ", " +
                    *diff;
    if (!fresh) return std::nullopt;
    return std::pair{std::move(mid), std::move(*fresh)};
  }

  // Validation::end checks only the last interval: the tree `t` in force
  // from `from` is leaving force (kept, in that mode), or the tree in force
  // now has new motions (the interval kept is forgotten).
  bool keeps_last() const { return mode_ == Validation::end; }
  void leaving(const Time& from, tree::Kvd_tree t) {
    if (mode_ == Validation::end) last_.emplace(from, std::move(t));
  }
  void forget() { last_.reset(); }
  // At the end of a run at `now`.
  void finish(const Time& now, Simulation<Time>& sim) const {
    if (mode_ == Validation::end && last_ && k_.compare(last_->first, now) < 0) check(last_->first, now, last_->second, sim);
  }

private:
  const K& k_;
  const scene::Scene& scene_;
  Validation mode_;
  std::unique_ptr<const predicates::Classifier<K>> oracle_;
  std::optional<std::pair<Time, tree::Kvd_tree>> last_;  // the tree before the last batch, from its instant
};

}  // namespace kvd::kinetic
