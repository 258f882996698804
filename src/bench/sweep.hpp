// What the bench suites share: the --out folder; and for those that sweep
// the number of triangles or segments, the --sizes option and the scenes
// generated for a size as `kvd generate FAMILY --triangles N --moving F
// --degree D --seed 1` (or `segments-FAMILY --n N --moving M --seed 1`)
// makes them.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <string>
#include <numeric>
#include <vector>

#include "kvd/scene/scene.hpp"
#include "kvd/segments/segment_generators.hpp"

namespace kvd::bench {

// "25,50,100" as sizes, increasing and distinct; a Usage_error naming
// `kvd bench SUITE` and `flag` if an item is not a positive number of `what`.
std::vector<std::size_t> sizes_option(const std::string& suite, const std::string& text,
                                      const std::string& flag = "--sizes", const std::string& what = "triangles");

// The uniform-scale or uniform-density scene of `size` triangles, seed 1.
scene::Scene generated(const std::string& suite, const std::string& family, std::size_t size, const scene::Q& moving,
                       int degree);

// The generated segment scene of n segments, m of them moving, seed 1.
segments::Segment_scene generated_segments(const std::string& suite, segments::Segment_family family, std::size_t n,
                                           std::size_t m, segments::Crossings crossings);

// The mean and the largest of v; 0 for none.
inline double mean_of(const std::vector<double>& v) {
  return v.empty() ? 0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}
inline double max_of(const std::vector<double>& v) { return v.empty() ? 0 : *std::max_element(v.begin(), v.end()); }

// Milliseconds from `start` to now (steady clock).
inline double ms_since(std::chrono::steady_clock::time_point start) {
  return 1000 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// --out DIR: a Usage_error naming `kvd bench SUITE` when DIR holds a quote
// (the gnuplot scripts quote it); check before the first run.
void check_out(const std::string& suite, const std::string& dir);
// Creates DIR and its parents; a Usage_error naming the suite when it cannot.
void make_out(const std::string& suite, const std::string& dir);

}  // namespace kvd::bench
