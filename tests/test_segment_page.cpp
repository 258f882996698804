// The kvd view page of a segment scene (src/view/segment_page.hpp), against
// a run of its own: the page's batches are the run's, each interval's tree
// is the run's tree in force there and a fresh build's at the page's
// instant, which lies strictly between the batch and the next failure, and
// the segments marked are those the batch's failing certificates name.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <set>
#include <string>

#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "kvd/segments/segment_io.hpp"
#include "kvd/segments/segment_svg.hpp"
#include "animation.hpp"
#include "segment_page.hpp"

using namespace kvd;
using namespace kvd::segments;

namespace {

using Run = Kinetic_segment_bsp<Exact_kernel>;

Segment_scene bundled(const std::string& name) {
  return load_segments(std::string(KVD_SOURCE_DIR) + "/data/segments/" + name + ".json");
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The text (Cylindrical_bsp::text) of subtree k of the page's table.
std::string text_of(const nlohmann::json& table, std::size_t k) {
  const nlohmann::json& e = table.at(k);
  if (e.is_null()) return ".";
  return "(" + e.at(0).get<std::string>() + " " + text_of(table, e.at(1)) + " " + text_of(table, e.at(2)) + ")";
}

// The endpoints' pixel positions the page draws interval i with (its
// script's reading of "endpoints", "moving" and "moving_at").
std::vector<double> page_endpoints(const nlohmann::json& data, std::size_t i) {
  std::vector<double> e = data.at("endpoints").get<std::vector<double>>();
  const auto& moving = data.at("moving");
  const auto& at = data.at("intervals")[i].at("moving_at");
  REQUIRE(at.size() == 2 * moving.size());
  for (std::size_t k = 0; k < moving.size(); ++k)
    for (std::size_t c = 0; c < 2; ++c) e.at(2 * moving[k].get<std::size_t>() + c) = at[2 * k + c];
  return e;
}

// Checks the page's data of scene s against a run of its own.
void check_page(const Segment_scene& s, const nlohmann::json& data, std::size_t max_events,
                const std::optional<mpq_class>& until = std::nullopt) {
  const Exact_kernel k;
  const Segment_predicates<Exact_kernel> pred(k, s);
  Run run(k, s, false);
  const auto& batches = data.at("batches");
  const auto& intervals = data.at("intervals");
  // The time limit: the earlier of the scene's end and --until.
  std::optional<mpq_class> limit = s.end;
  if (until && (!limit || *until < *limit)) limit = until;
  REQUIRE(intervals.size() == batches.size() + 1);
  // The page's frame holds every interval's view box.
  Segment_svg_options svg;
  svg.size = data.at("width");
  svg.notes = {""};  // the page's caption has one line of notes (the batch)
  svg.box = view_box(s, mpq_class(intervals[0].at("instant").get<std::string>()));
  for (const auto& v : intervals) svg.box = hull(*svg.box, view_box(s, mpq_class(v.at("instant").get<std::string>())));
  std::vector<std::array<double, 2>> first;  // the endpoints' positions in the first interval
  std::set<std::size_t> moved;               // the endpoints placed elsewhere in another
  std::size_t failures = 0;
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    CAPTURE(s.name, i);
    std::optional<Exact_time> from;
    std::set<std::size_t> named;
    if (i > 0) {
      const Run::Batch b = run.advance();
      const auto& page = batches[i - 1];
      CHECK(page.at("time") == k.to_string(b.time));
      REQUIRE(page.at("failing").size() == b.failing.size());
      for (std::size_t f = 0; f < b.failing.size(); ++f) {
        CHECK(page["failing"][f].at("features") == features(b.failing[f]));
        for (const std::size_t seg : named_segments(b.failing[f])) named.insert(seg);
      }
      for (std::size_t e = 0; e < 4; ++e)
        CHECK(page.at("events").value(segment_event_names[e], std::size_t{0}) == b.events[e]);
      failures += b.failing.size();
      from = b.time;
    }
    const mpq_class instant(intervals[i].at("instant").get<std::string>());
    // An interval from the time limit is drawn there (the tree at an
    // instant is the one just after it); every other instant lies strictly
    // after the interval's start, and none past the limit.
    const Exact_time begins = from ? *from : Exact_time(s.start);
    if (limit && k.compare(begins, Exact_time(*limit)) >= 0) CHECK(instant == *limit);
    else CHECK(k.compare(Exact_time(instant), begins) > 0);
    if (limit) CHECK(instant <= *limit);
    if (const auto next = run.next_event_time()) CHECK(k.compare(Exact_time(instant), *next) < 0);
    const std::string tree = text_of(data.at("subtrees"), intervals[i].at("root"));
    CHECK(tree == run.tree().text());
    CHECK(tree == build_cylindrical_bsp(pred, Exact_time(instant)).text());
    // Each endpoint where segment_layout puts it at the instant.
    const std::vector<double> drawn = page_endpoints(data, i);
    const Segment_layout layout = segment_layout(s, run.tree(), instant, svg);
    REQUIRE(drawn.size() == 2 * layout.endpoints.size());
    for (std::size_t e = 0; e < layout.endpoints.size(); ++e) {
      CHECK(drawn[2 * e] == layout.endpoints[e][0]);
      CHECK(drawn[2 * e + 1] == layout.endpoints[e][1]);
      if (i > 0 && layout.endpoints[e] != first.at(e)) moved.insert(e);
    }
    if (i == 0) first = layout.endpoints;
    std::set<std::size_t> marked;
    for (const std::size_t seg : intervals[i].at("marked")) CHECK(marked.insert(seg).second);
    CHECK(marked == named);
  }
  // Only the endpoints that move are written again: a static one once.
  CHECK(data.at("moving").get<std::set<std::size_t>>() == moved);
  CHECK(data.at("failures") == failures);
  // Where the page stopped: the run has no failure left, or its next batch
  // lies after the limit, or else the page has its events.
  const auto next = run.next_event_time();
  const std::string stopped = !next                                                 ? "exhausted"
                              : until && k.compare(*next, Exact_time(*until)) > 0 ? "limit"
                                                                                  : "events";
  CHECK(data.at("stopped") == stopped);
  // The time reached: the limit when the page stopped there or ran out of
  // failures, else the last batch's.
  CHECK(data.at("time_reached") == k.to_string(stopped != "events" && limit ? Exact_time(*limit) : run.now()));
  if (stopped == "events") {
    CHECK(failures >= max_events);
    if (!batches.empty()) CHECK(failures - batches.back().at("failing").size() < max_events);
  }
}

// The bundled scene `name` with its span ending at its first batch.
Segment_scene ending_at_first_batch(const std::string& name) {
  Segment_scene s = bundled(name);
  const Exact_kernel k;
  Run run(k, s, false);
  const auto first = run.next_event_time();
  REQUIRE(first);
  REQUIRE(first->is_rational());
  s.end = first->rational();
  return s;
}

}  // namespace

