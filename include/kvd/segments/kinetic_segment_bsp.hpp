// The cylindrical BSP of moving segments kept through time (seed 003,
// section 3.1), as a stepping object over any kernel.
//
// Certificates: every sign the construction of the tree in force evaluated,
// with the polynomials that decided it (Segment_predicates::record); the
// tree cannot change before one of them changes sign, since the construction
// branches on nothing else. A batch is every certificate failing at the
// earliest failure time: exactly equal times in the exact kernel (decided by
// the kernel's compare), the thesis's epsilon-minimum in the floating-point
// ones. Each failure is classified as the paper's vertex, edge, intersection
// or flip event (event_of).
//
// This version makes the tree just after a batch by building it again at the
// batch's time, and its certificates with it; the paper's local updates
// (LeftShave and the splits of sections 3.1.1-3.1.4) are not implemented yet.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "kvd/detail/kinetic/root_cache.hpp"
#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

// How the tree just after a batch is made: by replaying, in the subtree of
// each node where a failing certificate was decided, the insertions that
// reached it (local), or by building the whole tree again (rebuild, the
// reference).
enum class Segment_update { local, rebuild };

template <class K>
class Kinetic_segment_bsp {
public:
  using Time = typename K::Time;

  struct Batch {
    Time time;
    std::vector<Segment_certificate_key> failing;  // in key order
    std::array<std::size_t, 4> events{};           // failures by Segment_event
    bool changed = false;                          // the tree just after differs from the one before
    std::size_t certificates = 0;                  // in force after the batch
    double update_seconds = 0;                     // the tree and its certificates made again
    std::size_t nodes_rebuilt = 0;                 // nodes made again (all of them with rebuild)
  };

  // The scene is copied. With `validate`, the tree in force is compared,
  // before each batch, with a fresh build at an instant strictly between the
  // last batch and this one (a rational in the exact kernel).
  Kinetic_segment_bsp(const K& k, Segment_scene scene, bool validate, Segment_update update = Segment_update::local);

  const Time& now() const { return now_; }
  const Segment_scene& scene() const { return scene_; }
  const Cylindrical_bsp& tree() const { return tree_; }
  std::size_t certificates() const { return certificates_.size(); }
  // The earliest failure of a certificate in force after now, within the
  // scene's span; none when nothing fails there.
  std::optional<Time> next_event_time();
  // Processes the next batch. Precondition: next_event_time() has a value.
  Batch advance();
  // The validations that found a tree in force different from a fresh
  // build, described (empty when every one agreed), and how many ran.
  const std::vector<std::string>& validation_failures() const { return failures_; }
  std::size_t validations() const { return validations_; }

private:
  // The tree and its certificates at now, and each certificate's failure.
  void rebuild();

  K k_;
  Segment_scene scene_;
  bool validate_;
  Segment_update update_;
  Time now_;
  Segment_predicates<K> pred_;
  Cylindrical_bsp tree_;
  typename Segment_predicates<K>::Recorded certificates_;
  std::vector<std::pair<Segment_certificate_key, Time>> failing_;  // the certificates that fail, and when
  kinetic::Root_cache<K> roots_;
  std::vector<std::string> failures_;
  std::size_t validations_ = 0;
};

}  // namespace kvd::segments
