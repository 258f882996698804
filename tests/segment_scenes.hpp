// Small segment scenes built in code, shared by the segment tests.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kvd/detail/scene/priority.hpp"
#include "kvd/segments/segment_generators.hpp"
#include "kvd/segments/segment_io.hpp"
#include "kvd/segments/segment_scene.hpp"

namespace kvd::test {

inline segments::Segment fixed(long x0, long y0, long x1, long y1) {
  segments::Segment s;
  s.rest = {segments::Point3{x0, y0, 1}, segments::Point3{x1, y1, 1}};
  return s;
}

inline segments::QPoly linear(long c0, long c1) { return segments::QPoly({mpq_class(c0), mpq_class(c1)}); }

// A segment whose endpoints move: each coordinate a polynomial in t.
inline segments::Segment moving(const segments::QPoly& x0, const segments::QPoly& y0, const segments::QPoly& x1,
                                const segments::QPoly& y1) {
  segments::Segment s;
  s.rest = {segments::Point3{0, 0, 1}, segments::Point3{0, 0, 1}};
  s.motion.kind = segments::Segment_motion::Kind::endpoints;
  s.motion.endpoints = {segments::Motion_point3{x0, y0, segments::QPoly(1)},
                        segments::Motion_point3{x1, y1, segments::QPoly(1)}};
  return s;
}

// The segments in the given priority order, over [start, end] (no end: none).
inline segments::Segment_scene scene_of(std::vector<segments::Segment> segs, std::vector<std::size_t> order,
                                        long start = 0, std::optional<long> end = std::nullopt) {
  segments::Segment_scene s;
  s.segments = std::move(segs);
  s.order = std::move(order);
  s.start = start;
  if (end) s.end = mpq_class(*end);
  s.derive();
  return s;
}

// A generated scene of the family over [0, end], the generator's other
// options at their defaults.
inline segments::Segment_scene generated(segments::Segment_family family, std::size_t n, std::uint64_t seed,
                                         long end, segments::Crossings crossings = segments::Crossings::linear) {
  segments::Segment_generator_options o;
  o.family = family;
  o.n = n;
  o.seed = seed;
  o.end = end;
  o.crossings = crossings;
  return segments::generate_segments(o);
}

// Seven segments with endpoints on small integers, over [0, 2], moving
// linearly (all of them for an even seed, every other one for an odd seed):
// shared coordinates and simultaneous events are common. None when the
// endpoints of a segment meet in the span (sampled), which is not valid input.
inline std::optional<segments::Segment_scene> small_integer_scene(std::uint64_t seed) {
  scene::Split_mix64 g(seed);
  std::vector<segments::Segment> segs;
  const bool all_moving = seed % 2 == 0;
  while (segs.size() < 7) {
    const long x0 = g.between(-6, 6), y0 = g.between(-6, 6), x1 = g.between(-6, 6), y1 = g.between(-6, 6);
    if (x0 == x1 && y0 == y1) continue;
    if (!all_moving && segs.size() % 2 == 0) {
      segs.push_back(fixed(x0, y0, x1, y1));
      continue;
    }
    const long vx = g.between(-2, 2), vy = g.between(-2, 2), wx = g.between(-2, 2), wy = g.between(-2, 2);
    segs.push_back(moving(linear(x0, vx), linear(y0, vy), linear(x1, wx), linear(y1, wy)));
  }
  segments::Segment_scene s;
  s.segments = std::move(segs);
  s.seed = seed;
  s.end = 2;
  s.derive();
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    const auto p = s.endpoint(2 * i), q = s.endpoint(2 * i + 1);
    const segments::QPoly dx = p[0] - q[0], dy = p[1] - q[1];
    for (int n = 0; n <= 200; ++n) {
      const mpq_class t(n, 100);
      if (dx(t) == 0 && dy(t) == 0) return std::nullopt;
    }
  }
  return s;
}

// Generated scenes over [0, 2], random (n_random segments) and rotating
// (n_rotating), of seeds 1 to `seeds`, and the small-integer scenes of
// seeds 1 to 12, named.
inline std::vector<std::pair<std::string, segments::Segment_scene>> generated_and_small(std::size_t n_random,
                                                                                        std::size_t n_rotating,
                                                                                        std::uint64_t seeds) {
  std::vector<std::pair<std::string, segments::Segment_scene>> scenes;
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    scenes.emplace_back("random " + std::to_string(seed), generated(segments::Segment_family::random, n_random, seed, 2));
    scenes.emplace_back("rotating " + std::to_string(seed),
                        generated(segments::Segment_family::rotating, n_rotating, seed, 2));
  }
  for (std::uint64_t seed = 1; seed <= 12; ++seed)
    if (auto s = small_integer_scene(seed)) scenes.emplace_back("small " + std::to_string(seed), *s);
  return scenes;
}

// The scenes on which the paper's certificates are checked against the
// tree's changes (test_aeg_certificates, test_aeg_kinetic), named: five
// bundled ones, and generated ones of the three families (the degenerate
// one: shared x-coordinates, concurrent crossings, collinear overlaps,
// resolved by the perturbation), seeds 1 to 4.
inline std::vector<std::pair<std::string, segments::Segment_scene>> certificate_scenes() {
  std::vector<std::pair<std::string, segments::Segment_scene>> scenes;
  for (const char* name : {"two-crossing", "over-endpoint", "turning-vertical", "concurrent-three", "rotating-10"})
    scenes.emplace_back(name, segments::load_segments(std::string(KVD_SOURCE_DIR) + "/data/segments/" + name + ".json"));
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    scenes.emplace_back("random " + std::to_string(seed), generated(segments::Segment_family::random, 12, seed, 10));
    scenes.emplace_back("rotating " + std::to_string(seed), generated(segments::Segment_family::rotating, 6, seed, 10));
    scenes.emplace_back("degenerate " + std::to_string(seed),
                        generated(segments::Segment_family::degenerate, 10, seed, 10));
  }
  return scenes;
}

}  // namespace kvd::test
