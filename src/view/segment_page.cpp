#include "segment_page.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>

#include "animation.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "kvd/segments/segment_svg.hpp"
#include "tree_table.hpp"

namespace kvd::view {

namespace {

using Run = segments::Kinetic_segment_bsp<Exact_kernel>;

// An interval of the run: from a batch (none: the start) to the next
// failure (none: the run's end), and the tree in force there.
struct Run_interval {
  std::optional<std::size_t> batch;
  segments::Cylindrical_bsp tree;
  mpq_class instant;
};

std::string approx(double t) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.10g", t);
  return buf;
}

nlohmann::json batch_json(const Exact_kernel& k, const Run::Batch& b) {
  nlohmann::json events = nlohmann::json::object(), failing = nlohmann::json::array();
  for (std::size_t e = 0; e < 4; ++e)
    if (b.events[e]) events[segments::segment_event_names[e]] = b.events[e];
  for (const auto& key : b.failing) {
    nlohmann::json named = nlohmann::json::array();
    for (const std::size_t s : segments::named_segments(key))
      if (std::find(named.begin(), named.end(), s) == named.end()) named.push_back(s);
    failing.push_back({{"kind", segments::kind_name(key.kind)}, {"features", segments::features(key)}, {"segments", named}});
  }
  return {{"time", k.to_string(b.time)}, {"approx", approx(k.to_double(b.time))}, {"events", events},
          {"failing", failing}, {"changed", b.changed}, {"nodes_rebuilt", b.nodes_rebuilt},
          {"certificates", b.certificates}};
}

// The table's entries as [cut, left, right], the entries of a leaf as null.
nlohmann::json subtrees(const Tree_table& table) {
  nlohmann::json out = nlohmann::json::array();
  for (const Tree_table::Entry& e : table.entries())
    out.push_back(e.left < 0 ? nlohmann::json(nullptr) : nlohmann::json::array({e.cut, e.left, e.right}));
  return out;
}

// The endpoints' pixel positions, `at[i][e]` in interval i: every one's in
// the first interval ("endpoints": [x0, y0, x1, y1, ...]), the endpoints
// placed elsewhere in some interval ("moving", once), and each interval's
// positions of those ("moving_at": [x, y, ...] in that order). A static
// segment's are written once: at 1,600 segments, half moving, they were
// most of a 7.6 MiB page.
void add_positions(const std::vector<std::vector<std::array<double, 2>>>& at, nlohmann::json& page) {
  nlohmann::json first = nlohmann::json::array(), moving = nlohmann::json::array();
  std::vector<std::size_t> moved;
  for (std::size_t e = 0; e < at.front().size(); ++e) {
    first.insert(first.end(), {at.front()[e][0], at.front()[e][1]});
    if (std::ranges::any_of(at, [&](const auto& p) { return p[e] != at.front()[e]; })) moved.push_back(e);
  }
  for (std::size_t i = 0; i < at.size(); ++i) {
    nlohmann::json these = nlohmann::json::array();
    for (const std::size_t e : moved) these.insert(these.end(), {at[i][e][0], at[i][e][1]});
    page["intervals"][i]["moving_at"] = std::move(these);
  }
  page["endpoints"] = std::move(first);
  page["moving"] = moved;
}

}  // namespace

