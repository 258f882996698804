// The library's front door: scenes, kernels, the static KVD, and the kinetic
// KVD as an object that is stepped from outside (the kinetic data structure
// model of Basch, Guibas and Hershberger: the structure is advanced event by
// event, and queried between events).
//
//   kvd::Kinetic_kvd<kvd::Exact_kernel> k(kvd::Exact_kernel(), scene);
//   while (const auto* batch = k.advance()) { ... k.tree(), k.back_to_front(view) ... }
//
// Every step is the same computation as kinetic::simulate, which runs the
// whole simulation at once: stepping gives the same batches, trees and
// certificates.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kernel/float_kernel.hpp"
#include "kvd/kinetic/certificate.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/query/visibility.hpp"
#include "kvd/scene/scene.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd {

namespace kinetic::detail {
template <class K>
class Simulator;
}

template <class K>
class Kinetic_kvd {
public:
  using Time = typename K::Time;
  using Batch = kinetic::Batch<Time>;

  // Builds the tree just after the scene's start and its certificates.
  // `options` bound the run as they bound kinetic::simulate (max_events,
  // until, validation, collisions...). Throws tree::Build_error when the
  // triangles meet at the start.
  Kinetic_kvd(const K& kernel, const scene::Scene& scene, kinetic::Options options = {},
              kinetic::Observer<K>* observer = nullptr);
  // The kernel is held by reference: a temporary one would dangle.
  Kinetic_kvd(const K&&, const scene::Scene&, kinetic::Options = {}, kinetic::Observer<K>* = nullptr) = delete;
  ~Kinetic_kvd();
  Kinetic_kvd(Kinetic_kvd&&) noexcept;
  Kinetic_kvd& operator=(Kinetic_kvd&&) noexcept;

  // The instant the tree in force is valid just after.
  const Time& now() const;
  // The time of the next batch, none when the run has stopped or no
  // certificate fails any more.
  std::optional<Time> next_event_time() const;
  // Processes the next batch, with any motion change (X-collide) or
  // floating-point repair before it; the batch, or none when the run stops
  // (why: record().stopped).
  const Batch* advance();
  // Processes every batch at a time <= t; how many.
  std::size_t advance_to(const typename K::FT& t);
  bool stopped() const;

  // A flight-plan change (seed 003, section 3): `object` moves by `motion`
  // from the rational instant `at` on, now() <= at < next_event_time().
  // Every certificate is made again from the new motions, and the change is
  // recorded among record().motion_changes (which --events N also bounds).
  // Throws std::invalid_argument on a bad object, motion or instant, and
  // tree::Build_error, leaving the run as it was, when triangles would meet
  // just after `at`.
  void set_motion(std::size_t object, const scene::Motion& motion, const mpq_class& at);

  // The tree in force, read-only (valid on (now, next_event_time)).
  const tree::Kvd_tree& tree() const;
  // Its structure hash (tree/compare.hpp: a Merkle hash of the canonical
  // serialisation), kept up to date along the paths each batch changed.
  std::string structure_hash() const;
  // The certificates in force.
  std::vector<kinetic::Certificate<typename K::Poly>> certificates() const;
  // The T-nodes of the tree in force, back to front from the Euclidean
  // point `view`, at an instant inside the current interval.
  std::vector<int> back_to_front(const Point4<typename K::FT>& view) const;
  // The run so far: batches, motion changes, counts, recovery, validation;
  // with the time reached and the final hash once it has stopped.
  const kinetic::Simulation<Time>& record() const;

private:
  std::unique_ptr<kinetic::Options> options_;  // the simulator keeps a reference
  std::unique_ptr<kinetic::detail::Simulator<K>> sim_;
};

}  // namespace kvd
