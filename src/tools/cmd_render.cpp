// kvd render SCENE --view X,Y,Z: a picture of the decomposition; of the
// cylindrical BSP for a segment scene.
#include <iostream>
#include <optional>

#include "cli.hpp"
#include "segment_commands.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/query/render.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/segments/segment_io.hpp"
#include "kvd/segments/segment_svg.hpp"
#include "kvd/tree/build.hpp"

namespace kvd::cli {

namespace {
const char* const render_help =
    "usage: kvd render SCENE --view X,Y,Z [--time T] [--seed S] [--cells] [--size PX] [--out FILE.svg|FILE.png]\n"
    "                  [--allow-intersecting]\n"
    "       kvd render SEGMENTS [--time T] [--seed S] [--size PX] [--out FILE.svg]\n"
    "\n"
    "Builds the KVD just after time T (default: the scene's start) with the\n"
    "exact kernel and paints its triangle fragments back to front as seen from\n"
    "(X, Y, Z), looking at the scene's centre with z up, each object in its own\n"
    "colour. Writes SVG or PNG (by FILE's extension) to FILE, atomically, or\n"
    "SVG to standard output.\n"
    "\n"
    "  --cells     outline every fragment side by the cut that made it:\n"
    "              P-cuts red, E-cuts green, the triangle's own edges blue\n"
    "  --size PX   picture size in pixels (default 800)\n"
    "  --allow-intersecting\n"
    "              accept triangles that intersect at the start time\n"
    "  -o FILE     the same as --out FILE\n"
    "\n"
    "For a kvd-segments/1 scene (told apart by its \"format\"), draws the\n"
    "cylindrical BSP of its segments just after time T (exact; default: the\n"
    "scene's start; it must lie in the scene's span) in the plane, y up, as\n"
    "SVG only: each cut clipped to its cell, vertex cuts blue dashed,\n"
    "intersection cuts orange dashed, edge cuts black, endpoints as dots,\n"
    "crossings as crosses, leaves' cells in pale colours, with a legend\n"
    "counting the cuts and a caption with the scene's name, T, the number of\n"
    "nodes and the height. --size is the picture's width; --view and --cells\n"
    "are for triangle scenes.\n"
    "\n"
    "Exit status: 0 on success, 2 on a bad scene or bad usage.\n";

// The cylindrical BSP of a segment scene, as SVG.
int render_segments(const Scene_args& sa, const std::string& text, const std::optional<std::string>& out, int size) {
  if (out && !ends_with(*out, ".svg"))
    throw Usage_error("kvd render: a segment scene is drawn as SVG only: --out must name an .svg file");
  const segments::Segment_scene s = sa.read_segments("render", text);
  require_finite_in<double>(*sa.path, s, drawn_in_double);
  const mpq_class t = sa.time ? *sa.time : s.start;
  const Exact_kernel k;
  const segments::Segment_predicates<Exact_kernel> pred(k, s);
  const std::string svg =
      segments::segment_svg(s, segments::build_cylindrical_bsp(pred, Exact_time(t)), t, {size, {}, {}, {}});
  if (out) write_atomically("render", *out, svg);
  else std::cout << svg;
  return 0;
}

}  // namespace

int render(Args& args) {
  Scene_args sa;
  sa.wants_time = sa.wants_view = true;
  std::optional<std::string> out;
  std::vector<std::string> triangle_only;
  query::Render_options o;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << render_help;
      return 0;
    }
    if (a == "--cells" || a == "--view") triangle_only.push_back(a);
    if (a == "--cells") o.cells = true;
    else if (a == "--out" || a == "-o") out = args.value(a);
    else if (a == "--size") {
      const std::uint64_t px = args.unsigned_value(a);
      if (px < 16 || px > 20000) throw Usage_error("kvd render: --size must be between 16 and 20000");
      o.size = static_cast<int>(px);
    } else if (!sa.take(args, a)) args.unknown(a);
  }
  const std::string text = sa.read_text("render");
  if (segments::scene_format(text) == "kvd-segments/1") {
    if (sa.load.allow_intersecting) triangle_only.push_back("--allow-intersecting");
    refuse_triangle_flags("render", triangle_only);
    return render_segments(sa, text, out, o.size);
  }
  const scene::Scene s = sa.read_scene("render", text);
  require_finite_in<double>(*sa.path, s, drawn_in_double);
  const auto& view = sa.required_view("render");
  const bool png = out && ends_with(*out, ".png");
  if (out && !png && !ends_with(*out, ".svg")) throw Usage_error("kvd render: --out must name an .svg or .png file");
  if (png && !query::png_supported())
    throw Usage_error("kvd render: this build has no PNG output (cairo was not found when it was built); use .svg");
  const mpq_class t = sa.time ? *sa.time : s.start;
  const Exact_kernel k;
  const predicates::Classifier<Exact_kernel> c(k, s);
  const tree::Kvd_tree tr = build_tree("render", *sa.path, c, Exact_time(t));
  const auto picture = query::paint(c, tr, {{view[0], view[1], view[2], mpq_class(1)}}, t, o);
  if (out) write_atomically("render", *out, png ? query::to_png(picture, o) : query::to_svg(picture, o));
  else std::cout << query::to_svg(picture, o);
  return 0;
}

}  // namespace kvd::cli
