// kvd import MESH: an OBJ, OFF or ASCII PLY mesh as a kvd-scene/1 scene, read exactly.
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "cli.hpp"
#include "kvd/scene/mesh_io.hpp"
#include "kvd/scene/scene_io.hpp"

namespace kvd::cli {

namespace {
const char* const import_help =
    "usage: kvd import MESH.obj|.off|.ply [-o SCENE.json] [--translate [NAME=]VX,VY,VZ]...\n"
    "                  [--rotate [NAME=]UX,UY,UZ]... [--end T] [--seed S] [--name TEXT]\n"
    "\n"
    "Writes the mesh as a kvd-scene/1 scene (to stdout, or atomically to SCENE).\n"
    "Coordinates are read exactly: every decimal is the rational it spells.\n"
    "OBJ 'o' and 'g' lines start objects (vertices are shared across the file;\n"
    "each object keeps those its faces use); an OFF or ASCII PLY file is one\n"
    "object.\n"
    "Polygons are split into fans from their first corner. The scene is\n"
    "checked as kvd info checks it (triangles of different objects, or folded\n"
    "ones, must not intersect) before anything is written.\n"
    "\n"
    "options:\n"
    "  --translate V         every object moves with constant velocity V;\n"
    "                        NAME=V moves the object of that name only\n"
    "  --rotate U            every object turns about the axis U through its\n"
    "                        centroid, by the exact rational rotation of angle\n"
    "                        2 atan(t |U|) (degree 2); NAME=U for one object\n"
    "  --end T               the scene's time span is [0, T] (default: no end)\n"
    "  --seed S              the priority seed (default 0)\n"
    "  --name TEXT           the scene's name (default: the mesh file's name)\n"
    "  -o FILE               write to FILE instead of stdout\n"
    "\n"
    "Exit status: 0 on success, 2 on a malformed mesh (the message names the\n"
    "line), intersecting triangles or bad usage.\n";

// "NAME=X,Y,Z" or "X,Y,Z": the object's name (empty: every object) and the vector.
std::pair<std::string, std::array<mpq_class, 3>> targeted(const std::string& flag, const std::string& text) {
  const std::size_t eq = text.find('=');
  const std::string name = eq == std::string::npos ? "" : text.substr(0, eq);
  return {name, point_option("import", flag, eq == std::string::npos ? text : text.substr(eq + 1))};
}

}  // namespace

int import(Args& args) {
  std::optional<std::string> mesh, output, name;
  std::vector<std::pair<std::string, std::array<mpq_class, 3>>> translations, rotations;
  std::optional<mpq_class> end;
  std::uint64_t seed = 0;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << import_help;
      return 0;
    }
    if (a == "-o") output = args.value(a);
    else if (a == "--translate") translations.push_back(targeted(a, args.value(a)));
    else if (a == "--rotate") rotations.push_back(targeted(a, args.value(a)));
    else if (a == "--end") end = exact_option("import", a, args.value(a));
    else if (a == "--seed") seed = args.unsigned_value(a);
    else if (a == "--name") name = args.value(a);
    else if (!a.empty() && a[0] != '-' && !mesh) mesh = a;
    else args.unknown(a);
  }
  if (!mesh) throw Usage_error("kvd import: missing the MESH file (see kvd import --help)");
  if (end && *end <= 0) throw Usage_error("kvd import: --end must be positive");
  scene::Scene s = scene::mesh_scene(scene::read_mesh(scene::read_input(*mesh), *mesh),
                                     name.value_or(std::filesystem::path(*mesh).filename().string()));
  s.end = end;
  s.priority_spec.seed = seed;
  // Each motion goes to the objects it names; an object gets one motion.
  std::map<std::size_t, std::string> moved;
  const auto apply = [&](const std::string& flag, const std::string& target, const auto& make) {
    bool found = false;
    for (std::size_t o = 0; o < s.objects.size(); ++o) {
      if (!target.empty() && s.objects[o].name != target) continue;
      found = true;
      if (!moved.emplace(o, flag).second)
        throw Usage_error("kvd import: object " + std::to_string(o) + " gets both " + moved[o] + " and " + flag);
      s.objects[o].motion = make(o);
    }
    if (!found) throw Usage_error("kvd import: " + flag + " names no object \"" + target + "\"");
  };
  for (const auto& t : translations)
    apply("--translate", t.first, [&](std::size_t) {
      scene::Motion m;
      m.kind = scene::Motion::Kind::translation;
      for (std::size_t a = 0; a < 3; ++a) m.translation[a] = scene::QPoly({scene::Q(0), t.second[a]});
      return m;
    });
  for (const auto& r : rotations)
    apply("--rotate", r.first, [&](std::size_t o) { return scene::rotation_about_centroid(s, o, r.second); });
  s.derive();
  // The loader's checks, intersections among them, on exactly what is written.
  const std::string text = scene::write_scene(s);
  scene::read_scene(text, *mesh);
  if (output) write_atomically("import", *output, text);
  else std::cout << text;
  return 0;
}

}  // namespace kvd::cli
