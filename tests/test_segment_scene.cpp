// Scenes of moving segments (`kvd-segments/1`): every rejection of the
// format page with its JSON place, the writer's round trip, the exact count
// of crossings, and the generators' families and determinism.
#include <catch2/catch.hpp>
#include <filesystem>
#include <set>
#include <string>

#include "kvd/detail/scene/priority.hpp"
#include "kvd/detail/scene/span_check.hpp"
#include "kvd/segments/segment_crossings.hpp"
#include "kvd/segments/segment_generators.hpp"
#include "kvd/segments/segment_io.hpp"

using namespace kvd::segments;
using kvd::scene::Scene_error;

namespace {

// A document with `segments` spliced in, and extra top-level text.
std::string doc(const std::string& segments, const std::string& extra = "") {
  return R"({"format": "kvd-segments/1", )" + extra + R"("segments": )" + segments + "}";
}
const std::string seg = R"({"endpoints": [["0", "0"], ["4", "1"]]})";
// A segment at rest from (0,0) to (4,1) with the given motion.
std::string moving(const std::string& motion) {
  return "[" + seg.substr(0, seg.size() - 1) + R"(, "motion": )" + motion + "}]";
}

// The message of the rejection, or "" when the document loads.
std::string rejection(const std::string& text) {
  try {
    read_segments(text, "bad.json");
    return "";
  } catch (const Scene_error& e) {
    return e.what();
  }
}

#define REJECTED_AT(text, place, words)                            \
  do {                                                             \
    const std::string msg = rejection(text);                       \
    INFO(msg);                                                     \
    CHECK(msg.rfind(std::string("bad.json: ") + place, 0) == 0);   \
    CHECK(msg.find(words) != std::string::npos);                   \
  } while (0)

Segment make_segment(Q x0, Q y0, Q x1, Q y1) {
  Segment s;
  s.rest = {Point3{x0, y0, Q(1)}, Point3{x1, y1, Q(1)}};
  return s;
}

Segment_scene scene_of(std::vector<Segment> segments) {
  Segment_scene s;
  s.end = Q(10);
  s.segments = std::move(segments);
  s.derive();
  return s;
}

// The Euclidean endpoints of segment i at the start time.
std::array<std::array<Q, 2>, 2> ends(const Segment_scene& s, std::size_t i) {
  std::array<std::array<Q, 2>, 2> e;
  for (std::size_t k = 0; k < 2; ++k) {
    const Point3 p = s.endpoint_at(2 * i + k, s.start);
    e[k] = {p[0] / p[2], p[1] / p[2]};
  }
  return e;
}

int orientation(const std::array<Q, 2>& a, const std::array<Q, 2>& b, const std::array<Q, 2>& c) {
  return sgn((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

// Whether p lies on segment i (its closed extent) at the start time.
bool on_segment(const Segment_scene& s, std::size_t i, const std::array<Q, 2>& p) {
  const auto e = ends(s, i);
  if (orientation(e[0], e[1], p) != 0) return false;
  for (std::size_t c = 0; c < 2; ++c)
    if (p[c] < std::min(e[0][c], e[1][c]) || p[c] > std::max(e[0][c], e[1][c])) return false;
  return true;
}

std::vector<Segment_family> families() {
  return {Segment_family::random, Segment_family::rotating, Segment_family::degenerate};
}

}  // namespace

TEST_CASE("the baseline documents of these tests load", "[segments][reject]") {
  CHECK(rejection(doc("[" + seg + "]")) == "");
  CHECK(rejection(doc(moving(R"({"translation": [["0", "1/2"], "0"]})"))) == "");
  CHECK(rejection(doc(moving("null"))) == "");
}

TEST_CASE("malformed JSON, duplicate keys, unknown and missing keys are rejected", "[segments][reject]") {
  REJECTED_AT(R"({"format": "kvd-segments/1", )", "malformed JSON", "byte");
  REJECTED_AT(doc("[" + seg + "]", R"("name": "a", "name": "b", )"), "/name: duplicate key", "name");
  REJECTED_AT(R"({"format": "kvd-segments/2", "segments": []})", "/format", "kvd-segments/1");
  REJECTED_AT(R"({"format": "kvd-scene/1", "segments": []})", "/format", "kvd-segments/1");
  REJECTED_AT(R"({"segments": []})", "/: ", "missing required key \"format\"");
  REJECTED_AT(R"({"format": "kvd-segments/1"})", "/: ", "missing required key \"segments\"");
  REJECTED_AT(doc("[" + seg + "]", R"("objects": [], )"), "/objects", "unknown key");
  REJECTED_AT(doc(R"([{"endpoints": [[0, 0], [1, 1]], "moton": null}])"), "/segments/0/moton", "unknown key");
  REJECTED_AT(doc(R"([{"name": "a"}])"), "/segments/0", "missing required key \"endpoints\"");
  REJECTED_AT(doc("[]"), "/segments", "at least one segment");
  REJECTED_AT(doc("{}"), "/segments", "expected an array");
  REJECTED_AT(doc(moving(R"({"spin": 1})")), "/segments/0/motion/spin", "unknown key");
  REJECTED_AT(doc(moving(R"({"translation": [0, 0], "matrix": []})")), "/segments/0/motion", "exactly one");
  REJECTED_AT(doc(moving("[]")), "/segments/0/motion", "expected an object");
}

TEST_CASE("names, time, and priority are checked", "[segments][reject]") {
  const std::string two = "[" + seg + R"(, {"endpoints": [[1, 3], [3, -1]]}])";
  REJECTED_AT(doc(R"([{"name": "a", "endpoints": [[0, 0], [1, 1]]}, {"name": "a", "endpoints": [[2, 0], [3, 1]]}])"),
              "/segments/1/name", "used twice");
  // "" is no name (SEGMENT_FORMAT.md), so two of them are no clash.
  CHECK(rejection(doc(R"([{"name": "", "endpoints": [[0, 0], [1, 1]]}, {"name": "", "endpoints": [[2, 0], [3, 1]]}])")) == "");
  REJECTED_AT(doc(R"([{"name": 7, "endpoints": [[0, 0], [1, 1]]}])"), "/segments/0/name", "expected a string");
  REJECTED_AT(doc(two, R"("time": {"start": "1", "end": "1"}, )"), "/time", "less than");
  REJECTED_AT(doc(two, R"("time": {"start": "0", "stop": "1"}, )"), "/time/stop", "unknown key");
  REJECTED_AT(doc(two, R"("time": {"start": "0.1.2"}, )"), "/time/start", "0.1.2");
  REJECTED_AT(doc(two, R"("priority": {"seed": 1, "order": [0, 1]}, )"), "/priority", "exactly one");
  REJECTED_AT(doc(two, R"("priority": {"seed": -1}, )"), "/priority/seed", "non-negative integer");
  REJECTED_AT(doc(two, R"("priority": {"order": [0]}, )"), "/priority/order", "every segment exactly once");
  REJECTED_AT(doc(two, R"("priority": {"order": [0, 0]}, )"), "/priority/order/1", "listed twice");
  REJECTED_AT(doc(two, R"("priority": {"order": [0, 2]}, )"), "/priority/order/1", "out of range");
  CHECK(rejection(doc(two, R"("priority": {"order": [1, 0]}, )")) == "");
}

TEST_CASE("numbers, polynomials, points and motions have their shapes", "[segments][reject]") {
  REJECTED_AT(doc(R"([{"endpoints": [[0, 0]]}])"), "/segments/0/endpoints", "2 entries");
  REJECTED_AT(doc(R"([{"endpoints": [[0, 0, 1, 1], [1, 1]]}])"), "/segments/0/endpoints/0", "[x, y]");
  REJECTED_AT(doc(R"([{"endpoints": [[0, 0], [1, 1, 0]]}])"), "/segments/0/endpoints/1", "W = 0");
  REJECTED_AT(doc(R"([{"endpoints": [[0, "1/0"], [1, 1]]}])"), "/segments/0/endpoints/0/1", "1/0");
  REJECTED_AT(doc(R"([{"endpoints": [[0, [0, 1]], [1, 1]]}])"), "/segments/0/endpoints/0/1", "expected a number");
  REJECTED_AT(doc(moving(R"({"translation": [0, 0, 0]})")), "/segments/0/motion/translation", "2 entries");
  std::string degree_33 = "[0";
  for (int i = 0; i < 33; ++i) degree_33 += ", 1";
  REJECTED_AT(doc(moving(R"({"translation": [0, )" + degree_33 + "]]}")), "/segments/0/motion/translation/1",
              "degree in t is at most 32");
  REJECTED_AT(doc(moving(R"({"matrix": [[1, 0, 0], [0, 1, 0]]})")), "/segments/0/motion/matrix", "3 entries");
  REJECTED_AT(doc(moving(R"({"matrix": [[1, 0, 0], [0, 1], [0, 0, 1]]})")), "/segments/0/motion/matrix/1", "3 entries");
  REJECTED_AT(doc(moving(R"({"endpoints": [[0, 0, 1]]})")), "/segments/0/motion/endpoints", "2 entries");
  REJECTED_AT(doc(moving(R"({"endpoints": [[0, 0], [1, 1, 1]]})")), "/segments/0/motion/endpoints/0", "3 entries");
  REJECTED_AT(doc(moving(R"({"endpoints": [[0, 0, 1], [1, "x", 1]]})")), "/segments/0/motion/endpoints/1/1", "\"x\"");
}

TEST_CASE("endpoints stay Euclidean and segments keep a length over the span", "[segments][reject]") {
  // W of the image of (x, y, 1) is 1 - t: zero at t = 1, or at the start.
  REJECTED_AT(doc(moving(R"({"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, [1, -1]]]})"), R"("time": {"end": 2}, )"),
              "/segments/0/endpoints/0", "W vanishes at t = 1, inside the time span");
  REJECTED_AT(doc(moving(R"({"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, [1, -1]]]})")), "/segments/0/endpoints/0",
              "after the start time (the scene has no end)");
  REJECTED_AT(doc(moving(R"({"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, [0, 1]]]})")), "/segments/0/endpoints/0",
              "W is zero at the start time");
  REJECTED_AT(doc(moving(R"({"endpoints": [[0, 0, 1], [1, 1, [2, -1]]]})"), R"("time": {"start": 1, "end": 2}, )"),
              "/segments/0/motion/endpoints/1", "W vanishes at t = 2");
  CHECK(rejection(doc(moving(R"({"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, [1, -1]]]})"), R"("time": {"end": "1/2"}, )")) ==
        "");
  // Zero length at the start, at rest or by motion, and endpoints that meet later.
  REJECTED_AT(doc(R"([{"endpoints": [[1, 2], [2, 4, 2]]}])"), "/segments/0: ", "zero length at the start time");
  REJECTED_AT(doc(moving(R"({"endpoints": [[0, 0, 1], [0, 0, 1]]})")), "/segments/0: ", "zero length");
  const std::string meeting = moving(R"({"endpoints": [[0, 0, 1], [[4, -2], [1, "-1/2"], 1]]})");
  REJECTED_AT(doc(meeting, R"("time": {"end": 3}, )"), "/segments/0: ", "endpoints coincide at t = 2, inside the time span");
  CHECK(rejection(doc(meeting, R"("time": {"end": 1}, )")) == "");
  // Only a common zero counts: x meeting at t = 2, y at t = 4.
  CHECK(rejection(doc(moving(R"({"endpoints": [[0, 0, 1], [[4, -2], [4, -1], 1]]})"))) == "");
}

