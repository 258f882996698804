// The kvd view page of a segment scene (src/view/segment_page.hpp), against
// a run of its own: the page's batches are the run's, each interval's tree
// is the run's tree in force there and a fresh build's at the page's
// instant, which lies strictly between the batch and the next failure, and
// the segments marked are those the batch's failing certificates name.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>

#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "kvd/segments/segment_io.hpp"
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

// Checks the page's data of scene s against a run of its own.
void check_page(const Segment_scene& s, const nlohmann::json& data, std::size_t max_events,
                const std::optional<mpq_class>& until = std::nullopt) {
  const Exact_kernel k;
  const Segment_predicates<Exact_kernel> pred(k, s);
  Run run(k, s, false);
  const auto& batches = data.at("batches");
  const auto& intervals = data.at("intervals");
  REQUIRE(intervals.size() == batches.size() + 1);
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
    CHECK(k.compare(Exact_time(instant), from ? *from : Exact_time(s.start)) > 0);
    if (const auto next = run.next_event_time()) CHECK(k.compare(Exact_time(instant), *next) < 0);
    const std::string tree = intervals[i].at("tree");
    CHECK(tree == run.tree().text());
    CHECK(tree == build_cylindrical_bsp(pred, Exact_time(instant)).text());
    CHECK(occurrences(intervals[i].at("picture"), "<line class=\"marked\"") == named.size());
  }
  CHECK(data.at("failures") == failures);
  // Where the page stopped: the run has no failure left, or the page
  // stopped before the batch after the limit.
  const std::string stopped = data.at("stopped");
  CHECK(stopped == (run.next_event_time() ? stopped : "exhausted"));
  if (stopped == "events") {
    CHECK(failures >= max_events);
    if (!batches.empty()) CHECK(failures - batches.back().at("failing").size() < max_events);
  }
  if (stopped == "limit") CHECK(k.compare(*run.next_event_time(), Exact_time(*until)) > 0);
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
  const nlohmann::json data = view::segment_page_data(s, "over-endpoint <&>", {std::nullopt, 100, 320});
  const std::string html = view::segment_page_html(data);
  CHECK(html.find("/*KVD_") == std::string::npos);
  const std::string open = "<script type=\"application/json\" id=\"kvd-data\">";
  const auto from = html.find(open);
  REQUIRE(from != std::string::npos);
  const auto to = html.find("</script>", from);
  REQUIRE(to != std::string::npos);
  CHECK(nlohmann::json::parse(html.substr(from + open.size(), to - from - open.size())) == data);
  CHECK(occurrences(html, "</script>") == 2);  // the data's and the page script's
}
