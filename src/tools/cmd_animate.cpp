// kvd animate SCENE --view X,Y,Z --out FILE.svg|.mp4|.gif: a run as a film;
// of the cylindrical BSP for a segment scene.
#include <algorithm>
#include <array>
#include <iostream>

#include "animation.hpp"
#include "cli.hpp"
#include "kvd/segments/segment_io.hpp"
#include "kvd/segments/segment_svg.hpp"
#include "segment_animation.hpp"
#include "segment_commands.hpp"

namespace kvd::cli {

namespace {
const char* const animate_help =
    "usage: kvd animate SCENE --out FILE.svg|FILE.mp4|FILE.gif [--view X,Y,Z]\n"
    "                   [--events N] [--until T] [--fps N] [--frames N] [--hold N]\n"
    "                   [--cells] [--size PX] [--seed S] [--collisions reverse|stop]\n"
    "                   [--allow-intersecting]\n"
    "\n"
    "Runs the exact kinetic KVD (as kvd simulate, validating every batch) and\n"
    "films it from (X, Y, Z) (default: in front, to the left and above, at\n"
    "three times the scene's size), looking at the scene's centre at the start\n"
    "with z up: every frame paints the triangle fragments back to front with the tree\n"
    "in force at its instant. Frames are sampled evenly over the run, and just\n"
    "after every batch a frame is held with the failing certificates' features\n"
    "marked in red and named, so that every event of the run appears. The\n"
    "camera stays still; the caption gives the time.\n"
    "\n"
    "  --events N   stop after the batch holding the N-th failure (default 100)\n"
    "  --until T    stop after the last batch at a time <= T (exact)\n"
    "  --fps N      frames per second (default 10)\n"
    "  --frames N   frames sampled evenly over the run (default 80)\n"
    "  --hold N     frames each batch is held for (default 5)\n"
    "  --cells      outline fragment sides by the cut that made them: P red,\n"
    "               E green, the triangle's own edges blue\n"
    "  --size PX    picture size in pixels (default 640)\n"
    "  --allow-intersecting\n"
    "               accept triangles that intersect at the start time\n"
    "  -o FILE      the same as --out FILE\n"
    "\n"
    "FILE.svg is one SVG showing the frames in turn (SMIL, looping; a browser\n"
    "plays it). FILE.mp4 (H.264) and FILE.gif are encoded by ffmpeg (Debian's\n"
    "ffmpeg) from PNG frames drawn with cairo. FILE is written completely or not\n"
    "at all. Exit status: 0 on success, 1 on a failed validation, 2 on bad input\n"
    "(or no ffmpeg for a video).\n"
    "\n"
    "For a kvd-segments/1 scene (told apart by its \"format\"): runs the exact\n"
    "kinetic cylindrical BSP (not validated) over the scene's span, or to\n"
    "--until, and films it in the plane as kvd render draws it: frames sampled\n"
    "evenly, and one held just after every batch, captioned with the batch's\n"
    "event kinds (vertex event, edge event, intersection event, flip). Each\n"
    "frame draws the tree built afresh at its rational instant, all in one\n"
    "view box. FILE.svg only; --size is the width; --view, --cells and\n"
    "--collisions are for triangle scenes.\n";

// In front of the scene at its start, to the left and above: its centre
// plus (-2, -3, 2) times the largest extent of its vertices (exact).
std::array<mpq_class, 3> default_view(const scene::Scene& s) {
  std::array<mpq_class, 3> lo, hi;
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const auto p = s.position_at(v, s.start);
    for (int j = 0; j < 3; ++j) {
      const mpq_class x = p[j] / p[3];
      const auto i = static_cast<std::size_t>(j);
      if (v == 0 || x < lo[i]) lo[i] = x;
      if (v == 0 || x > hi[i]) hi[i] = x;
    }
  }
  mpq_class extent = 1;
  for (std::size_t j = 0; j < 3; ++j) extent = std::max(extent, mpq_class(hi[j] - lo[j]));
  const std::array<int, 3> away{-2, -3, 2};
  std::array<mpq_class, 3> eye;
  for (std::size_t j = 0; j < 3; ++j) eye[j] = (lo[j] + hi[j]) / 2 + away[j] * extent;
  return eye;
}

void print_summary(std::size_t batches, std::size_t failures, std::size_t pictures, std::size_t shown, int fps,
                   const std::string& out) {
  std::cout << "kvd animate: " << batches << " batches, " << failures << " events, " << pictures << " pictures in "
            << shown << " frames (" << static_cast<double>(shown) / fps << " s at " << fps << " fps); wrote " << out
            << "\n";
}

// The film of a segment scene's cylindrical BSP, as SMIL SVG.
int animate_segments(const Scene_args& sa, const std::string& text, const std::string& out, const kinetic::Options& o,
                     const view::Animation_options& a) {
  if (!ends_with(out, ".svg"))
    throw Usage_error("kvd animate: a segment scene is filmed as SVG only: --out must name an .svg file");
  const segments::Segment_scene s = sa.read_segments("animate", text);
  require_finite_in<double>(*sa.path, s, drawn_in_double);
  if (o.until) require_in_span("animate", "--until", *o.until, s.start, s.end);
  const view::Segment_film film =
      view::segment_film(s, {o.until, o.max_events, a.sampled, a.hold, a.render.size},
                         progress_every_few_seconds("kvd animate"),
                         progress_every_few_seconds("kvd animate", "frames drawn"));
  write_atomically("animate", out,
                   view::smil_svg(film.frames, film.width, film.height, a.fps, segments::segment_svg_style()));
  std::size_t shown = 0;
  for (const auto& f : film.frames) shown += static_cast<std::size_t>(f.repeat);
  print_summary(film.batches, film.failures, film.frames.size(), shown, a.fps, out);
  return 0;
}

int bounded(Args& args, const std::string& flag, std::uint64_t lo, std::uint64_t hi) {
  const std::uint64_t n = args.unsigned_value(flag);
  if (n < lo || n > hi)
    throw Usage_error("kvd animate: " + flag + " must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return static_cast<int>(n);
}
}  // namespace

int animate(Args& args) {
  Scene_args sa;
  sa.wants_view = true;
  kinetic::Options o;
  view::Animation_options a;
  a.render.size = 640;
  std::optional<std::string> out;
  std::vector<std::string> triangle_only;
  while (!args.done()) {
    const std::string& arg = args.next();
    if (arg == "--help" || arg == "-h") {
      std::cout << animate_help;
      return 0;
    }
    if (arg == "--view" || arg == "--cells" || arg == "--collisions") triangle_only.push_back(arg);
    if (arg == "--events") o.max_events = args.unsigned_value(arg);
    else if (arg == "--until") o.until = exact_option("animate", arg, args.value(arg));
    else if (arg == "--out" || arg == "-o") out = args.value(arg);
    else if (arg == "--collisions") o.collisions = collisions_option("animate", args.value(arg));
    else if (arg == "--fps") a.fps = bounded(args, arg, 1, 120);
    else if (arg == "--frames") a.sampled = bounded(args, arg, 0, 100000);
    else if (arg == "--hold") a.hold = bounded(args, arg, 1, 1000);
    else if (arg == "--size") a.render.size = bounded(args, arg, 16, 8000);
    else if (arg == "--cells") a.render.cells = true;
    else if (arg == "--json" || !sa.take(args, arg)) args.unknown(arg);
  }
  if (!out) throw Usage_error("kvd animate: missing --out FILE.svg|FILE.mp4|FILE.gif (see kvd animate --help)");
  const std::string text = sa.read_text("animate");
  if (segments::scene_format(text) == "kvd-segments/1") {
    if (sa.load.allow_intersecting) triangle_only.push_back("--allow-intersecting");
    refuse_triangle_flags("animate", triangle_only);
    return animate_segments(sa, text, *out, o, a);
  }
  const bool svg = ends_with(*out, ".svg");
  if (!svg && !ends_with(*out, ".mp4") && !ends_with(*out, ".gif"))
    throw Usage_error("kvd animate: --out must name an .svg, .mp4 or .gif file");
  if (!svg && !query::png_supported())
    throw Usage_error("kvd animate: this build has no PNG frames (cairo was not found when it was built); use .svg");
  const scene::Scene s = sa.read_scene("animate", text);
  require_finite_in<double>(*sa.path, s, drawn_in_double);
  a.view = sa.view ? *sa.view : default_view(s);
  if (o.until) require_in_span("animate", "--until", *o.until, s);
  o.progress = progress_every_few_seconds("kvd animate");
  const view::Recorded_run run = with_disjoint_triangles("animate", *sa.path, [&] { return view::record_run(s, o); });
  if (!run.sim.valid()) {
    std::cerr << "kvd animate: validation failed: " << run.sim.failure << "\n";
    return 1;
  }
  const auto frames = view::animation_frames(run, a, progress_every_few_seconds("kvd animate", "frames drawn"));
  std::string bytes;
  try {
    bytes = svg ? view::animated_svg(frames, a)
                : view::encoded_video(frames, a, ends_with(*out, ".gif") ? view::Video::gif : view::Video::mp4);
  } catch (const std::runtime_error& e) {
    throw Usage_error("kvd animate: " + std::string(e.what()));
  }
  write_atomically("animate", *out, bytes);
  std::size_t shown = 0;
  for (const auto& f : frames) shown += static_cast<std::size_t>(f.repeat);
  print_summary(run.sim.batches.size(), run.sim.failures, frames.size(), shown, a.fps, *out);
  return 0;
}

}  // namespace kvd::cli