TEST_CASE("crossing, overlapping and vertical segments are accepted", "[segments]") {
  const Segment_scene s = read_segments(doc(R"([{"endpoints": [[0, 0], [4, 4]]}, {"endpoints": [[0, 4], [4, 0]]},
      {"endpoints": [[1, 1], [3, 3]]}, {"endpoints": [[2, -1], [2, 5]]}, {"endpoints": [[2, 6], [2, 8]]}])"),
                                        "ok.json");
  CHECK(s.segments.size() == 5);
  CHECK(s.moving_count() == 0);
}

TEST_CASE("the load options' seed replaces the file's priority", "[segments]") {
  const std::string text = doc("[" + seg + R"(, {"endpoints": [[1, 3], [3, -1]]}, {"endpoints": [[5, 0], [6, 1]]}])",
                               R"("priority": {"order": [2, 0, 1]}, )");
  const Segment_scene ordered = read_segments(text, "a.json");
  CHECK(ordered.priority_order == std::vector<std::size_t>{2, 0, 1});
  CHECK(ordered.rank == std::vector<std::size_t>{1, 2, 0});
  const Segment_scene seeded = read_segments(text, "a.json", Segment_load_options{5});
  CHECK_FALSE(seeded.order);
  CHECK(seeded.seed == 5);
  CHECK(seeded.priority_order == kvd::scene::shuffled_ids(3, 5));
}

