// The cylindrical BSP of moving segments kept through time (seed 003,
// section 3.1), as a stepping object over any kernel.
//
// Certificates: every sign the construction of the tree in force evaluated,
// with the polynomials that decided it and the nodes where it was decided
// (Segment_predicates::record); the tree cannot change before one of them
// changes sign, since the construction branches on nothing else. A batch is
// every certificate failing at the earliest failure time: exactly equal
// times in the exact kernel (decided by the kernel's compare), the thesis's
// epsilon-minimum in the floating-point ones. Each failure is classified as
// the paper's vertex, edge, intersection or flip event (event_in_batch: the
// x orders of a turning segment's points count with its flip).
//
// The subtree update replays, in the subtree of each topmost node u where a
// failing certificate was decided, the insertion steps that reached it
// (kvd/detail/segments/bsp_builder.hpp; proofs/segment-local-update.md): the
// rest of the tree, and its certificates, stay. The local update (the
// default) replays less: when the signs that changed at u are those of one
// segment s's steps, and u's cut is older than s, only s's steps are decided
// again from u down to the frontier (the first nodes of cuts of s or later
// segments: the leaves of B_{s-1} under u), and only the frontier nodes whose
// arrivals changed are made again, keeping the old subtrees below s's cuts
// whose arrivals did not change (Subtree_fit::remake). Several segments
// deciding failing keys at u, or at failing nodes below it (events of
// several segments at one instant), have their steps decided again from
// there too, down to the frontier of the earliest of them, whose nodes are
// then made again with that segment's cuts first (Replay_root::several). A
// u on the frontier of the earliest segment deciding a failing key at it is
// made again as a frontier node is. Otherwise (a failing key with no logged
// step deciding it, or a u below that frontier) it replays u's subtree,
// which the small-integer scenes of the tests never need. A flip is
// local too: the construction walks each segment from endpoint 0 to endpoint
// 1 whichever is left, so the signs a flip changes are all decided in the
// cells of the segment's own cuts, and the update is the paper's (section
// 3.1.4) update of the subtrees of the cells it crosses, not O(1): a topmost
// node that is the turning segment's first cut on its path, with only flip
// failures below it, is remade as a frontier node (its cuts again, old
// subtrees moved where their arrivals did not change; flip_frontiers), one
// deeper is replayed. This is
// not the paper's constant-size surgery (LeftShave and the splits of
// sections 3.1.1-3.1.4), though the fit of old subtrees to new cells follows
// the moved walls as LeftShave does.
//
// An update reads the sign of every certificate in force it decides again,
// instead of computing it (Segment_predicates::held): the sign holds until
// the certificate's failure, which is later than now. The construction
// likewise reads the sign of a key it already decided at another node.
//
// Floating-point kernels only: rounding can make a construction's signs
// contradict each other (Bsp_contradiction). The run then builds the whole
// tree again at now, and failing that at now + 2^i epsilon, i = 1, ...,
// kinetic::recovery_steps, the first that succeeds; the batches in between
// are lost, which kvd diff reports as missed. When none succeeds the run
// stops (stuck()). In the exact kernel a contradiction is a bug and is thrown.
// With validation, a floating-point run whose tree is stale (an event
// missed) adopts the fresh build and its instant, as the KVD's does.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_set>
#include <vector>

#include "kvd/detail/flat_map.hpp"
#include "kvd/detail/kinetic/root_cache.hpp"
#include "kvd/detail/kinetic/time_heap.hpp"
#include "kvd/detail/segments/bsp_builder.hpp"
#include "kvd/detail/segments/reroute.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

// How the tree just after a batch is made: by the frontier replay where it
// applies (local), by replaying the topmost subtrees whole (subtree, the
// previous local update), or by building the whole tree again (rebuild, the
// reference). All three make the same trees and certificates.
enum class Segment_update { local, subtree, rebuild };
inline constexpr const char* segment_update_names[] = {"local", "subtree", "rebuild"};

template <class K>
class Kinetic_segment_bsp {
public:
  using Time = typename K::Time;

