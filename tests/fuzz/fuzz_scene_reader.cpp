// libFuzzer harness on the scene readers: a document whose "format" is
// "kvd-segments/1" goes to the segment reader, anything else to the motion
// reader of a flight-plan change (as the Python bindings' set_motion reads
// one) and then to the triangle reader. Any bytes either load or are
// refused with Scene_error; what loads writes back and loads again as the
// same scene. Anything else (a crash, a sanitizer report, another
// exception, a refusal of what was written, a hang) is a finding. The
// input's length chooses, for triangles, whether intersecting triangles are
// allowed, and for segments whether the priority is replaced by a seed
// (`--seed`), so both paths of each are fuzzed (a first or last byte would
// nearly always be a brace).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "kvd/scene/scene_io.hpp"
#include "kvd/segments/segment_io.hpp"

namespace {

// Reads back what was written out: a refusal of it is a finding too.
template <class Read>
auto again(Read read) {
  try {
    return read();
  } catch (const kvd::scene::Scene_error&) {
    __builtin_trap();
  }
}

void segments(const std::string& text, bool reseed) {
  kvd::segments::Segment_load_options options;
  if (reseed) options.seed = text.size();
  const kvd::segments::Segment_scene s = kvd::segments::read_segments(text, "fuzz", options);
  const std::string written = kvd::segments::write_segments(s);
  if (!(again([&] { return kvd::segments::read_segments(written, "fuzz-again"); }) == s)) __builtin_trap();
}

// Whether a refusal is for the scene's geometry, which a motion read alone
// cannot see: an endpoint at or through infinity, the endpoints meeting.
bool geometric(const kvd::scene::Scene_error& e) {
  const std::string_view what = e.what();
  for (const char* why : {"W is zero", "W vanishes", "zero length", "endpoints coincide"})
    if (what.find(why) != std::string_view::npos) return true;
  return false;
}

// A motion that loads, given to a unit segment, must make a scene that
// either writes out and loads back unchanged or is refused for its geometry
// (an endpoint through infinity, the endpoints meeting).
void motion(const std::string& text) {
  kvd::segments::Segment_scene s;
  s.segments.push_back({"", {{{0, 0, 1}, {1, 0, 1}}}, kvd::segments::read_segment_motion(text, "fuzz")});
  s.derive();
  try {
    if (!(kvd::segments::read_segments(kvd::segments::write_segments(s), "fuzz-scene") == s)) __builtin_trap();
  } catch (const kvd::scene::Scene_error& e) {
    if (!geometric(e)) __builtin_trap();
  }
}

void triangles(const std::string& text, bool allow_intersecting) {
  kvd::scene::Load_options options;
  options.allow_intersecting = allow_intersecting;
  const kvd::scene::Scene s = kvd::scene::read_scene(text, "fuzz", options);
  const std::string written = kvd::scene::write_scene(s);
  if (!(again([&] { return kvd::scene::read_scene(written, "fuzz-again", options); }) == s)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const bool odd = size & 1;
  try {
    if (kvd::segments::scene_format(text) == "kvd-segments/1") {
      segments(text, odd);
      return 0;
    }
    try {
      motion(text);
    } catch (const kvd::scene::Scene_error&) {
    }
    triangles(text, odd);
  } catch (const kvd::scene::Scene_error&) {
  }
  return 0;
}