TEST_CASE("scene_format names the format of a document without reading it all", "[segments]") {
  CHECK(scene_format(doc("[" + seg + "]")) == "kvd-segments/1");
  CHECK(scene_format(R"({"name": {"format": "x"}, "format": "kvd-scene/1", "objects": []})") == "kvd-scene/1");
  // Numbers a double cannot hold come before it; the text after it is not read.
  CHECK(scene_format(R"({"a": 1e400, "b": [123456789012345678901234567890], "format": "kvd-segments/1", )") ==
        "kvd-segments/1");
  CHECK(scene_format("\xEF\xBB\xBF" + doc("[]")) == "kvd-segments/1");
  CHECK(scene_format(R"({"format": 1})") == "");
  CHECK(scene_format(R"({"format": ["kvd-segments/1"]})") == "");
  CHECK(scene_format(R"(["format", "kvd-segments/1"])") == "");
  CHECK(scene_format("not JSON") == "");
  CHECK(scene_format("") == "");
}

TEST_CASE("count_crossings counts proper crossings only", "[segments][crossings]") {
  // An X, a T (an endpoint on the other's interior), a V (a shared endpoint),
  // collinear overlapping and parallel segments.
  CHECK(count_crossings(scene_of({make_segment(0, 0, 4, 4), make_segment(0, 4, 4, 0)}), 0) == 1);
  CHECK(count_crossings(scene_of({make_segment(0, 0, 4, 0), make_segment(2, 0, 2, 3)}), 0) == 0);
  CHECK(count_crossings(scene_of({make_segment(0, 0, 4, 0), make_segment(4, 0, 5, 3)}), 0) == 0);
  CHECK(count_crossings(scene_of({make_segment(0, 0, 4, 2), make_segment(2, 1, 6, 3)}), 0) == 0);
  CHECK(count_crossings(scene_of({make_segment(0, 0, 4, 2), make_segment(0, 1, 4, 3)}), 0) == 0);
  // A grid of three horizontal and three vertical segments: nine crossings.
  std::vector<Segment> grid;
  for (int i = 1; i <= 3; ++i) {
    grid.push_back(make_segment(0, i, 4, i));
    grid.push_back(make_segment(i, 0, i, 4));
  }
  CHECK(count_crossings(scene_of(grid), 0) == 9);
  // Three segments through one point: three pairs.
  CHECK(count_crossings(scene_of({make_segment(0, 0, 4, 4), make_segment(1, 4, 3, 0), make_segment(-1, 1, 5, 3)}), 0) ==
        3);
  // A segment sinking through another: touching it at t = 1 and t = 2, crossing it between.
  Segment sinker = make_segment(1, 1, 3, 2);
  sinker.motion.kind = Segment_motion::Kind::translation;
  sinker.motion.translation = {QPoly(), QPoly{Q(0), Q(-1)}};
  const Segment_scene s = scene_of({make_segment(0, 0, 4, 0), sinker});
  CHECK(count_crossings(s, 0) == 0);
  CHECK(count_crossings(s, 1) == 0);
  CHECK(count_crossings(s, Q(3, 2)) == 1);
  CHECK(count_crossings(s, 2) == 0);
}