  struct Batch {
    Time time;
    std::vector<Segment_certificate_key> failing;  // in key order
    std::array<std::size_t, 4> events{};           // failures by Segment_event (event_in_batch)
    bool changed = false;                          // the tree just after differs from the one before
    std::size_t certificates = 0;                  // in force after the batch
    double update_seconds = 0;                     // the tree and its certificates made again
    std::size_t nodes_rebuilt = 0;                 // nodes made again (all of them with rebuild)
    // The topmost nodes of the failures updated by the frontier replay (a
    // flip's remade as frontier nodes included), and those whose subtree was
    // replayed whole (local and subtree updates).
    std::size_t frontier_replays = 0, subtree_replays = 0;
    // The signs the update decided, and those it read from the certificates
    // in force (rule held): its cost in predicates, the same on any machine
    // (not counted: a fresh build adopted by validation, set_motion).
    long signs = 0, held = 0;
    long repeated = 0;  // answered from a remembered instant (Segment_predicates::remember): this run does not remember
  };

  // The scene is copied. With `validate`, the tree in force is compared,
  // before each batch, with a fresh build at an instant strictly between the
  // last batch and this one (a rational in the exact kernel). The run starts
  // at the scene's start, or just after `from`.
  Kinetic_segment_bsp(const K& k, Segment_scene scene, bool validate, Segment_update update = Segment_update::local,
                      const std::optional<Time>& from = std::nullopt);

  const Time& now() const { return now_; }
  const Segment_scene& scene() const { return scene_; }
  // The tree in force, numbered afresh (a copy: the run edits its own).
  Cylindrical_bsp tree() const { return tree_.compacted(); }
  std::size_t certificates() const { return certs_.size(); }
  // The construction's steps logged at each node of tree(), in its
  // pre-order: those a construction at now makes (proofs/
  // segment-local-update.md, "Exact logs"); for tests.
  std::vector<std::vector<Arrival>> arrivals() const;
  // The certificates in force, each with the nodes (of tree()) where it was
  // decided (-1: at no node), in key order.
  std::vector<std::pair<Segment_certificate_key, std::vector<std::int32_t>>> certificate_list() const;
  // The polynomials in t of a certificate in force (each factor's value, or
  // its first ε-coefficient that does not vanish; constants left out) and the
  // sign it had when decided: the product of the factors' signs.
  const std::vector<typename K::Poly>& polynomials(const Segment_certificate_key& key) const {
    return certs_.at(key).polys;
  }
  int sign(const Segment_certificate_key& key) const { return certs_.at(key).sign; }
  // The earliest failure of a certificate in force after now, within the
  // scene's span; none when nothing fails there.
  std::optional<Time> next_event_time();
  // Processes the next batch. Precondition: next_event_time() has a value.
  // (A floating-point run with validation may first adopt a fresh build; when
  // nothing fails after it, the batch returned is that adoption, with no
  // failures.)
  Batch advance();
  // Processes every batch at a time <= t, then moves now to t (if later),
  // but not past the span's end.
  std::vector<Batch> advance_to(const Time& t);
  // A flight-plan change: segment `segment` follows `motion` from now on.
  // The motion must put the segment where it is now (std::invalid_argument
  // otherwise, and when W vanishes at now or later in the span). Only the
  // certificates naming the segment are made again (Lemma 3.1); where the
  // new motion changes a sign just after now, the tree is updated as for a
  // batch. Returns whether the tree changed.
  bool set_motion(std::size_t segment, const Segment_motion& motion);
  // The validations that found a tree in force different from a fresh
  // build, described (empty when every one agreed), and how many ran.
  const std::vector<std::string>& validation_failures() const { return failures_; }
  std::size_t validations() const { return validations_; }
  // Floating-point kernels: the contradictions met (failed_builds), the
  // stale trees validation found (stale_trees), the builds that repaired
  // them (rebuilds) and the contradictions none did (unrepaired); all zero
  // in the exact kernel.
  const kinetic::Recovery& recovery() const { return recovery_; }
  // Whether the run stopped at a contradiction no rebuild repaired.
  bool stuck() const { return recovery_.unrepaired > 0; }

private:
  using P = typename K::Poly;
  struct Certificate {
    std::vector<P> polys;
    std::vector<std::int32_t> nodes;  // where it was decided; -1: at no node
    int sign = 0;                     // as decided
    std::uint64_t version = 0;        // queue entries of another version are stale
  };
  struct Entry {
    Time time;
    Segment_certificate_key key;
    std::uint64_t version;
  };