nlohmann::json segment_page_data(const segments::Segment_scene& s, const std::string& title,
                                 const Segment_page_options& o,
                                 const std::function<void(std::size_t, std::size_t)>& run_progress,
                                 const std::function<void(std::size_t, std::size_t)>& draw_progress) {
  const Exact_kernel k;
  Run run(k, s, false);
  const mpq_class within = (s.end ? *s.end - s.start : mpq_class(1)) / 1000;
  const std::optional<mpq_class> limit = s.limit(o.until);
  // The instant drawn for the interval from `from` to the next failure.
  const auto inside = [&](const Exact_time& from, const std::optional<Exact_time>& to) {
    return drawn_after(from, to, limit, within);
  };
  std::vector<Run::Batch> batches;
  std::vector<Run_interval> intervals;
  std::optional<Exact_time> next = run.next_event_time();
  intervals.push_back({std::nullopt, run.tree(), inside(Exact_time(s.start), next)});
  std::size_t failures = 0;
  std::string stopped = "exhausted";
  for (; next; next = run.next_event_time()) {
    if (o.until && k.compare(*next, Exact_time(*o.until)) > 0) {
      stopped = "limit";
      break;
    }
    if (failures >= o.max_events) {
      stopped = "events";
      break;
    }
    batches.push_back(run.advance());
    failures += batches.back().failing.size();
    intervals.push_back({batches.size() - 1, run.tree(), mpq_class()});
    if (run_progress) run_progress(batches.size(), failures);
  }
  for (std::size_t i = 1; i < intervals.size(); ++i)
    intervals[i].instant = inside(batches[*intervals[i].batch].time,
                                  i + 1 < intervals.size() ? std::optional<Exact_time>(batches[i].time) : next);

  segments::Segment_svg_options svg;
  svg.size = o.size;
  svg.box = segments::view_box(s, intervals.front().instant);
  for (const Run_interval& v : intervals) svg.box = segments::hull(*svg.box, segments::view_box(s, v.instant));
  const segments::Segment_predicates<Exact_kernel> pred(k, s);
  nlohmann::json shown = nlohmann::json::array();
  segments::Segment_layout layout;
  std::vector<std::vector<std::array<double, 2>>> positions;  // the endpoints', each interval's
  // The intervals' trees share most subtrees (a batch changes a few nodes):
  // each is kept once (a page of 1,600 segments was 27 MiB with a text per
  // interval).
  Tree_table table;
  for (const Run_interval& v : intervals) {
    const std::string text = v.tree.text();
    if (segments::build_cylindrical_bsp(pred, Exact_time(v.instant)).text() != text)
      throw Segment_page_invalid("the tree in force at t = " + v.instant.get_str() +
                                 " differs from a fresh build there");
    std::vector<std::size_t> marked;
    if (v.batch)
      for (const auto& key : batches[*v.batch].failing)
        for (const std::size_t seg : segments::named_segments(key))
          if (std::find(marked.begin(), marked.end(), seg) == marked.end()) marked.push_back(seg);
    svg.notes = {v.batch ? "after batch " + std::to_string(*v.batch + 1) + " of " + std::to_string(batches.size())
                         : "before the first batch"};
    // The page draws the picture from the tree and these positions: a
    // picture written out here was some 200 bytes a cell (17 MiB for
    // random-100.json's 90 intervals).
    layout = segments::segment_layout(s, v.tree, v.instant, svg);
    nlohmann::json crossings = nlohmann::json::object();
    positions.push_back(layout.endpoints);
    for (const auto& [c, at] : layout.crossings) crossings[segments::point_name(c)] = at;
    const segments::Bsp_counts c = v.tree.counts();
    shown.push_back({{"instant", v.instant.get_str()}, {"root", table.add(v.tree)}, {"nodes", c.nodes}, {"height", c.height},
                     {"caption", layout.caption}, {"crossings", crossings},
                     {"marked", marked}});
    if (draw_progress) draw_progress(shown.size(), intervals.size());
  }
  nlohmann::json list = nlohmann::json::array();
  for (const auto& b : batches) list.push_back(batch_json(k, b));
  // The time reached: the last batch's, or the limit when the page stopped
  // there or ran out of failures before it, as kvd simulate says.
  const Exact_time reached = stopped != "events" && limit ? Exact_time(*limit) : run.now();
  nlohmann::json page = {{"format", "kvd-segment-view/3"},
                         {"title", title},
                         {"scene", s.name},
                         {"segments", s.segments.size()},
                         {"start", s.start.get_str()},
                         {"failures", failures},
                         {"stopped", stopped},
                         {"time_reached", k.to_string(reached)},
                         {"time_reached_approx", approx(k.to_double(reached))},
                         {"width", layout.width},
                         {"height", layout.height},
                         {"frame", {layout.left, layout.top, layout.box_width, layout.box_height}},
                         {"style", segments::segment_svg_style()},
                         {"batches", list},
                         {"subtrees", subtrees(table)},
                         {"intervals", shown}};
  add_positions(positions, page);
  return page;
}

}  // namespace kvd::view
