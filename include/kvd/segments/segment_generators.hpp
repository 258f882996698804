// Generators of segment scenes (`kvd generate segments-*`).
//
// Every number is an exact rational with a small denominator and all
// randomness comes from SplitMix64 (kvd/detail/scene/priority.hpp), so a seed
// fixes the output byte for byte on every platform. Every generated scene
// loads back through read_segments. Parameters that cannot be met raise
// kvd::scene::Generator_error.
#pragma once

#include <cstdint>
#include <optional>

#include "kvd/scene/generators.hpp"
#include "kvd/segments/segment_scene.hpp"

namespace kvd::segments {

enum class Segment_family {
  // n segments of one length at random places and directions in the box
  // [0, box]^2, no two endpoints with the same x and none vertical at the
  // start time.
  random,
  // The same places, every moving segment turning about its midpoint by the
  // exact rational rotation by 2 atan(w t), so that segments turn through
  // vertical (the cylindrical BSP's flip events).
  rotating,
  // Small gadgets in the cells of a grid, repeated up to n segments: three
  // segments through one point, two collinear overlapping segments, a
  // vertical segment and a segment above it sharing its x, two segments
  // sharing both endpoints' x. Moving segments translate vertically (linear
  // or quadratic motion), which keeps every x, so shared x and vertical
  // segments stay while they cross the others; or they turn as in `rotating`.
  degenerate,
};

// How a moving segment moves: translation by a random velocity (`linear`),
// translation with a t^2 term (`quadratic`), or the rotation about its
// midpoint (`rotating`).
enum class Segment_motion_kind { linear, quadratic, rotating };

// The number of crossings k at the start time the segment length aims at
// when none is given: `linear` takes the length 1/ceil(sqrt(n)) of the box
// side (k = O(n)), `quadratic` half the box side (k = Theta(n^2)).
enum class Crossings { linear, quadratic };

struct Segment_generator_options {
  Segment_family family = Segment_family::random;
  std::size_t n = 100;
  std::uint64_t seed = 0;  // of the generator and of the priority order
  Q box = 100;             // the side of the box [0, box]^2
  // random and rotating: the segments' length as a fraction of the box side,
  // in (0, 1]; from `crossings` when absent.
  std::optional<Q> length;
  Crossings crossings = Crossings::linear;
  // How many of the n segments move (a seeded choice); all when absent.
  std::optional<std::size_t> moving;
  // The motion of the moving segments; the family's own when absent
  // (rotating for `rotating`, linear otherwise). `rotating` allows no other.
  std::optional<Segment_motion_kind> motion;
  Q end = 10;  // the time span is [0, end]
};

Segment_scene generate_segments(const Segment_generator_options& options);

}  // namespace kvd::segments