TEST_CASE("every generated family round-trips through the writer and the reader", "[segments][generate]") {
  for (const Segment_family f : families())
    for (const Segment_motion_kind m :
         {Segment_motion_kind::linear, Segment_motion_kind::quadratic, Segment_motion_kind::rotating}) {
      if (f == Segment_family::rotating && m != Segment_motion_kind::rotating) continue;
      Segment_generator_options o;
      o.family = f;
      o.motion = m;
      o.n = 40;
      o.seed = 11;
      o.moving = 25;
      const Segment_scene s = generate_segments(o);
      INFO(s.name);
      CHECK(s.segments.size() == 40);
      CHECK(s.moving_count() == 25);
      const std::string text = write_segments(s);
      const Segment_scene again = read_segments(text, "generated");
      CHECK(again == s);
      CHECK(again.priority_order == s.priority_order);
      CHECK(write_segments(again) == text);
    }
}

TEST_CASE("the bundled segment scenes load and round-trip", "[segments]") {
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(KVD_SOURCE_DIR) + "/data/segments")) {
    if (e.path().extension() != ".json") continue;
    INFO(e.path().string());
    const Segment_scene s = load_segments(e.path().string());
    CHECK(read_segments(write_segments(s), "written") == s);
    ++files;
  }
  CHECK(files >= 5);
  const std::string dir = std::string(KVD_SOURCE_DIR) + "/data/segments/";
  CHECK(count_crossings(load_segments(dir + "two-crossing.json"), 0) == 1);
  CHECK(count_crossings(load_segments(dir + "concurrent-three.json"), 0) == 3);
  const Segment_scene sinking = load_segments(dir + "over-endpoint.json");
  CHECK(count_crossings(sinking, 3) == 0);  // on the floor's endpoint
  CHECK(count_crossings(sinking, Q(13, 4)) == 1);
  const Segment_scene turning = load_segments(dir + "turning-vertical.json");
  const Motion_point3 a = turning.endpoint(2), b = turning.endpoint(3);
  const auto vertical = kvd::scene::first_zero(a[0] * b[2] - b[0] * a[2], turning.start, turning.end);
  REQUIRE(vertical);
  CHECK(vertical->to_string() == "1");
}

