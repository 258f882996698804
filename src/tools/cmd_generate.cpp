// kvd generate FAMILY: the thesis's data sets, degenerate scenes, and scenes
// of moving segments.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cli.hpp"
#include "kvd/detail/scene/exact_number.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/segments/segment_crossings.hpp"
#include "kvd/segments/segment_generators.hpp"
#include "kvd/segments/segment_io.hpp"

namespace kvd::cli {

namespace {
const char* const generate_help =
    "usage: kvd generate FAMILY [options] [-o FILE]\n"
    "\n"
    "Writes a kvd-scene/1 scene, or a kvd-segments/1 scene for the segments-*\n"
    "families (to stdout, or atomically to FILE). Exact rationals throughout;\n"
    "the same seed gives the same bytes on every platform.\n"
    "\n"
    "families:\n"
    "  uniform-scale    N congruent triangles, random positions and orientations\n"
    "                   in the box [0,100]^3 (thesis 8.2), same size for every N\n"
    "  uniform-density  the same, scaled by (100/N)^(1/3) to keep the density of\n"
    "                   the 100-triangle scene (identical to uniform-scale at N=100)\n"
    "  boxes            axis-aligned boxes with shared coordinates, coplanar faces\n"
    "  rotor            blades turning by the exact rational rotation 2 atan(t)\n"
    "  segments-random  N segments of one length at random in the box [0,B]^2, no\n"
    "                   shared x; prints the crossings at t = 0 on stderr\n"
    "  segments-rotating\n"
    "                   the same, turning about their midpoints by the rational\n"
    "                   rotation 2 atan(w t), so that they pass through vertical\n"
    "  segments-degenerate\n"
    "                   gadgets: three segments through a point, collinear\n"
    "                   overlaps, vertical segments, shared x; moving ones translate\n"
    "                   vertically (--moving 0 for the static variant)\n"
    "\n"
    "options:\n"
    "  --triangles N    uniform families: number of triangles (default 100)\n"
    "  --moving F       fraction of moving triangles or boxes, a number in [0,1]\n"
    "                   such as 1, 0.1 or 1/10 (default 1); for the segments-*\n"
    "                   families the number of moving segments (default all)\n"
    "  --degree D       uniform families: degree of the random polynomial\n"
    "                   translations (default 1: linear motion)\n"
    "  --boxes N        boxes: number of boxes (default 9)\n"
    "  --blades N       rotor: number of blades (default 3)\n"
    "  --n N            segments-*: number of segments (default 100)\n"
    "  --length F       segments-random, -rotating: segment length as a fraction\n"
    "                   of the box side, in (0,1] (default from --crossings)\n"
    "  --crossings K    linear (length 1/ceil(sqrt(N)): O(N) crossings, the\n"
    "                   default) or quadratic (length 1/2: Theta(N^2) crossings)\n"
    "  --motion M       segments-*: linear, quadratic or rotating (default linear;\n"
    "                   segments-rotating: rotating)\n"
    "  --box B          segments-*: side of the box (default 100)\n"
    "  --end T          segments-*: end of the time span [0, T] (default 10)\n"
    "  --seed S         seed of the generator and of the priority order (default 0)\n"
    "  -o FILE          write to FILE instead of stdout\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or parameters that cannot be met.\n";

using Family = segments::Segment_family;
using Motion_kind = segments::Segment_motion_kind;

// A segments-* family's scene text; its crossings at the start go to stderr.
std::string segment_scene_text(const std::string& family, segments::Segment_generator_options o,
                               const std::optional<std::string>& moving) {
  // The family is known (refuse_others).
  if (family == "segments-random") o.family = Family::random;
  else if (family == "segments-rotating") o.family = Family::rotating;
  else o.family = Family::degenerate;
  if (o.n > 20000) throw Usage_error("kvd generate: at most 20000 segments");
  if (moving) {
    if (moving->empty() || moving->size() > 5 || moving->find_first_not_of("0123456789") != std::string::npos)
      throw Usage_error("kvd generate: --moving expects a number of segments for " + family + ", got '" + *moving + "'");
    o.moving = std::stoul(*moving);
  }
  segments::Segment_scene s;
  try {
    s = segments::generate_segments(o);
  } catch (const scene::Generator_error& e) {
    throw Usage_error(std::string("kvd generate: ") + e.what());
  }
  const std::string text = segments::write_segments(s);
  // Every scene goes out only after the loader's full validation accepts it.
  segments::read_segments(text, "generated " + family);
  std::cerr << "kvd generate: " << s.segments.size() << " segments, " << segments::count_crossings(s, s.start)
            << " crossings at t = " << s.start.get_str() << "\n";
  return text;
}

// Refuses, rather than ignores, the options given that `family` does not read.
void refuse_others(const std::string& family, const std::vector<std::string>& given) {
  static const std::map<std::string, std::set<std::string>> reads{
      {"uniform-scale", {"--triangles", "--moving", "--degree"}},
      {"uniform-density", {"--triangles", "--moving", "--degree"}},
      {"boxes", {"--boxes", "--moving"}},
      {"rotor", {"--blades"}},
      {"segments-random", {"--n", "--moving", "--length", "--crossings", "--motion", "--box", "--end"}},
      {"segments-rotating", {"--n", "--moving", "--length", "--crossings", "--motion", "--box", "--end"}},
      {"segments-degenerate", {"--n", "--moving", "--motion", "--box", "--end"}}};
  const auto it = reads.find(family);
  if (it == reads.end()) throw Usage_error("kvd generate: unknown family '" + family + "' (see kvd generate --help)");
  std::string list;
  for (const std::string& a : given)
    if (!it->second.count(a)) list += (list.empty() ? "" : ", ") + a;
  if (!list.empty()) throw Usage_error("kvd generate: " + list + ": not read by the family " + family + " (see kvd generate --help)");
}

}  // namespace

int generate(Args& args) {
  std::optional<std::string> family, output, moving;
  scene::Uniform_params p;
  std::size_t box_count = 9, blades = 3;
  segments::Segment_generator_options so;
  std::vector<std::string> given;  // the options given but --seed and -o, which every family reads
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << generate_help;
      return 0;
    }
    if (a.rfind("--", 0) == 0 && a != "--seed") given.push_back(a);
    if (a == "--triangles") p.triangles = args.unsigned_value(a);
    else if (a == "--degree") {
      const std::uint64_t d = args.unsigned_value(a);
      if (d < 1 || d > 16) throw Usage_error("kvd generate: --degree must be between 1 and 16");
      p.degree = static_cast<int>(d);
    } else if (a == "--moving") moving = args.value(a);
    else if (a == "--boxes") box_count = args.unsigned_value(a);
    else if (a == "--blades") blades = args.unsigned_value(a);
    else if (a == "--n") so.n = args.unsigned_value(a);
    else if (a == "--length") so.length = exact_option("generate", a, args.value(a));
    else if (a == "--crossings")
      so.crossings = choice_option<segments::Crossings>(
          "generate", a, args.value(a),
          {{"linear", segments::Crossings::linear}, {"quadratic", segments::Crossings::quadratic}});
    else if (a == "--motion")
      so.motion = choice_option<Motion_kind>(
          "generate", a, args.value(a),
          {{"linear", Motion_kind::linear}, {"quadratic", Motion_kind::quadratic}, {"rotating", Motion_kind::rotating}});
    else if (a == "--box") so.box = exact_option("generate", a, args.value(a));
    else if (a == "--end") so.end = exact_option("generate", a, args.value(a));
    else if (a == "--seed") p.seed = so.seed = args.unsigned_value(a);
    else if (a == "-o") output = args.value(a);
    else if (!a.empty() && a[0] != '-' && !family) family = a;
    else args.unknown(a);
  }
  if (!family) throw Usage_error("kvd generate: missing the FAMILY (see kvd generate --help)");
  refuse_others(*family, given);
  if (family->rfind("segments-", 0) == 0) {
    const std::string text = segment_scene_text(*family, so, moving);
    if (output) write_atomically("generate", *output, text);
    else std::cout << text;
    return 0;
  }
  if (moving) {
    std::string why;
    const auto q = scene::parse_exact_number(*moving, why);
    if (!q || *q < 0 || *q > 1)
      throw Usage_error("kvd generate: --moving expects a number in [0, 1], got '" + *moving + "'");
    p.moving = *q;
  }
  if (p.triangles > 20000 || box_count > 10000 || blades > 10000)
    throw Usage_error("kvd generate: at most 20000 triangles, 10000 boxes or 10000 blades");
  if (p.triangles >= 2000)
    p.progress = [total = p.triangles](std::size_t placed) {
      if (placed % 1000 == 0 || placed == total)
        std::cerr << "kvd generate: placed " << placed << " of " << total << " triangles\n";
    };
  scene::Scene s;
  try {
    if (*family == "uniform-scale") s = scene::uniform_scale(p);
    else if (*family == "uniform-density") s = scene::uniform_density(p);
    else if (*family == "boxes") s = scene::boxes(box_count, p.moving, p.seed);
    else s = scene::rotor(blades, p.seed);  // the family is known (refuse_others)
  } catch (const scene::Generator_error& e) {
    throw Usage_error(std::string("kvd generate: ") + e.what());
  }
  const std::string text = scene::write_scene(s);
  // Every scene goes out only after the loader's full validation accepts it.
  scene::read_scene(text, "generated " + *family);
  if (output) write_atomically("generate", *output, text);
  else std::cout << text;
  return 0;
}

}  // namespace kvd::cli
