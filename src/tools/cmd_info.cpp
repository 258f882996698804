// kvd info SCENE: counts of a scene.
#include <iostream>
#include <optional>

#include "cli.hpp"
#include "json_out.hpp"
#include "kvd/scene/scene_io.hpp"

namespace kvd::cli {

namespace {
const char* const info_help =
    "usage: kvd info SCENE [--json] [--seed N] [--allow-intersecting]\n"
    "\n"
    "SCENE is a file, or - for standard input.\n"
    "Loads and validates a kvd-scene/1 file and prints its counts: objects,\n"
    "vertices, edges, triangles, moving triangles, maximum motion degree.\n"
    "\n"
    "  --json                print one JSON object instead of text\n"
    "  --seed N              replace the file's priority order by the seeded one\n"
    "  --allow-intersecting  accept triangles that intersect at the start time\n"
    "\n"
    "Exit status: 0 on success, 2 on a bad scene or bad usage.\n";
}  // namespace

int info(Args& args) {
  Scene_args sa;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << info_help;
      return 0;
    }
    if (!sa.take(args, a)) args.unknown(a);
  }
  const scene::Scene s = sa.load_scene("info");
  const std::string& path = *sa.path;
  const bool json = sa.json;
  const std::size_t moving = s.moving_triangle_count();
  if (json) {
    std::cout << json_line({{"file", path}, {"name", s.name}, {"objects", s.objects.size()},
                            {"vertices", s.rest.size()}, {"edges", s.edges.size()},
                            {"triangles", s.triangles.size()}, {"moving_triangles", moving},
                            {"max_motion_degree", s.max_motion_degree()}})
              << "\n";
  } else {
    std::cout << "scene:             " << (s.name.empty() ? "(unnamed)" : s.name) << " (" << path << ")\n"
              << "objects:           " << s.objects.size() << "\n"
              << "vertices:          " << s.rest.size() << "\n"
              << "edges:             " << s.edges.size() << "\n"
              << "triangles:         " << s.triangles.size() << "\n"
              << "moving triangles:  " << moving << "\n"
              << "max motion degree: " << s.max_motion_degree() << "\n";
  }
  return 0;
}

}  // namespace kvd::cli