TEST_CASE("the segment page shows the tree in force in every interval of the run, at an instant inside it",
          "[view][segments]") {
  for (const auto& [name, events] : {std::pair{"rotating-10", 40}, {"over-endpoint", 100}, {"turning-vertical", 100},
                                     {"concurrent-three", 100}, {"random-100", 25}}) {
    const Segment_scene s = bundled(name);
    CAPTURE(name);
    const nlohmann::json data = view::segment_page_data(s, name, {std::nullopt, std::size_t(events), 320});
    check_page(s, data, std::size_t(events));
  }
}

TEST_CASE("a batch at the span's end is drawn at the end, not after it", "[view][segments]") {
  for (const std::string name : {"over-endpoint", "turning-vertical"}) {
    const Segment_scene s = ending_at_first_batch(name);
    CAPTURE(name);
    const nlohmann::json data = view::segment_page_data(s, name, {std::nullopt, 100, 320});
    REQUIRE(data.at("batches").size() == 1);
    CHECK(data.at("intervals")[1].at("instant") == s.end->get_str());
    check_page(s, data, 100);
  }
}

TEST_CASE("a batch at --until is drawn there, though a failure follows", "[view][segments]") {
  const Segment_scene s = bundled("random-100");
  const Exact_kernel k;
  Run run(k, s, false);
  for (int i = 0; i < 3; ++i) run.advance();
  REQUIRE(run.now().is_rational());
  const mpq_class until = run.now().rational();
  REQUIRE(run.next_event_time());
  const nlohmann::json data = view::segment_page_data(s, "random-100", {until, 1000, 320});
  CHECK(data.at("stopped") == "limit");
  REQUIRE(data.at("batches").size() == 3);
  CHECK(data.at("intervals")[3].at("instant") == until.get_str());
  check_page(s, data, 1000, until);
}