TEST_CASE("the same options give the same bytes, another seed another scene", "[segments][generate]") {
  for (const Segment_family f : families()) {
    Segment_generator_options o;
    o.family = f;
    o.n = 30;
    o.seed = 4;
    const std::string a = write_segments(generate_segments(o));
    CHECK(write_segments(generate_segments(o)) == a);
    o.seed = 5;
    CHECK(write_segments(generate_segments(o)) != a);
  }
}

TEST_CASE("long random segments cross many more times than short ones", "[segments][generate]") {
  Segment_generator_options o;
  o.n = 60;
  o.seed = 2;
  o.length = Q(1, 8);
  const std::size_t short_k = count_crossings(generate_segments(o), 0);
  o.length = Q(1);
  const std::size_t long_k = count_crossings(generate_segments(o), 0);
  INFO("short " << short_k << ", long " << long_k);
  CHECK(long_k > 5 * short_k);
  // The presets: half the box side against 1/ceil(sqrt(n)).
  o.length.reset();
  o.crossings = Crossings::quadratic;
  const std::size_t quadratic_k = count_crossings(generate_segments(o), 0);
  o.crossings = Crossings::linear;
  CHECK(quadratic_k > 3 * count_crossings(generate_segments(o), 0));
}

TEST_CASE("random scenes have no shared x and no vertical segment at the start", "[segments][generate]") {
  Segment_generator_options o;
  o.n = 200;
  o.seed = 9;
  const Segment_scene s = generate_segments(o);
  std::set<Q> xs;
  for (std::size_t i = 0; i < s.segments.size(); ++i)
    for (const auto& e : ends(s, i)) CHECK(xs.insert(e[0]).second);
}

