// The kinetic KVD with the full certificate set and the reference update
// (DESIGN.md section 5): the certificates are every sign the construction
// evaluated; the next event is the smallest sign-changing root, after the
// current time, of any of their polynomials; an event batch is every
// certificate failing at that same time; the update rebuilds the tree valid
// just after it.
//
// In the exact kernel event times are algebraic numbers ordered exactly and
// a batch is an exact equality. The floating-point kernels compare times
// within their epsilon, so a batch is every failure within epsilon of the
// minimum: the thesis's epsilon-minimum grouping, on purpose.
//
// Validation: the tree in force between two consecutive batches must be the
// tree built at a time strictly between them (a rational in the exact
// kernel, the midpoint in the others); a difference means an event was
// missed.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/scene/scene.hpp"
#include "kvd/symbolic/symbolic.hpp"

namespace kvd::kinetic {

template <class Time>
struct Full_event {
  Time time;
  // The certificates failing: classifications of a symbolic vertex against a symbolic plane.
  std::vector<std::pair<symbolic::Symbolic_vertex, symbolic::Symbolic_plane>> failing_certificates;
  std::size_t certificates = 0;  // certificates (non-incident classifications) before the event
  bool changed = false;          // whether the tree just after differs from the tree before
  // How many certificates fail at this time.
  std::size_t failing() const { return failing_certificates.size(); }
};

template <class Time>
struct Full_simulation {
  std::vector<Full_event<Time>> events;  // one per batch
  std::size_t failures = 0;              // certificate failures processed (the "events")
  std::size_t simultaneous_batches = 0;
  Time time_reached{};
  std::string structure_hash;            // of the tree in force at the end
  std::optional<std::string> collision;  // triangles meeting: the simulation stops there
  std::size_t validation_failures = 0;
  std::string failure;  // the first validation failure, in words
  bool valid() const { return validation_failures == 0; }
};

enum class Validation { every, end, none };

struct Full_options {
  std::size_t max_events = 100;             // stop after the batch holding the N-th failure
  std::optional<mpq_class> until;           // process every batch at a time <= until
  Validation validate = Validation::every;  // between every two batches, or only the last
  // Called after every batch with the number of batches and of failures so far.
  std::function<void(std::size_t batches, std::size_t failures)> progress;
};

// Runs from the scene's start until its end or `until`, no events are left,
// max_events, or a collision (a fragment crossing a triangle's plane when the
// tree is rebuilt: the triangles meet).
template <class K>
Full_simulation<typename K::Time> simulate_full(const K& kernel, const scene::Scene& s, const Full_options& options);

// A rational strictly between a < b.
mpq_class rational_between(const Exact_time& a, const Exact_time& b);

}  // namespace kvd::kinetic