  void record(const Segment_certificate_key& key, std::vector<P>&& polys, std::int32_t node, int sign);
  // The certificate entered in the index by segment, once that is made
  // (see index() in the source); the index made from the certificates.
  void index(const Segment_certificate_key& key);
  void make_index();
  void enter(const Segment_certificate_key& key);
  typename Segment_predicates<K>::Recorder recorder();
  // Queues the certificate's next failure after now, within the span.
  void schedule(const Segment_certificate_key& key, Certificate& c);
  // A certificate whose sign changed, with the nodes where it was decided
  // (-1: at no node, a flip certificate, decided again after the update).
  using Failing = std::pair<Segment_certificate_key, std::vector<std::int32_t>>;
  // The tree just after now; whether it changed, and the nodes made.
  bool update(const std::vector<Failing>& failing, Batch& b);
  using Replay_root = segments::Replay_root;
  // The frontier replay at the topmost node u (see above; `nodes`: every
  // failing node, sorted): the changing segments' steps decided again and
  // their logs and certificates above the frontier made anew; returns the frontier
  // nodes to replay, or none when it does not apply (and nothing changed).
  std::optional<std::vector<Replay_root>> frontier_replay(std::size_t u, const std::vector<Failing>& failing,
                                                          const std::vector<std::int32_t>& nodes);
  // The topmost failing nodes (of `nodes`, sorted) that a flip remakes as
  // frontier nodes, with the rank of the turning segment: those that are its
  // first cut on their path and below which every failing key is the x
  // order of two points of a turning segment (proofs/segment-local-update.md,
  // "Flips").
  std::map<std::size_t, std::size_t> flip_frontiers(const std::vector<Failing>& failing,
                                                    const std::vector<std::int32_t>& nodes) const;
  void rebuild();
  // Compares the tree in force with a fresh build strictly between now and
  // t. Floating-point kernels: a stale tree is replaced by the fresh build,
  // and now moves to its instant; whether that happened.
  bool validate(const Time& t);
  // Runs f (a construction or an update); in a floating-point kernel, a
  // contradiction in it is repaired by building the tree again (see above).
  // Whether the tree was built again.
  template <class F>
  bool guarded(F f);
  // Replays the subtrees of the roots (none below another; `failing`: every
  // failing node, sorted); whether one's text changed.
  bool replay(const std::vector<Replay_root>& roots, const std::vector<std::int32_t>& failing, std::size_t& added);
  // A node's certificate keys move to another slot (Subtree_fit).
  void move_keys(std::size_t from, std::size_t to);
  void forget(std::size_t node);
  // The key's decision at the node goes (drop), and the node's entry of it.
  void unrecord(const Segment_certificate_key& key, std::int32_t node);
  // Removes the certificate's decision at `node`; with its last, the
  // certificate goes to limbo_.
  void drop(const Segment_certificate_key& key, std::int32_t node);
  bool stale(const Entry& e) const;

  K k_;
  Segment_scene scene_;
  bool validate_;
  Segment_update update_;
  Time now_;
  bool bounded_;
  Time end_;
  Segment_predicates<K> pred_;
  Cylindrical_bsp tree_;
  Build_log log_;
  // Stored flat: every sign the run reads from a certificate in force is a
  // lookup here (kvd/detail/flat_map.hpp; a reference into it holds only
  // until the next insertion or erasure).
  using Certificates = kvd::detail::Flat_map<Segment_certificate_key, Certificate, Segment_certificate_key_hash>;
  Certificates certs_;
  // During an update: the certificates in force at its start that have lost
  // every node. One decided again is taken back, with its polynomials and
  // its queue entry (its sign still holds); the rest are gone at the end.
  Certificates limbo_;
  std::vector<std::vector<Segment_certificate_key>> node_keys_;  // per node slot
  // Where the certificates naming a crossing were decided: when a replay
  // finds a crossing no longer, its certificates above the replayed subtree go.
  std::map<Site_point, std::vector<std::pair<Segment_certificate_key, std::int32_t>>> by_crossing_;
  // The certificate keys naming each segment, for set_motion (see index()).
  std::vector<std::unordered_set<Segment_certificate_key, Segment_certificate_key_hash>> by_segment_;
  std::size_t indexed_ = 0;  // keys added to by_segment_ since it was last made
  bool indexing_ = false;    // by_segment_ made (at the first set_motion) and kept
  kinetic::Time_heap<K, Entry> queue_{k_};
  std::uint64_t versions_ = 0;
  kinetic::Root_cache<K> roots_;
  std::vector<std::string> failures_;
  std::size_t validations_ = 0;
  kinetic::Recovery recovery_;
};

}  // namespace kvd::segments
