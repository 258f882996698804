// libFuzzer harness on the scene readers, as the command line picks them:
// a document whose "format" is "kvd-segments/1" goes to the segment reader,
// anything else to the triangle reader. Any bytes either load as a scene or
// are refused with Scene_error. Anything else (a crash, a sanitizer report,
// another exception, a hang) is a finding. For triangles the first byte also
// chooses whether intersecting triangles are allowed, so both paths are
// fuzzed.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kvd/scene/scene_io.hpp"
#include "kvd/segments/segment_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // What loads must write back and load again as the same scene.
    if (kvd::segments::scene_format(text) == "kvd-segments/1") {
      const kvd::segments::Segment_scene s = kvd::segments::read_segments(text, "fuzz");
      if (!(kvd::segments::read_segments(kvd::segments::write_segments(s), "fuzz-again") == s)) __builtin_trap();
      return 0;
    }
    kvd::scene::Load_options options;
    options.allow_intersecting = size > 0 && (data[0] & 1);
    const kvd::scene::Scene s = kvd::scene::read_scene(text, "fuzz", options);
    if (!(kvd::scene::read_scene(kvd::scene::write_scene(s), "fuzz-again", options) == s)) __builtin_trap();
  } catch (const kvd::scene::Scene_error&) {
  }
  return 0;
}
