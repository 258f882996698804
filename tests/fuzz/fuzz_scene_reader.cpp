// libFuzzer harness on the scene reader: any bytes either load as a scene or
// are refused with Scene_error. Anything else (a crash, a sanitizer report,
// another exception, a hang) is a finding. The first byte also chooses
// whether intersecting triangles are allowed, so both paths are fuzzed.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kvd/scene/scene_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  kvd::scene::Load_options options;
  options.allow_intersecting = size > 0 && (data[0] & 1);
  try {
    const kvd::scene::Scene s = kvd::scene::read_scene(std::string(reinterpret_cast<const char*>(data), size), "fuzz", options);
    // What loads must write back and load again as the same scene.
    if (!(kvd::scene::read_scene(kvd::scene::write_scene(s), "fuzz-again", options) == s)) __builtin_trap();
  } catch (const kvd::scene::Scene_error&) {
  }
  return 0;
}