TEST_CASE("rotating segments turn through vertical inside the span", "[segments][generate]") {
  Segment_generator_options o;
  o.family = Segment_family::rotating;
  o.n = 10;
  o.seed = 1;
  const Segment_scene s = generate_segments(o);
  CHECK(s.max_motion_degree() == 2);
  std::size_t turning = 0;
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    const Motion_point3 a = s.endpoint(2 * i), b = s.endpoint(2 * i + 1);
    // The x difference of the endpoints, times W1 W2.
    turning += kvd::scene::first_zero(a[0] * b[2] - b[0] * a[2], s.start, s.end).has_value();
  }
  CHECK(turning > 0);
  o.motion = Segment_motion_kind::linear;
  CHECK_THROWS_AS(generate_segments(o), kvd::scene::Generator_error);
}

TEST_CASE("degenerate scenes hold shared x, concurrent triples, collinear overlaps and vertical segments",
          "[segments][generate]") {
  for (const std::size_t m : {std::size_t(0), std::size_t(12)}) {
    Segment_generator_options o;
    o.family = Segment_family::degenerate;
    o.n = 20;
    o.seed = 3;
    o.moving = m;
    const Segment_scene s = generate_segments(o);
    CHECK(s.moving_count() == m);
    const std::size_t n = s.segments.size();
    bool shared_x = false, concurrent = false, overlap = false, vertical = false;
    for (std::size_t i = 0; i < n; ++i) {
      const auto a = ends(s, i);
      vertical = vertical || a[0][0] == a[1][0];
      for (std::size_t j = i + 1; j < n; ++j) {
        const auto b = ends(s, j);
        for (const auto& p : a)
          for (const auto& q : b) shared_x = shared_x || p[0] == q[0];
        const int o0 = orientation(a[0], a[1], b[0]), o1 = orientation(a[0], a[1], b[1]);
        // Collinear, and an endpoint of one strictly inside the other.
        if (o0 == 0 && o1 == 0)
          for (std::size_t k = 0; k < 2; ++k)
            overlap = overlap || (on_segment(s, i, b[k]) && b[k] != a[0] && b[k] != a[1]) ||
                      (on_segment(s, j, a[k]) && a[k] != b[0] && a[k] != b[1]);
        if (o0 * o1 >= 0 || orientation(b[0], b[1], a[0]) * orientation(b[0], b[1], a[1]) >= 0) continue;
        // The crossing point of i and j, and a third segment through it.
        const Q dx = a[1][0] - a[0][0], dy = a[1][1] - a[0][1], ex = b[1][0] - b[0][0], ey = b[1][1] - b[0][1];
        const Q u = ((b[0][0] - a[0][0]) * ey - (b[0][1] - a[0][1]) * ex) / (dx * ey - dy * ex);
        const std::array<Q, 2> p{a[0][0] + u * dx, a[0][1] + u * dy};
        for (std::size_t k = 0; k < n; ++k) concurrent = concurrent || (k != i && k != j && on_segment(s, k, p));
      }
    }
    CHECK(shared_x);
    CHECK(concurrent);
    CHECK(overlap);
    CHECK(vertical);
    // Moving segments translate vertically, so every x stays.
    for (std::size_t i = 0; i < n; ++i)
      if (s.is_moving(i)) CHECK(s.segments[i].motion.translation[0].is_zero());
  }
}

TEST_CASE("impossible generator parameters are refused", "[segments][generate]") {
  Segment_generator_options o;
  o.n = 0;
  CHECK_THROWS_AS(generate_segments(o), kvd::scene::Generator_error);
  o.n = 5;
  o.moving = 6;
  CHECK_THROWS_AS(generate_segments(o), kvd::scene::Generator_error);
  o.moving.reset();
  o.length = Q(3, 2);
  CHECK_THROWS_AS(generate_segments(o), kvd::scene::Generator_error);
  o.length = Q(1, 2);
  o.end = 0;
  CHECK_THROWS_AS(generate_segments(o), kvd::scene::Generator_error);
}
