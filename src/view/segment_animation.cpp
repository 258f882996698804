#include "segment_animation.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "kvd/segments/segment_svg.hpp"

namespace kvd::view {

namespace {

using Run = segments::Kinetic_segment_bsp<Exact_kernel>;

struct Planned {
  mpq_class time;
  std::optional<std::size_t> batch;
};

// "edge event, 2 intersection events".
std::string event_kinds(const Run::Batch& b) {
  static const char* const names[] = {"vertex event", "edge event", "intersection event", "flip"};
  std::string out;
  for (std::size_t k = 0; k < 4; ++k) {
    if (b.events[k] == 0) continue;
    out += out.empty() ? "" : ", ";
    out += b.events[k] == 1 ? std::string(names[k]) : std::to_string(b.events[k]) + " " + names[k] + "s";
  }
  return out;
}

// t exactly when it is a short rational, else to 10 digits.
std::string time_text(const Exact_time& t) {
  if (t.is_rational() && t.rational().get_str().size() <= 20) return "t = " + t.rational().get_str();
  char buf[48];
  std::snprintf(buf, sizeof buf, "t ≈ %.10g", t.to_double());
  return buf;
}

}  // namespace

Segment_film segment_film(const segments::Segment_scene& s, const Segment_film_options& o,
                          const std::function<void(std::size_t, std::size_t)>& run_progress,
                          const std::function<void(std::size_t, std::size_t)>& frame_progress) {
  const Exact_kernel k;
  Run run(k, s, false);
  std::vector<Run::Batch> batches;
  Segment_film film;
  std::optional<Exact_time> next;  // the first failure after the last batch
  bool reached_limit = true;
  while ((next = run.next_event_time()) && (!o.until || k.compare(*next, Exact_time(*o.until)) <= 0)) {
    if (film.failures >= o.max_events) {
      reached_limit = false;
      break;
    }
    batches.push_back(run.advance());
    film.failures += batches.back().failing.size();
    if (run_progress) run_progress(batches.size(), film.failures);
  }
  film.batches = batches.size();

  // The film runs to the time limit when the run reached it, else to its
  // last batch; with no batch, to the start when the run stopped for its
  // events, or a second on when it ran out of them with no limit.
  const std::optional<mpq_class> limit = s.limit(o.until);
  mpq_class end = reached_limit ? s.start + 1 : s.start;
  if (reached_limit && limit) end = *limit;
  else if (!batches.empty()) end = batches.back().time.lower();  // the time itself when rational
  std::vector<Planned> plan;
  for (int i = 0; i < o.sampled && end > s.start; ++i)
    plan.push_back({s.start + (end - s.start) * (2 * i + 1) / (2 * o.sampled), {}});
  const mpq_class within = (end > s.start ? end - s.start : mpq_class(1)) / 1000;
  for (std::size_t b = 0; b < batches.size(); ++b) {
    const Exact_time& at = batches[b].time;
    const std::optional<Exact_time> to = b + 1 < batches.size() ? std::optional(batches[b + 1].time) : next;
    plan.push_back({drawn_after(at, to, limit, within), b});
  }
  if (plan.empty()) plan.push_back({s.start, {}});
  std::stable_sort(plan.begin(), plan.end(), [](const Planned& a, const Planned& b) { return a.time < b.time; });

  segments::Segment_svg_options svg;
  svg.size = o.size;
  svg.box = segments::view_box(s, plan.front().time);
  for (const Planned& p : plan) svg.box = segments::hull(*svg.box, segments::view_box(s, p.time));
  const segments::Segment_predicates<Exact_kernel> pred(k, s);
  for (const Planned& p : plan) {
    // The tree in force at p.time, built afresh there.
    const segments::Cylindrical_bsp tree = segments::build_cylindrical_bsp(pred, Exact_time(p.time));
    svg.notes = {p.batch ? "after batch " + std::to_string(*p.batch + 1) + " of " + std::to_string(batches.size()) +
                               " (" + time_text(batches[*p.batch].time) + "): " + event_kinds(batches[*p.batch])
                         : ""};
    const segments::Segment_picture pic = segments::draw_segment_bsp(s, tree, p.time, svg);
    film.width = pic.width;
    film.height = pic.height;
    film.frames.push_back({pic.elements, p.batch ? o.hold : 1, p.batch});
    if (frame_progress) frame_progress(film.frames.size(), plan.size());
  }
  return film;
}

}  // namespace kvd::view
