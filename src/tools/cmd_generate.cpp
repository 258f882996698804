// kvd generate FAMILY: the thesis's data sets and degenerate scenes.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "cli.hpp"
#include "kvd/detail/scene/exact_number.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/scene/scene_io.hpp"

namespace kvd::cli {

namespace {
const char* const generate_help =
    "usage: kvd generate FAMILY [options] [-o FILE]\n"
    "\n"
    "Writes a kvd-scene/1 scene (to stdout, or atomically to FILE). Exact\n"
    "rationals throughout; the same seed gives the same bytes on every platform.\n"
    "\n"
    "families:\n"
    "  uniform-scale    N congruent triangles, random positions and orientations\n"
    "                   in the box [0,100]^3 (thesis 8.2), same size for every N\n"
    "  uniform-density  the same, scaled by (100/N)^(1/3) to keep the density of\n"
    "                   the 100-triangle scene (identical to uniform-scale at N=100)\n"
    "  boxes            axis-aligned boxes with shared coordinates, coplanar faces\n"
    "  rotor            blades turning by the exact rational rotation 2 atan(t)\n"
    "\n"
    "options:\n"
    "  --triangles N    uniform families: number of triangles (default 100)\n"
    "  --moving F       fraction of moving triangles or boxes, a number in [0,1]\n"
    "                   such as 1, 0.1 or 1/10 (default 1)\n"
    "  --degree D       uniform families: degree of the random polynomial\n"
    "                   translations (default 1: linear motion)\n"
    "  --boxes N        boxes: number of boxes (default 9)\n"
    "  --blades N       rotor: number of blades (default 3)\n"
    "  --seed S         seed of the generator and of the priority order (default 0)\n"
    "  -o FILE          write to FILE instead of stdout\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or parameters that cannot be met.\n";

}  // namespace

int generate(Args& args) {
  std::optional<std::string> family, output;
  scene::Uniform_params p;
  std::size_t box_count = 9, blades = 3;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << generate_help;
      return 0;
    }
    if (a == "--triangles") p.triangles = args.unsigned_value(a);
    else if (a == "--degree") {
      const std::uint64_t d = args.unsigned_value(a);
      if (d < 1 || d > 16) throw Usage_error("kvd generate: --degree must be between 1 and 16");
      p.degree = static_cast<int>(d);
    } else if (a == "--moving") {
      std::string why;
      const std::string& v = args.value(a);
      const auto q = scene::parse_exact_number(v, why);
      if (!q || *q < 0 || *q > 1) throw Usage_error("kvd generate: --moving expects a number in [0, 1], got '" + v + "'");
      p.moving = *q;
    } else if (a == "--boxes") box_count = args.unsigned_value(a);
    else if (a == "--blades") blades = args.unsigned_value(a);
    else if (a == "--seed") p.seed = args.unsigned_value(a);
    else if (a == "-o") output = args.value(a);
    else if (!a.empty() && a[0] != '-' && !family) family = a;
    else args.unknown(a);
  }
  if (!family) throw Usage_error("kvd generate: missing the FAMILY (see kvd generate --help)");
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
    else if (*family == "rotor") s = scene::rotor(blades, p.seed);
    else throw Usage_error("kvd generate: unknown family '" + *family + "' (see kvd generate --help)");
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
