// The numbers of a scene with their JSON places, for checks that depend on
// the arithmetic a scene will be run in (a floating-point kernel cannot hold
// 1e400).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "kvd/scene/scene.hpp"

namespace kvd::scene {

struct Number_place {
  std::string place;  // JSON pointer of the number, or of its polynomial
  int power = 0;      // for a polynomial: the power of t it multiplies
  Q value;
};

// The first number of the scene in file order (decomposition, then each
// object's vertices and motion) for which `bad` holds.
std::optional<Number_place> first_number(const Scene& s, const std::function<bool(const Q&)>& bad);

}  // namespace kvd::scene
