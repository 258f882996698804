// kvd view SCENE|REPORT --out FILE.html: an interactive page of a run.
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "kvd/segments/segment_io.hpp"
#include "page_data.hpp"
#include "segment_commands.hpp"
#include "segment_page.hpp"

namespace kvd::cli {

namespace {
const char* const view_help =
    "usage: kvd view SCENE|REPORT --out FILE.html [--events N] [--until T]\n"
    "                [--view X,Y,Z] [--seed S] [--collisions reverse|stop]\n"
    "                [--allow-intersecting]\n"
    "       kvd view TRACE --scene SCENE --out FILE.html [--seed S] [...]\n"
    "\n"
    "Runs the exact kinetic KVD (as kvd simulate, validating every batch) and\n"
    "writes one self-contained HTML page, which works offline:\n"
    "  * the triangles in 3D (drag to orbit, wheel to zoom), cut into the\n"
    "    fragments of the tree in force, with the cells' walls shown or hidden\n"
    "    by kind (P red, E green, T blue);\n"
    "  * a timeline of the batches and motion changes: clicking one shows the\n"
    "    tree just after it, its exact time, the failing certificates with\n"
    "    their features marked in red, and the nodes it changed;\n"
    "  * the tree itself as a collapsible outline.\n"
    "Each interval of the run is drawn at a rational instant inside it, never\n"
    "past the time limit (a batch at the limit is drawn there).\n"
    "\n"
    "REPORT is the output of kvd diff --json: the page then also lists the exact\n"
    "and the floating-point events side by side, with the first divergence\n"
    "marked. The run is the report's scene (its path as written there, from the\n"
    "current folder or else from the report's) over the report's exact events.\n"
    "TRACE is the output of kvd simulate --trace (exact kernel) of SCENE: the page\n"
    "shows its batches. The run must list the same events as the report or the\n"
    "trace, in the same order at the same exact times (exit 2 if not).\n"
    "\n"
    "  --events N      stop after the batch holding the N-th failure (default 100)\n"
    "  --until T       stop after the last batch at a time <= T (exact)\n"
    "  --view X,Y,Z    the camera's first position (default: in front, above)\n"
    "  --allow-intersecting\n"
    "                  accept triangles that intersect at the start time\n"
    "\n"
    "For a kvd-segments/1 scene (told apart by its \"format\"): runs the exact\n"
    "kinetic cylindrical BSP (seed 003, as kvd simulate) and writes a page of\n"
    "its pictures: for each interval of the run (before the first batch, then\n"
    "after each) the cells and cuts of the tree in force, drawn at a rational\n"
    "instant inside it (at the limit for a batch there) with the segments the batch's failing certificates name\n"
    "marked in red; the timeline (arrow keys step through it), each batch's\n"
    "exact time, events and failing certificates, and the tree as an outline.\n"
    "Every tree shown is compared with a fresh build at its instant (exit 1,\n"
    "nothing written, if one differs). Takes --events, --until and --seed.\n"
    "\n"
    "The triangle page holds three.js (MIT licence, Debian's libjs-three) and\n"
    "the data.\n"
    "FILE is written completely or not at all. Exit status: 0 on success, 1 on a\n"
    "failed validation (nothing written), 2 on bad input.\n";

// An event as a report or a trace lists it, with its place there.
struct Listed_event {
  std::string place, time, certificate, nodes;
};

// The fields kvd view reads from a report or a trace, each checked for its
// type: a field of another type is a Usage_error naming the file, the place
// (a line of a trace) and the field, never a JSON exception.
class Checked_fields {
public:
  // `prefix` starts every message: "kvd view: FILE: a kvd diff report".
  explicit Checked_fields(std::string prefix) : prefix_(std::move(prefix)) {}

