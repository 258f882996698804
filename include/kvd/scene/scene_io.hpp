// Reading and writing scene files (`kvd-scene/1`, the scene format page).
//
// Every rejection throws Scene_error with a message "SOURCE: /json/pointer:
// what was expected", where SOURCE is the file name and the pointer is the
// JSON place (RFC 6901), "/" for the document itself.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "kvd/scene/scene.hpp"

namespace kvd::scene {

class Scene_error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// A motion polynomial has at most this degree in t (33 coefficients): the
// certificates multiply motions, so their degree, and the cost of isolating
// their roots, grows with it.
inline constexpr int max_motion_degree = 32;

struct Load_options {
  // Replaces the file's priority (seed or explicit order) by this seed.
  std::optional<std::uint64_t> seed;
  // Skips the check that triangles are disjoint at the start time.
  bool allow_intersecting = false;
};

Scene read_scene(const std::string& text, const std::string& source, const Load_options& options = {});
Scene load_scene(const std::string& path, const Load_options& options = {});
// The bytes of a file (or of standard input for "-"), at most 64 MiB;
// Scene_error naming it when it is missing, a folder, unreadable or larger.
std::string read_input(const std::string& path);
// How messages name the input at `path`: the path, or "(stdin)" for "-".
std::string input_name(const std::string& path);
// The scene as a `kvd-scene/1` document; numbers are written as exact strings.
// read_scene(write_scene(s)) == s.
std::string write_scene(const Scene& s);
// A motion as the value of an object's "motion" key, on one line ("null"
// for none).
std::string write_motion(const Motion& m);

}  // namespace kvd::scene
