#include "animation.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace kvd::view {

namespace {

using D2 = query::Camera::D2;

struct Planned {
  mpq_class time;
  std::optional<std::size_t> batch;
};

// Sampled instants over [start, end] and one just after each batch, in time
// order. `end` is the limit when the run went on to it, else its last batch;
// with no batch, the start when the run stopped for its events, or a second
// on when it ran out of them with no limit.
std::vector<Planned> plan(const Recorded_run& run, int sampled) {
  const auto& batches = run.sim.batches;
  const mpq_class start = run.scene.start;
  const auto spans = intervals(run);
  const bool for_events = run.sim.stopped == kinetic::Stop::events;
  mpq_class end = for_events ? start : start + 1;
  if (!for_events && run.sim.limit) end = *run.sim.limit;
  else if (!batches.empty()) end = batches.back().time.is_rational() ? batches.back().time.rational() : batches.back().time.lower();
  std::vector<Planned> out;
  for (int i = 0; i < sampled && end > start; ++i) out.push_back({start + (end - start) * (2 * i + 1) / (2 * sampled), {}});
  const mpq_class within = (end > start ? end - start : mpq_class(1)) / 1000;
  for (std::size_t k = 0; k < batches.size(); ++k) {
    const Interval& after = spans[k + 1];
    out.push_back({drawn_after(after.from, after.to, run.sim.limit, within), k});
  }
  if (out.empty()) out.push_back({start, {}});
  std::stable_sort(out.begin(), out.end(), [](const Planned& a, const Planned& b) { return a.time < b.time; });
  return out;
}

std::string approx(double t, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, t);
  return buf;
}

std::vector<std::string> caption(const Recorded_run& run, const Planned& p) {
  if (!p.batch) return {"t ≈ " + approx(p.time.get_d(), 6)};
  const auto& b = run.sim.batches[*p.batch];
  std::string exact = "t = " + b.time.to_string();
  if (exact.size() > 90) exact = exact.substr(0, 87) + "...";
  std::vector<std::string> lines{"batch " + std::to_string(*p.batch + 1) + " of " +
                                     std::to_string(run.sim.batches.size()) + ", t ≈ " + approx(b.time.to_double(), 10),
                                 exact};
  const auto& failing = run.failing[*p.batch];
  for (std::size_t i = 0; i < failing.size() && i < 6; ++i)
    lines.push_back(std::string(kinetic::to_string(failing[i].type)) + " " + failing[i].features);
  if (failing.size() > 6) lines.push_back("... and " + std::to_string(failing.size() - 6) + " more");
  return lines;
}

// The features' marks, projected unframed; points behind the eye dropped.
query::Overlay marks(const Recorded_run& run, const Planned& p, const Instant& in, const query::Camera& camera) {
  query::Overlay o;
  o.caption = caption(run, p);
  if (!p.batch) return o;
  const auto line = [&](auto const& ends) {
    std::vector<D2> out;
    for (const auto& e : ends)
      if (const auto q = camera.project(e)) out.push_back(*q);
    return out;
  };
  for (const auto& f : run.failing[*p.batch]) {
    const Feature_shapes s = feature_shapes(f, in);
    for (const auto& point : s.points)
      if (const auto q = camera.project(point)) o.points.push_back(*q);
    for (const auto& e : s.segments) o.outlines.push_back(line(e));
    for (const auto& t : s.triangles) o.outlines.push_back(line(t));
  }
  return o;
}

