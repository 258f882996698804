// The scene model of moving segments in the plane (`kvd-segments/1`,
// SEGMENT_FORMAT.md): the input of the Agarwal–Erickson–Guibas cylindrical
// BSP (seed 003, section 2.1) and of its kinetic version (section 3.1).
//
// Points are homogeneous (X, Y, W), W last as everywhere in the library.
// Segment s has endpoints 2s and 2s + 1 (the first as written is the marked
// endpoint). Everything is exact.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kvd/kernel/poly.hpp"

namespace kvd::segments {

using Q = mpq_class;
using QPoly = Poly<Q>;
using Point3 = std::array<Q, 3>;             // (X, Y, W), a constant point
using Motion_point3 = std::array<QPoly, 3>;  // (X, Y, W) as polynomials in t
using Motion_matrix3 = std::array<std::array<QPoly, 3>, 3>;

// A motion as the file gives it (kept in its form so a scene writes back as
// it was read).
struct Segment_motion {
  enum class Kind { none, translation, matrix, endpoints };
  Kind kind = Kind::none;
  std::array<QPoly, 2> translation;         // (dx, dy)
  Motion_matrix3 matrix;                    // applied to (x, y, 1)
  std::array<Motion_point3, 2> endpoints;   // one point3 per endpoint
  friend bool operator==(const Segment_motion&, const Segment_motion&) = default;
};

struct Segment {
  std::string name;              // may be empty
  std::array<Point3, 2> rest;    // rest positions, W != 0
  Segment_motion motion;
  friend bool operator==(const Segment&, const Segment&) = default;
};

class Segment_scene {
public:
  std::string name;
  Q start = 0;
  std::optional<Q> end;
  std::uint64_t seed = 0;                          // {"seed": N}
  std::optional<std::vector<std::size_t>> order;   // {"order": [...]}, highest priority first
  std::vector<Segment> segments;

  // Derived by `derive()`.
  std::vector<std::size_t> priority_order;  // segment ids, highest priority first
  std::vector<std::size_t> rank;            // the place of each segment in priority_order

  // The priority: the explicit order, or the segments shuffled with the
  // project's SplitMix64 Fisher–Yates (kvd/detail/scene/priority.hpp) from
  // `seed`. Unlike the KVD, static segments are not put first: the paper's
  // analysis assumes a uniformly random permutation.
  void derive();

  std::size_t endpoint_count() const { return 2 * segments.size(); }
  bool is_moving(std::size_t segment) const;
  std::size_t moving_count() const;
  int max_motion_degree() const;
  // Endpoint e = 2 s + k as polynomials in t, and at an instant.
  Motion_point3 endpoint(std::size_t e) const;
  Point3 endpoint_at(std::size_t e, const Q& t) const;
  // The time limit of a run to `until` (none: to the end): the earlier of
  // the two; none when there is neither.
  std::optional<Q> limit(const std::optional<Q>& until) const {
    return until && (!end || *until < *end) ? until : end;
  }

  friend bool operator==(const Segment_scene& a, const Segment_scene& b) {
    return a.name == b.name && a.start == b.start && a.end == b.end && a.seed == b.seed && a.order == b.order &&
           a.segments == b.segments;
  }
};

}  // namespace kvd::segments