  // Usage_error unless `ok`: `field` (a JSON pointer, or a key in quotes)
  // holds `value`, which is not `expected`.
  void require(bool ok, const std::string& field, const nlohmann::json& value, const char* expected) const {
    if (!ok)
      throw Usage_error(prefix_ + " with a field of the wrong type: " + field + " is " + a(value) + ", not " + expected);
  }
  // The string at `key` of the object j ("" when it is missing: the event
  // then is not the run's, which the comparison names).
  std::string string(const nlohmann::json& j, const std::string& field, const char* key) const {
    const auto it = j.find(key);
    if (it == j.end()) return "";
    require(it->is_string(), field, *it, "a string");
    return it->get<std::string>();
  }

private:
  static std::string a(const nlohmann::json& value) {
    switch (value.type()) {
      case nlohmann::json::value_t::null: return "null";
      case nlohmann::json::value_t::boolean: return "a boolean";
      case nlohmann::json::value_t::string: return "a string";
      case nlohmann::json::value_t::array: return "an array";
      case nlohmann::json::value_t::object: return "an object";
      default: return "a number";
    }
  }
  std::string prefix_;
};

// A kvd diff --json report, or nothing when `text` holds something else.
std::optional<nlohmann::json> diff_report(const std::string& path, const std::string& text) {
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("first_divergence_event")) return std::nullopt;
  for (const char* key : {"scene", "kernel", "events", "spurious", "events_compared"})
    if (!j.contains(key)) throw Usage_error("kvd view: " + path + ": a kvd diff report without \"" + key + "\"");
  const Checked_fields report("kvd view: " + path + ": a kvd diff report");
  report.require(j["scene"].is_string(), "/scene", j["scene"], "a string");
  report.require(j["kernel"].is_string(), "/kernel", j["kernel"], "a string");
  report.require(j["events"].is_array(), "/events", j["events"], "an array");
  report.require(j["spurious"].is_array(), "/spurious", j["spurious"], "an array");
  report.require(j["events_compared"].is_number_unsigned(), "/events_compared", j["events_compared"],
                 "a count");
  const auto& first = j["first_divergence_event"];
  report.require(first.is_null() || first.is_number_unsigned(), "/first_divergence_event", first, "an event or null");
  return j;
}

// The events of a report from diff_report.
std::vector<Listed_event> report_events(const std::string& path, const nlohmann::json& j) {
  const Checked_fields report("kvd view: " + path + ": a kvd diff report");
  std::vector<Listed_event> out;
  for (std::size_t i = 0; i < j["events"].size(); ++i) {
    const std::string place = "/events/" + std::to_string(i);
    const auto& e = j["events"][i];
    report.require(e.is_object(), place, e, "an object");
    out.push_back({place, report.string(e, place + "/exact_time", "exact_time"),
                   report.string(e, place + "/certificate", "certificate"), report.string(e, place + "/nodes", "nodes")});
  }
  return out;
}

// The failures of a kvd simulate --trace file (JSON lines), or nothing when
// `text` is not one.
std::optional<std::vector<Listed_event>> trace_events(const std::string& path, const std::string& text) {
  std::vector<Listed_event> out;
  std::size_t line_number = 0, start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (line.empty()) continue;
    const auto j = nlohmann::json::parse(line, nullptr, false);
    const bool traced = j.is_object() && (j.contains("batch") || j.contains("motion_change"));
    const std::string place = "line " + std::to_string(line_number);
    if (!traced) {
      if (line_number == 1) return std::nullopt;
      throw Usage_error("kvd view: " + path + ": " + place + " is not a trace line");
    }
    if (j.contains("batch")) {
      const Checked_fields fields("kvd view: " + path + ": " + place + ": a trace line");
      out.push_back({place, fields.string(j, "\"time\"", "time"), fields.string(j, "\"certificate\"", "certificate"),
                     fields.string(j, "\"nodes\"", "nodes")});
    }
  }
  return out;
}

// The report's scene: its path from here, or else from the report's folder.
std::string report_scene(const std::string& report, const nlohmann::json& j) {
  const std::filesystem::path scene = j["scene"].get<std::string>();
  if (scene.is_absolute() || std::filesystem::exists(scene)) return scene.string();
  return (std::filesystem::path(report).parent_path() / scene).string();
}

// Usage_error unless the listed events are the exact run's, in order.
void require_same_events(const std::string& path, const std::vector<Listed_event>& listed, const view::Recorded_run& run) {
  std::size_t i = 0;
  for (std::size_t b = 0; b < run.failing.size(); ++b)
    for (const auto& f : run.failing[b]) {
      const std::string time = run.sim.batches[b].time.to_string();
      const std::string type = kinetic::to_string(f.type);
      if (i >= listed.size() || listed[i].time != time || listed[i].certificate != type || listed[i].nodes != f.features)
        throw Usage_error("kvd view: " + path + ": " + (i < listed.size() ? listed[i].place : "the end") +
                          ": not the exact run's event " + std::to_string(i) + " (" + type + " " + f.features +
                          " at " + time + "): it comes from another scene, seed, options or kernel");
      ++i;
    }
  if (i != listed.size())
    throw Usage_error("kvd view: " + path + ": " + std::to_string(listed.size()) + " events, the exact run has " +
                      std::to_string(i));
}

