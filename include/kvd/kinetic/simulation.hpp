// The kinetic KVD: the certificates of the tree in force (the reduced or the
// full set) go into an event queue; the next batch is every certificate
// failing at the earliest failure time after the current one; the update
// makes the tree valid just after it, locally (thesis 7.3) or by the
// reference rebuild (DESIGN.md section 5), and recomputes the certificates.
// The full set is the classifications a build evaluated, so it needs the
// rebuild.
//
// In the exact kernel event times are algebraic numbers ordered exactly and
// a batch is an exact equality. The floating-point kernels compare times
// within their epsilon, so a batch is every failure within epsilon of the
// minimum: the thesis's epsilon-minimum grouping, on purpose.
//
// Collisions: an update that finds triangles meeting (a fragment crossing a
// triangle's plane) is a collision. The response (X-collide, thesis 7.3.3,
// detail/kinetic/collision.hpp) reverses both objects' motions at a rational time
// strictly between the last batch and the collision; the tree in force stays
// valid there, and the certificates of the new motions replace the old ones.
// Objects meeting again at that same instant before any batch (another pair
// landing at once) are reversed at the same time, in the same motion change.
// With Collisions::stop the run stops at the collision instead.
//
// Validation: the tree in force between two consecutive batches must be the
// tree built at a time strictly between them (a rational in the exact
// kernel, the midpoint in the others); a difference means an event was
// missed.
//
// Recovery, floating-point kernels only: rounding can give a tree that
// contradicts itself or the scene. The run detects three signs of it and
// counts them in Recovery:
//  * a build that throws (a fragment put across a triangle's plane): the run
//    rebuilds at now + 2^i epsilon, i = 1, 2, ..., recovery_steps, and takes
//    the first that succeeds (a collision only when none does);
//  * a batch repeating the previous batch's failures without changing the
//    tree: the run moves on to the first such later instant whose tree
//    differs;
//  * with --validate every, a tree in force that differs from the fresh
//    build (a missed event): the run adopts the fresh build and its instant.
// Events in a skipped interval are lost, which the differential harness
// reports as missed. In the exact kernel none of this happens, and a build
// that throws is a collision.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kinetic/certificate.hpp"
#include "kvd/detail/kinetic/event_queue.hpp"
#include "kvd/scene/scene.hpp"