// Removes a folder and what it holds when it goes out of scope.
struct Temporary_folder {
  std::filesystem::path path;
  Temporary_folder() {
    std::string templ = (std::filesystem::temp_directory_path() / "kvd-animate-XXXXXX").string();
    if (!mkdtemp(templ.data())) throw std::runtime_error("cannot make a temporary folder for the frames");
    path = templ;
  }
  ~Temporary_folder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

// Runs a program with its arguments (no shell); its exit status.
int run_program(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cannot start " + argv[0]);
  if (pid == 0) {
    execvp(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) throw std::runtime_error("lost " + argv[0]);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

}  // namespace

mpq_class just_after(const Exact_time& a, const Exact_time& b, const mpq_class& within) {
  while (!a.is_rational() && a.upper() - a.lower() > within / 2) a.refine();
  const mpq_class t = (a.is_rational() ? a.rational() : a.upper()) + within / 2;
  return Exact_kernel().compare(Exact_time(t), b) < 0 ? t : kinetic::rational_between(a, b);
}

mpq_class drawn_after(const Exact_time& a, const std::optional<Exact_time>& b, const std::optional<mpq_class>& end,
                      const mpq_class& within) {
  const Exact_kernel k;
  if (end && k.compare(a, Exact_time(*end)) >= 0) return *end;
  if (end && (!b || k.compare(*b, Exact_time(*end)) > 0)) return just_after(a, Exact_time(*end), within);
  return just_after(a, b ? *b : Exact_time(a.upper() + within), within);
}

std::vector<Animation_frame> animation_frames(const Recorded_run& run, const Animation_options& o,
                                              const std::function<void(std::size_t, std::size_t)>& progress) {
  query::Camera camera({o.view[0].get_d(), o.view[1].get_d(), o.view[2].get_d()},
                      query::centroid(run.scene, run.scene.start), o.render.size);
  const Point4<mpq_class> eye{{o.view[0], o.view[1], o.view[2], mpq_class(1)}};
  const auto planned = plan(run, o.sampled);
  std::vector<Animation_frame> frames;
  D2 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()}, hi{-lo[0], -lo[1]};
  for (const Planned& p : planned) {
    const Instant in(run, p.time);
    Animation_frame f{p.time, p.batch, query::paint(in.classifier(), in.tree(), eye, camera, p.time, o.render),
                      marks(run, p, in, camera), p.batch ? o.hold : 1};
    // The frame holds every vertex of a triangle that is in front of the eye.
    for (const auto& tri : in.scene().triangles)
      for (std::size_t v : tri)
        if (const auto q = camera.project(in.position(symbolic::Symbolic_vertex::endpoint(v)))) {
          lo = {std::min(lo[0], (*q)[0]), std::min(lo[1], (*q)[1])};
          hi = {std::max(hi[0], (*q)[0]), std::max(hi[1], (*q)[1])};
        }
    frames.push_back(std::move(f));
    if (progress) progress(frames.size(), planned.size());
  }
  camera.frame(lo, hi);
  for (auto& f : frames) {
    for (auto& poly : f.picture)
      for (auto& q : poly.points) q = camera.to_image(q);
    for (auto& q : f.overlay.points) q = camera.to_image(q);
    for (auto& line : f.overlay.outlines)
      for (auto& q : line) q = camera.to_image(q);
  }
  return frames;
}

std::string smil_svg(const std::vector<Smil_frame>& frames, int width, int height, int fps,
                     const std::string& head) {
  std::size_t total = 0;
  for (const auto& f : frames) total += static_cast<std::size_t>(f.repeat);
  const double seconds = static_cast<double>(total) / fps;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << width << " " << height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" << head;
  std::size_t at = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const double from = static_cast<double>(at) / static_cast<double>(total);
    at += static_cast<std::size_t>(frames[i].repeat);
    const double to = static_cast<double>(at) / static_cast<double>(total);
    char timing[200];
    // Shown on [from, to) of each loop; a viewer without SMIL shows the first frame.
    if (i == 0)
      std::snprintf(timing, sizeof timing, "values=\"inline;none\" keyTimes=\"0;%.6f\"", to);
    else if (i + 1 == frames.size())
      std::snprintf(timing, sizeof timing, "values=\"none;inline\" keyTimes=\"0;%.6f\"", from);
    else
      std::snprintf(timing, sizeof timing, "values=\"none;inline;none\" keyTimes=\"0;%.6f;%.6f\"", from, to);
    svg << "<g class=\"frame\" display=\"" << (i == 0 ? "inline" : "none") << "\"" << (frames[i].batch ? " data-batch=\"" + std::to_string(*frames[i].batch) + "\"" : "")
        << ">\n<animate attributeName=\"display\" " << timing << " dur=\"" << seconds
        << "s\" calcMode=\"discrete\" repeatCount=\"indefinite\"/>\n"
        << frames[i].elements << "</g>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string animated_svg(const std::vector<Animation_frame>& frames, const Animation_options& o) {
  std::vector<Smil_frame> smil;
  for (const auto& f : frames) smil.push_back({query::svg_elements(f.picture, o.render, f.overlay), f.repeat, f.batch});
  return smil_svg(smil, o.render.size, o.render.size, o.fps);
}

std::string encoded_video(const std::vector<Animation_frame>& frames, const Animation_options& o, Video kind) {
  const bool gif = kind == Video::gif;
  Temporary_folder folder;
  std::size_t n = 0;
  for (const auto& f : frames) {
    const std::string png = query::to_png(f.picture, o.render, f.overlay);
    for (int r = 0; r < f.repeat; ++r) {
      char name[32];
      std::snprintf(name, sizeof name, "frame%06zu.png", n++);
      std::ofstream(folder.path / name, std::ios::binary) << png;
    }
  }
  const std::string out = (folder.path / (gif ? "out.gif" : "out.mp4")).string();
  std::vector<std::string> argv{"ffmpeg", "-nostdin", "-loglevel", "error", "-y", "-framerate", std::to_string(o.fps),
                                "-i", (folder.path / "frame%06d.png").string()};
  if (gif) argv.insert(argv.end(), {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse"});
  else argv.insert(argv.end(), {"-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-pix_fmt", "yuv420p", "-c:v", "libx264"});
  argv.push_back(out);
  const int status = run_program(argv);
  if (status == 127) throw std::runtime_error("ffmpeg was not found (Debian's package ffmpeg); write .svg instead");
  if (status != 0) throw std::runtime_error("ffmpeg failed with status " + std::to_string(status));
  std::ifstream in(out, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace kvd::view
