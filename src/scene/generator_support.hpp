// Pieces shared by the scene generators.
#pragma once

#include <string>

#include "kvd/scene/scene.hpp"

namespace kvd::scene {

// A scene with no objects: time [0, 10], the default directions, the given
// priority seed.
Scene empty_scene(const std::string& name, std::uint64_t seed);

// The number of moving items for a fraction of `count`: round(fraction * count).
std::size_t moving_count(const Q& fraction, std::size_t count);

}  // namespace kvd::scene
