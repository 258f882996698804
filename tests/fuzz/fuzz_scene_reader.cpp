// libFuzzer harness on the scene readers, as the command line picks them:
// a document whose "format" is "kvd-segments/1" goes to the segment reader,
// anything else to the motion reader of a flight-plan change and then to
// the triangle reader. Any bytes either load or are refused with
// Scene_error. Anything else (a crash, a sanitizer report, another
// exception, a hang) is a finding. The first byte also chooses, for
// triangles, whether intersecting triangles are allowed, and for segments
// whether the priority is replaced by a seed (`--seed`), so both paths of
// each are fuzzed.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kvd/scene/scene_io.hpp"
#include "kvd/segments/segment_io.hpp"

namespace {

// What loads must write back and load again as the same scene.
void segments(const std::string& text, bool reseed) {
  kvd::segments::Segment_load_options options;
  if (reseed) options.seed = text.size();
  const kvd::segments::Segment_scene s = kvd::segments::read_segments(text, "fuzz", options);
  if (!(kvd::segments::read_segments(kvd::segments::write_segments(s), "fuzz-again") == s)) __builtin_trap();
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
  } catch (const kvd::scene::Scene_error&) {
  }
}

void triangles(const std::string& text, bool allow_intersecting) {
  kvd::scene::Load_options options;
  options.allow_intersecting = allow_intersecting;
  const kvd::scene::Scene s = kvd::scene::read_scene(text, "fuzz", options);
  if (!(kvd::scene::read_scene(kvd::scene::write_scene(s), "fuzz-again", options) == s)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::uint8_t first = size > 0 ? data[0] : 0;
  try {
    if (kvd::segments::scene_format(text) == "kvd-segments/1") {
      segments(text, first & 2);
      return 0;
    }
    try {
      motion(text);
    } catch (const kvd::scene::Scene_error&) {
    }
    triangles(text, first & 1);
  } catch (const kvd::scene::Scene_error&) {
  }
  return 0;
}
