// kvd animate SCENE --view X,Y,Z --out FILE.svg|.mp4|.gif: a run as a film.
#include <algorithm>
#include <array>
#include <iostream>

#include "animation.hpp"
#include "cli.hpp"

namespace kvd::cli {

namespace {
const char* const animate_help =
    "usage: kvd animate SCENE --out FILE.svg|FILE.mp4|FILE.gif [--view X,Y,Z]\n"
    "                   [--events N] [--until T] [--fps N] [--frames N] [--hold N]\n"
    "                   [--cells] [--size PX] [--seed S] [--collisions reverse|stop]\n"
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
    "\n"
    "FILE.svg is one SVG showing the frames in turn (SMIL, looping; a browser\n"
    "plays it). FILE.mp4 (H.264) and FILE.gif are encoded by ffmpeg (Debian's\n"
    "ffmpeg) from PNG frames drawn with cairo. FILE is written completely or not\n"
    "at all. Exit status: 0 on success, 1 on a failed validation, 2 on bad input\n"
    "(or no ffmpeg for a video).\n";

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
  while (!args.done()) {
    const std::string& arg = args.next();
    if (arg == "--help" || arg == "-h") {
      std::cout << animate_help;
      return 0;
    }
    if (arg == "--events") o.max_events = args.unsigned_value(arg);
    else if (arg == "--until") o.until = exact_option("animate", arg, args.value(arg));
    else if (arg == "--out") out = args.value(arg);
    else if (arg == "--collisions") o.collisions = collisions_option("animate", args.value(arg));
    else if (arg == "--fps") a.fps = bounded(args, arg, 1, 120);
    else if (arg == "--frames") a.sampled = bounded(args, arg, 0, 100000);
    else if (arg == "--hold") a.hold = bounded(args, arg, 1, 1000);
    else if (arg == "--size") a.render.size = bounded(args, arg, 16, 8000);
    else if (arg == "--cells") a.render.cells = true;
    else if (arg == "--json" || !sa.take(args, arg)) args.unknown(arg);
  }
  if (!out) throw Usage_error("kvd animate: missing --out FILE.svg|FILE.mp4|FILE.gif (see kvd animate --help)");
  const bool svg = ends_with(*out, ".svg");
  if (!svg && !ends_with(*out, ".mp4") && !ends_with(*out, ".gif"))
    throw Usage_error("kvd animate: --out must name an .svg, .mp4 or .gif file");
  if (!svg && !query::png_supported())
    throw Usage_error("kvd animate: this build has no PNG frames (cairo was not found when it was built); use .svg");
  const scene::Scene s = sa.load_scene("animate");
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
  std::cout << "kvd animate: " << run.sim.batches.size() << " batches, " << run.sim.failures << " events, "
            << frames.size() << " pictures in " << shown << " frames (" << static_cast<double>(shown) / a.fps
            << " s at " << a.fps << " fps); wrote " << *out << "\n";
  return 0;
}

}  // namespace kvd::cli
