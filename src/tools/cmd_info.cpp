// kvd info SCENE: counts of a scene, of triangles or of segments.
#include <iostream>
#include <optional>

#include "cli.hpp"
#include "json_out.hpp"
#include "segment_commands.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/segments/segment_crossings.hpp"
#include "kvd/segments/segment_io.hpp"

namespace kvd::cli {

namespace {
const char* const info_help =
    "usage: kvd info SCENE [--json] [--seed N] [--allow-intersecting]\n"
    "\n"
    "SCENE is a file, or - for standard input.\n"
    "Loads and validates a kvd-scene/1 file and prints its counts: objects,\n"
    "vertices, edges, triangles, moving triangles, maximum motion degree.\n"
    "For a kvd-segments/1 file (told apart by its \"format\"): segments, moving\n"
    "segments, maximum motion degree, proper crossings at the start time\n"
    "(counted exactly) and the time span.\n"
    "\n"
    "  --json                print one JSON object instead of text\n"
    "  --seed N              replace the file's priority order by the seeded one\n"
    "  --allow-intersecting  accept triangles that intersect at the start time\n"
    "\n"
    "Exit status: 0 on success, 2 on a bad scene or bad usage.\n";

int segment_info(const Scene_args& sa, const std::string& text) {
  const std::string& path = *sa.path;
  const segments::Segment_scene s =
      segments::read_segments(text, scene::input_name(path), segments::Segment_load_options{sa.load.seed});
  const std::size_t crossings = segments::count_crossings(s, s.start);
  const std::string end = s.end ? s.end->get_str() : "no end";
  if (sa.json) {
    std::cout << json_line({{"file", path}, {"format", "kvd-segments/1"}, {"name", s.name},
                            {"segments", s.segments.size()}, {"moving_segments", s.moving_count()},
                            {"max_motion_degree", s.max_motion_degree()}, {"crossings_at_start", crossings},
                            {"start", s.start.get_str()}, {"end", s.end ? Json(end) : Json(nullptr)}})
              << "\n";
  } else {
    std::cout << "scene:             " << (s.name.empty() ? "(unnamed)" : s.name) << " (" << path << ")\n"
              << "format:            kvd-segments/1\n"
              << "segments:          " << s.segments.size() << "\n"
              << "moving segments:   " << s.moving_count() << "\n"
              << "max motion degree: " << s.max_motion_degree() << "\n"
              << "crossings:         " << crossings << " (at the start time)\n"
              << "time span:         [" << s.start.get_str() << ", " << end << "]\n";
  }
  return 0;
}

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
  const std::string text = sa.read_text("info");
  if (segments::scene_format(text) == "kvd-segments/1") {
    if (sa.load.allow_intersecting) refuse_triangle_flags("info", {"--allow-intersecting"});
    return segment_info(sa, text);
  }
  const scene::Scene s = sa.read_scene("info", text);
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