namespace kvd::kinetic {

// A failing certificate, by its identity.
using Failure = Certificate_key;

// Where a local update worked: in one subtree (proofs/local_update.md,
// section 5), over the whole tree (a batch not confined, or --update
// reinsert), or over the whole tree after a subtree was asked for and its
// checks found a sign above it changed (widened). None: no local update (a
// rebuild, or a floating-point repair's build).
enum class Update_scope : std::uint8_t { none, subtree, whole, widened };
inline constexpr const char* update_scope_names[] = {"none", "subtree", "whole", "widened"};

template <class Time>
struct Batch {
  Time time;
  std::vector<Failure> failing;  // the certificates failing at `time`
  std::size_t certificates = 0;  // in force before the batch
  bool changed = false;          // whether the tree just after differs from the tree before
  std::string structure;         // the structure hash of the tree just after
  std::size_t moving_sites = 0;   // --update local: the sites the batch moved
  Update_scope scope = Update_scope::none;
  std::size_t nodes_touched = 0;  // --update local: the nodes the update touched
  std::size_t nodes_changed = 0;  // --update local: the cuts and fragments made or removed (the larger count)
  std::size_t nodes_recomputed = 0;         // nodes that made their certificates again (all, with the full set)
  std::size_t certificates_recomputed = 0;  // the certificates they made
  double tree_seconds = 0;         // updating the tree
  double record_seconds = 0;       // its structure hash, along the changed paths (tells `changed`)
  double certificate_seconds = 0;  // making the certificates, their failure times and the queue
  std::size_t failures() const { return failing.size(); }
};

// A collision response: the objects' motions reversed at `time`, strictly
// between the last batch and `collision`, the instant at which they would
// have met. The new motions are in force from `time` on.
template <class Time>
struct Motion_change {
  mpq_class time;
  Time collision;
  std::vector<std::size_t> objects;    // increasing
  std::vector<scene::Motion> motions;  // the new motion of each object
  std::size_t batches_before = 0;      // the batches processed before it
  std::string contact;                 // which features met, in words
  bool tree_changed = false;           // whether the tree just after `time` differs from the tree before
  // A flight-plan change: the certificates made again (those naming the
  // object's features, and the others of the nodes holding them), and
  // those in force after it.
  std::size_t certificates_recomputed = 0, certificates = 0;
};

using Type_counts = std::array<std::size_t, certificate_types>;

// What a floating-point run detected and repaired; all zero in the exact kernel.
struct Recovery {
  std::size_t failed_builds = 0;  // a build threw: rounding put a fragment across a triangle's plane
  std::size_t refires = 0;        // batches repeating the previous batch's failures with the tree unchanged
  std::size_t stale_trees = 0;    // trees in force that validation found differing from a fresh build
  std::size_t rebuilds = 0;       // trees adopted to repair one of the above
  std::size_t zones_skipped = 0;  // refires repaired by stepping past the certificates' rounding zone
  std::size_t unrepaired = 0;     // refires that no step repaired: the run stopped (Stop::stuck)
  std::size_t detected() const { return failed_builds + refires + stale_trees; }
};
inline constexpr int recovery_steps = 20;

// Why a simulation stopped: max_events reached, the next failure after the
// time limit (the scene's end or `until`), no failure left, triangles met,
// or (floating-point kernels only) a batch repeating without time advancing
// that no repair could move past.
enum class Stop { events, limit, exhausted, collision, stuck };

template <class Time>
struct Simulation {
  std::vector<Batch<Time>> batches;
  std::size_t failures = 0;  // certificate failures processed (the "events")
  std::size_t simultaneous_batches = 0;
  Type_counts initial_certificates{};  // by type, for the tree at the start (thesis Figure 8.5)
  Type_counts failures_by_type{};
  double construction_seconds = 0;  // the first tree, its certificates and the queue
  Time time_reached{};  // the last batch's time; the limit when the run stopped there or ran out of events
  std::string structure_hash;            // of the tree in force at the end
  std::optional<std::string> collision;  // triangles meeting: the simulation stops there
  std::vector<Motion_change<Time>> motion_changes;  // the collision responses, in order
  Stop stopped = Stop::exhausted;
  // When the run stopped at its event count: the first failure it did not
  // process, which ends the interval of the tree in force at the end.
  std::optional<Time> next_failure;
  std::optional<mpq_class> limit;  // the time limit in force: the earlier of the scene's end and `until`
  Recovery recovery;
  std::size_t validations = 0;  // trees in force compared with a fresh build
  std::size_t validation_failures = 0;
  std::string failure;  // the first validation failure, in words
  bool valid() const { return validation_failures == 0; }
};

enum class Validation { every, end, none };

enum class Collisions { reverse, stop };

// How a batch changes the tree: by the local update of thesis 7.3
// (detail/kinetic/local_update.hpp) confined to the subtree of the failing
// signs, by the same update over the whole tree (every piece of every
// moving site dragged out and inserted again from the root), or by the
// reference rebuild.
enum class Update { local, reinsert, rebuild };

// Which nodes make their certificates again after a batch: those whose
// inputs changed or that hold a failed certificate (detail/kinetic/reduced_upkeep.hpp),
// or every node (the reference). The full set is always made afresh.
enum class Upkeep { local, all };

struct Options {
  std::size_t max_events = 100;             // stop after the batch holding the N-th failure
  std::optional<mpq_class> until;           // process every batch at a time <= until
  Validation validate = Validation::every;  // between every two batches, or only the last
  Certificate_set certificates = Certificate_set::reduced;
  Queue_kind queue = Queue_kind::tree;
  Update update = Update::local;  // the full set always rebuilds
  Collisions collisions = Collisions::reverse;  // max_events also bounds the motion changes
  Upkeep upkeep = Upkeep::local;
  // Called after every batch with the number of batches and of failures so far.
  std::function<void(std::size_t batches, std::size_t failures)> progress;
};

// One step of a collision response, as an observer sees it: `objects`
// (increasing) reversed at `time`, with their new `motions`, because of
// `contact`, found among the failures of `collision`, the batch at the
// instant of contact, which is not processed. A second contact at the same
// instant is a second step at the same time, with the objects it adds.
template <class Time>
struct Reversal {
  mpq_class time;
  Batch<Time> collision;
  std::vector<std::size_t> objects;
  std::vector<scene::Motion> motions;
  std::string contact;
};

// Sees what a simulation relies on, in order: the certificates put in force
// at the start, then for every batch the batch (before its update) and the
// certificates in force after it. A reversal comes before the certificates
// of the new motions. A batch at which triangles meet and the run stops
// comes with collision = true and is the last call.
template <class K>
class Observer {
public:
  virtual ~Observer() = default;
  virtual void in_force(const typename K::Time& now, const std::vector<Certificate<typename K::Poly>>& certs) = 0;
  virtual void batch(const Batch<typename K::Time>& b, bool collision) = 0;
  virtual void reversal(const Reversal<typename K::Time>&) {}
};

// Runs from the scene's start until its end or `until`, no events are left,
// max_events, or a collision (a fragment crossing a triangle's plane when the
// tree is rebuilt: the triangles meet).
template <class K>
Simulation<typename K::Time> simulate(const K& kernel, const scene::Scene& s, const Options& options,
                                      Observer<K>* observer = nullptr);

// Walks a run in its order: every motion change (on_change with its index)
// before the batches that follow it, every batch (on_batch with its index).
template <class Time, class On_change, class On_batch>
void in_run_order(const Simulation<Time>& sim, On_change on_change, On_batch on_batch) {
  std::size_t c = 0;
  for (std::size_t b = 0; b <= sim.batches.size(); ++b) {
    for (; c < sim.motion_changes.size() && sim.motion_changes[c].batches_before <= b; ++c) on_change(c);
    if (b < sim.batches.size()) on_batch(b);
  }
}

// The scene with the motions in force at t: s with every change at a time
// <= t applied in order.
template <class Time>
scene::Scene motions_at(scene::Scene s, const std::vector<Motion_change<Time>>& changes, const mpq_class& t) {
  for (const auto& c : changes)
    if (c.time <= t)
      for (std::size_t i = 0; i < c.objects.size(); ++i) s.objects[c.objects[i]].motion = c.motions[i];
  return s;
}

// A rational strictly between a < b.
mpq_class rational_between(const Exact_time& a, const Exact_time& b);

}  // namespace kvd::kinetic