// The page of a segment scene's run (src/view/segment_page.hpp).
int view_segments(const Scene_args& sa, const std::string& text, const std::string& out, const kinetic::Options& o) {
  const segments::Segment_scene s = sa.read_segments("view", text);
  require_finite_in<double>(*sa.path, s, drawn_in_double);
  if (o.until) require_in_span("view", "--until", *o.until, s.start, s.end);
  nlohmann::json data;
  try {
    data = view::segment_page_data(s, std::filesystem::path(*sa.path).filename().string(),
                                   {o.until, o.max_events, 640}, progress_every_few_seconds("kvd view"),
                                   progress_every_few_seconds("kvd view", "intervals drawn"));
  } catch (const view::Segment_page_invalid& e) {
    std::cerr << "kvd view: validation failed: " << e.what() << "\n";
    return 1;
  }
  const std::string html = view::segment_page_html(data);
  write_atomically("view", out, html);
  std::cout << "kvd view: " << data["batches"].size() << " batches, " << data["failures"].get<std::size_t>()
            << " events; wrote " << out << " (" << html.size() / 1024 << " KiB)\n";
  return 0;
}

}  // namespace

int view(Args& args) {
  Scene_args sa;
  sa.wants_view = true;
  kinetic::Options o;
  std::optional<std::string> out, scene_of_trace;
  bool collisions_given = false;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << view_help;
      return 0;
    }
    if (a == "--events") o.max_events = args.unsigned_value(a);
    else if (a == "--until") o.until = exact_option("view", a, args.value(a));
    else if (a == "--out") out = args.value(a);
    else if (a == "--scene") scene_of_trace = args.value(a);
    else if (a == "--collisions") {
      o.collisions = collisions_option("view", args.value(a));
      collisions_given = true;
    }
    else if (a == "--json" || !sa.take(args, a)) args.unknown(a);
  }
  if (!out) throw Usage_error("kvd view: missing --out FILE.html (see kvd view --help)");
  if (!ends_with(*out, ".html"))
    throw Usage_error("kvd view: --out must name an .html file");
  if (!sa.path) throw Usage_error("kvd view: missing the SCENE or REPORT file (see kvd view --help)");
  const std::string input = *sa.path;
  const std::string text = scene::read_input(input);
  const auto report = diff_report(input, text);
  const auto trace = report ? std::nullopt : trace_events(input, text);
  if (scene_of_trace && !trace)
    throw Usage_error("kvd view: --scene is for a trace; " + scene::input_name(input) + " is " +
                      (report ? "a kvd diff report, which names its scene" : "a scene"));
  std::optional<std::vector<Listed_event>> listed;
  if (report) {
    sa.path = report_scene(input, *report);
    listed = report_events(input, *report);
  } else if (trace) {
    if (!scene_of_trace) throw Usage_error("kvd view: " + input + " is a trace: give its scene with --scene SCENE");
    sa.path = *scene_of_trace;
    listed = trace;
  }
  if (listed) o.max_events = listed->size();
  // The input is read once: standard input cannot be read again.
  const std::string scene_text = listed ? sa.read_text("view") : text;
  if (segments::scene_format(scene_text) == "kvd-segments/1") {
    if (listed)
      throw Usage_error("kvd view: " + input + ": a report or trace is read with a triangle scene only; " + *sa.path +
                        " is a segment scene (kvd-segments/1)");
    std::vector<std::string> triangle_only;
    if (collisions_given) triangle_only.push_back("--collisions");
    if (sa.view) triangle_only.push_back("--view");
    if (sa.load.allow_intersecting) triangle_only.push_back("--allow-intersecting");
    refuse_triangle_flags("view", triangle_only);
    return view_segments(sa, scene_text, *out, o);
  }
  if (!view::page_supported())
    throw Usage_error("kvd view: this build has no viewer page (Debian's libjs-three was not found when it was built)");
  const scene::Scene s = sa.read_scene("view", scene_text);
  require_finite_in<double>(*sa.path, s, drawn_in_double);
  if (o.until) require_in_span("view", "--until", *o.until, s);
  o.progress = progress_every_few_seconds("kvd view");
  const view::Recorded_run run = with_disjoint_triangles("view", *sa.path, [&] { return view::record_run(s, o); });
  if (!run.sim.valid()) {
    std::cerr << "kvd view: validation failed: " << run.sim.failure << "\n";
    return 1;
  }
  if (listed) require_same_events(input, *listed, run);
  view::Page_input page{std::filesystem::path(*sa.path).filename().string(), &run, report, std::nullopt};
  if (sa.view) page.view = {{(*sa.view)[0].get_d(), (*sa.view)[1].get_d(), (*sa.view)[2].get_d()}};
  const std::string html = view::page_html(view::page_data(page, progress_every_few_seconds("kvd view", "intervals drawn")));
  write_atomically("view", *out, html);
  std::cout << "kvd view: " << run.sim.batches.size() << " batches, " << run.sim.failures << " events, "
            << run.sim.motion_changes.size() << " motion changes" << (report ? ", with the diff report" : trace ? ", as traced" : "")
            << "; wrote " << *out << " (" << html.size() / 1024 << " KiB)\n";
  return 0;
}

}  // namespace kvd::cli
