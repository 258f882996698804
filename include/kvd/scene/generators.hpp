// Generators of the thesis's data sets (chapter 8.2) and of degenerate scenes.
//
// Every number is an exact rational and all randomness comes from SplitMix64
// (kvd/detail/scene/priority.hpp), so a seed fixes the output byte for byte on every
// platform. Each generated scene is disjoint at time 0, checked exactly.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

#include "kvd/scene/scene.hpp"

namespace kvd::scene {

// Raised when the parameters cannot be met (a box too crowded to place every
// triangle without intersections).
class Generator_error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct Uniform_params {
  std::size_t triangles = 100;
  Q moving = 1;  // fraction of moving triangles, in [0, 1]
  int degree = 1;  // degree of the random polynomial translations
  std::uint64_t seed = 0;
  // Called after each triangle is placed (placement is quadratic in N).
  std::function<void(std::size_t placed)> progress;
};

// `uniform-scale`: N exactly congruent triangles (one object each) with random
// positions in the box [0,100]^3 and random orientations (exact rational
// rotations from integer quaternions). The triangle's size is the same for
// every N.
Scene uniform_scale(const Uniform_params& p);
// `uniform-density`: as uniform-scale, with the triangle scaled by
// (100/N)^(1/3) (rounded to 1/1000) so that the number of triangles per
// triangle-sized cube is that of the 100-triangle scene; identical to
// uniform-scale at N = 100.
Scene uniform_density(const Uniform_params& p);

// `boxes`: axis-aligned boxes on a grid, all sizes and gaps from a few
// integers, so that many faces are coplanar and many coordinates shared; a
// fraction of them translate along a coordinate axis, which keeps faces
// parallel and coplanarities alive while moving.
Scene boxes(std::size_t count, const Q& moving, std::uint64_t seed);

// `rotor`: a static floor and `blades` triangles turning about the z axis by
// the exact rational rotation by 2 atan(t) (a motion of degree 2).
Scene rotor(std::size_t blades, std::uint64_t seed);

}  // namespace kvd::scene