// The instant drawn after a batch (kvd view and kvd animate, both kinds of
// scene): inside the interval, never past the limit.
TEST_CASE("drawn_after stays inside the interval and never passes the limit", "[view]") {
  const Exact_kernel k;
  const auto t = [](long p, long q) { return Exact_time(mpq_class(p, q)); };
  const mpq_class within(1, 1000);
  const auto in = [&](const mpq_class& x, const Exact_time& lo, const Exact_time& hi) {
    return k.compare(Exact_time(x), lo) > 0 && k.compare(Exact_time(x), hi) < 0;
  };
  CHECK(in(view::drawn_after(t(1, 1), t(2, 1), std::nullopt, within), t(1, 1), t(2, 1)));
  CHECK(in(view::drawn_after(t(1, 1), t(2, 1), mpq_class(3), within), t(1, 1), t(2, 1)));
  // The next failure past the limit: inside (a, limit).
  CHECK(in(view::drawn_after(t(1, 1), t(5, 1), mpq_class(1001, 1000), within), t(1, 1), t(1001, 1000)));
  CHECK(in(view::drawn_after(t(1, 1), std::nullopt, mpq_class(1001, 1000), within), t(1, 1), t(1001, 1000)));
  // A batch at the limit: the limit, whatever follows.
  CHECK(view::drawn_after(t(2, 1), t(5, 1), mpq_class(2), within) == 2);
  CHECK(view::drawn_after(t(2, 1), std::nullopt, mpq_class(2), within) == 2);
  // No limit and no failure left: just after.
  CHECK(in(view::drawn_after(t(2, 1), std::nullopt, std::nullopt, within), t(2, 1), t(2001, 1000)));
}

TEST_CASE("the segment page stops at --until, after the last batch at or before it", "[view][segments]") {
  const Segment_scene s = bundled("rotating-10");
  const nlohmann::json all = view::segment_page_data(s, "rotating-10", {std::nullopt, 1000, 320});
  REQUIRE(all.at("batches").size() > 4);
  // A rational between the third batch and the fourth.
  const Exact_kernel k;
  Run run(k, s, false);
  for (int i = 0; i < 3; ++i) run.advance();
  const mpq_class until = view::just_after(run.now(), *run.next_event_time(), 1);
  const nlohmann::json upto = view::segment_page_data(s, "rotating-10", {until, 1000, 320});
  CHECK(upto.at("stopped") == "limit");
  CHECK(upto.at("batches").size() == 3);
  check_page(s, upto, 1000, until);
}

TEST_CASE("the segment page inlines its data, script and style whole", "[view][segments]") {
  const Segment_scene s = bundled("over-endpoint");
  const nlohmann::json data =
      view::segment_page_data(s, "over-endpoint <&> x</script><!--<script>", {std::nullopt, 100, 320});
  const std::string html = view::segment_page_html(data);
  CHECK(html.find("/*KVD_") == std::string::npos);
  const std::string open = "<script type=\"application/json\" id=\"kvd-data\">";
  const auto from = html.find(open);
  REQUIRE(from != std::string::npos);
  const auto to = html.find("</script>", from);
  REQUIRE(to != std::string::npos);
  CHECK(nlohmann::json::parse(html.substr(from + open.size(), to - from - open.size())) == data);
  CHECK(occurrences(html, "</script>") == 2);  // the data's and the page script's
  CHECK(occurrences(html.substr(from, to - from), "<!--") == 0);
}
