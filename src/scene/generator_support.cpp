#include "generator_support.hpp"

namespace kvd::scene {

Scene empty_scene(const std::string& name, std::uint64_t seed) {
  Scene s;
  s.name = name;
  s.start = 0;
  s.end = Q(10);
  s.x = {{QPoly(1), QPoly(), QPoly(), QPoly()}};
  s.z = {{QPoly(), QPoly(), QPoly(1), QPoly()}};
  s.priority_spec.seed = seed;
  return s;
}

std::size_t moving_count(const Q& fraction, std::size_t count) {
  return static_cast<std::size_t>(mpz_class(fraction * static_cast<long>(count) + Q(1, 2)).get_ui());
}

}  // namespace kvd::scene
