// Every rejection rule of the scene format, each with a malformed document:
// the loader throws Scene_error naming the source and the JSON place.
#include <catch2/catch.hpp>
#include <string>

#include "kvd/detail/scene/exact_number.hpp"
#include "kvd/scene/scene_io.hpp"

using kvd::scene::read_scene;
using kvd::scene::Scene_error;

namespace {

// A valid two-object scene with `objects` spliced in, and extra top-level text.
std::string doc(const std::string& objects, const std::string& extra = "") {
  return R"({"format": "kvd-scene/1", )" + extra + R"("objects": )" + objects + "}";
}
const std::string tri = R"({"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]]})";
const std::string tri_high = R"({"vertices": [[0,0,5],[1,0,5],[0,1,5]], "triangles": [[0,1,2]]})";

// The message of the rejection, or "" when the document loads.
std::string rejection(const std::string& text, const kvd::scene::Load_options& o = {}) {
  try {
    read_scene(text, "bad.json", o);
    return "";
  } catch (const Scene_error& e) {
    return e.what();
  }
}

#define REJECTED_AT(text, place, words)                   \
  do {                                                   \
    const std::string msg = rejection(text);             \
    INFO(msg);                                           \
    CHECK(msg.rfind(std::string("bad.json: ") + place, 0) == 0); \
    CHECK(msg.find(words) != std::string::npos);         \
  } while (0)

}  // namespace

TEST_CASE("the baseline documents of these tests load", "[scene][reject]") {
  CHECK(rejection(doc("[" + tri + "]")) == "");
  // A UTF-8 byte-order mark is ignored by design; one in the middle is malformed JSON.
  CHECK(rejection("\xEF\xBB\xBF" + doc("[" + tri + "]")) == "");
  REJECTED_AT("\xEF\xBB\xBF\xEF\xBB\xBF" + doc("[" + tri + "]"), "malformed JSON", "byte");
  CHECK(rejection(doc("[" + tri + "," + tri_high + "]")) == "");
}

TEST_CASE("malformed JSON, deep nesting, duplicate keys and garbage are rejected", "[scene][reject]") {
  REJECTED_AT("{\"format\": ", "malformed JSON", "byte");
  REJECTED_AT(doc("[" + tri + "]") + " 7", "malformed JSON", "byte");
  // Nesting and duplicate keys name their JSON place.
  std::string deep_place;
  for (int i = 0; i < 64; ++i) deep_place += "/0";
  REJECTED_AT(std::string(100000, '['), deep_place + ": nesting deeper than 64", "nesting");
  REJECTED_AT(R"({"format": "kvd-scene/1", "format": "kvd-scene/1", "objects": [])", "/format: duplicate key", "format");
  REJECTED_AT(R"({"format": "kvd-scene/1", "objects": [{"name": "a", "vertices": [], "name": "b"}]})",
              "/objects/0/name: duplicate key", "\"name\"");
  REJECTED_AT(R"({"format": "kvd-scene/1", "objects": [{"a/b~": {"x": 1, "x": 2}}]})", "/objects/0/a~1b~0/x: duplicate key", "x");
  REJECTED_AT(std::string("\x00\xff\xfe garbage", 12), "malformed JSON", "byte");
  REJECTED_AT(R"({"format": "kvd-scene/1", "name": "\xff", "objects": []})", "malformed JSON", "byte");
  CHECK(rejection(std::string(63, '[') + std::string(63, ']')).find("nesting") == std::string::npos);
}

TEST_CASE("unknown formats, missing keys and unknown keys are rejected", "[scene][reject]") {
  REJECTED_AT(R"({"format": "kvd-scene/2", "objects": [{}]})", "/format", "kvd-scene/1");
  REJECTED_AT(R"({"format": 1, "objects": [{}]})", "/format", "kvd-scene/1");
  REJECTED_AT(R"({"objects": []})", "/: ", "missing required key \"format\"");
  // Another format's keys: the format is named unknown, not the keys.
  REJECTED_AT(R"({"format": "kvd-segments/2", "segments": []})", "/format", "kvd-segments/1");
  REJECTED_AT(R"({"format": 3, "segments": []})", "/format", "unknown format");
  REJECTED_AT(R"({"segments": []})", "/: ", "missing required key \"format\"");
  REJECTED_AT(R"({"format": "kvd-scene/1"})", "/: ", "missing required key \"objects\"");
  REJECTED_AT(doc("[" + tri + "]", R"("objets": 1, )"), "/objets", "unknown key");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangels": [[0,1,2]]}])"), "/objects/0/triangels", "unknown key");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]]}])"), "/objects/0", "missing required key \"triangles\"");
  REJECTED_AT(doc("[]"), "/objects", "at least one object");
  REJECTED_AT(doc("[" + tri + "]", R"("time": {"start": 0, "stop": 1}, )"), "/time/stop", "unknown key");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]], "motion": {"spin": 1}}])"),
              "/objects/0/motion/spin", "unknown key");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]], "motion": {"translation": [0,0,0], "matrix": []}}])"),
              "/objects/0/motion", "exactly one");
  REJECTED_AT(doc("[" + tri + "]", R"("priority": {"seed": 1, "order": []}, )"), "/priority", "exactly one");
}

TEST_CASE("non-exact and unparsable numbers are rejected", "[scene][reject]") {
  for (const char* bad : {"\"+1\"", "\".5\"", "\"1/0\"", "\"NaN\"", "\"inf\"", "\" 1\"", "\"1 \"", "\"1e\"", "\"1.\"",
                          "\"0x10\"", "\"1/-2\"", "\"1e10001\"", "1e10001", "\"1e-99999999999999999999\"", "true", "[1]"}) {
    INFO(bad);
    REJECTED_AT(doc("[" + tri + "]", std::string(R"("time": {"start": )") + bad + "}, "), "/time/start", "");
  }
  // The exponent limit is inclusive, and JSON decimals are read from their text.
  CHECK(rejection(doc("[" + tri + "]", R"("time": {"start": "1e-10000"}, )")) == "");
  const auto s = read_scene(doc("[" + tri + "]", R"("time": {"start": 0.1, "end": "1E+3"}, )"), "ok.json");
  CHECK(s.start == mpq_class(1, 10));
  CHECK(*s.end == 1000);
  // JSON numbers beyond double's range are exact decimals too.
  const auto big = read_scene(doc("[" + tri + "]", R"("time": {"start": -1e400, "end": )" + std::string(400, '9') + "}, "), "ok.json");
  CHECK(big.start == -mpq_class(mpz_class("1" + std::string(400, '0'))));
  CHECK(*big.end == mpq_class(mpz_class(std::string(400, '9'))));
  // Offsets of malformed JSON refer to the file as written.
  CHECK(rejection(R"({"format": 1e400, "x": 1.5.})").find("at byte 27 (line 1, column 28)") != std::string::npos);
}

TEST_CASE("indices out of range and repeated or collinear vertices are rejected", "[scene][reject]") {
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,3]]}])"), "/objects/0/triangles/0/2", "out of range");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,-1]]}])"), "/objects/0/triangles/0/2", "index");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,1.0]]}])"), "/objects/0/triangles/0/2", "index");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,1]]}])"), "/objects/0/triangles/0", "repeated vertex");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,1,1],["1/2","1/2","1/2"]], "triangles": [[0,1,2]]}])"), "/objects/0/triangles/0", "collinear");
  // Collinear only at the start time (here t = 1), not at rest.
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]],
                      "motion": {"matrix": [[1,0,0,0],[0,[1,-1],0,0],[0,0,1,0],[0,0,0,1]]}}])",
                  R"("time": {"start": 1}, )"),
              "/objects/0/triangles/0", "collinear");
  REJECTED_AT(doc("[" + tri + "]", R"("priority": {"order": [[0, 1]]}, )"), "/priority/order/0/1", "out of range");
  REJECTED_AT(doc("[" + tri + "," + tri_high + "]", R"("priority": {"order": [[0, 0], [0, 0]]}, )"), "/priority/order/1", "twice");
  REJECTED_AT(doc("[" + tri + "," + tri_high + "]", R"("priority": {"order": [[1, 0]]}, )"), "/priority/order", "every triangle");
  REJECTED_AT(doc("[" + tri + "]", R"("priority": {"seed": -1}, )"), "/priority/seed", "non-negative integer");
}

TEST_CASE("degenerate points, directions and times are rejected", "[scene][reject]") {
  REJECTED_AT(doc("[" + tri + "]", R"("decomposition": {"x": [0, [], "0", [0, 0]]}, )"), "/decomposition/x", "identically");
  REJECTED_AT(doc("[" + tri + "]", R"("decomposition": {"x": [2, 0, 0, 0], "z": ["1", 0, 0, 0]}, )"), "/decomposition", "same projective point");
  // Proportional as polynomial vectors: (1+t) x.
  REJECTED_AT(doc("[" + tri + "]", R"("decomposition": {"x": [[1,1], 0, [0,0], 0], "z": [1, 0, 0, 0]}, )"), "/decomposition", "same projective point");
  CHECK(rejection(doc("[" + tri + "]", R"("decomposition": {"x": [1, 0, 0, 0], "z": [[0,1], 0, 1, 0]}, )")) == "");
  REJECTED_AT(doc("[" + tri + "]", R"("time": {"start": 2, "end": 2}, )"), "/time", "less than");
  REJECTED_AT(doc("[" + tri + "]", R"("time": {"start": 3, "end": "5/2"}, )"), "/time", "less than");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]]}])"), "/objects/0/vertices/0", "Euclidean");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]],
                      "motion": {"vertices": [[0,0,0,[0,1]], [1,0,0,1], [0,1,0,1]]}}])"),
              "/objects/0/vertices/0", "W is zero at the start time");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]],
                      "motion": {"vertices": [[0,0,0,0], [1,0,0,1], [0,1,0,1]]}}])"),
              "/objects/0/motion/vertices/0", "identically");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]],
                      "motion": {"vertices": [[0,0,0,1]]}}])"),
              "/objects/0/motion/vertices", "3 entries");
  REJECTED_AT(doc("[" + tri + R"(,{"name": "a", "vertices": [[0,0,9],[1,0,9],[0,1,9]], "triangles": [[0,1,2]]},
                  {"name": "a", "vertices": [[0,0,7],[1,0,7],[0,1,7]], "triangles": [[0,1,2]]}])"),
              "/objects/2/name", "used twice");
}

TEST_CASE("triangles intersecting at the start time are rejected unless allowed", "[scene][reject]") {
  // A vertical triangle piercing the floor triangle.
  const std::string piercing = doc("[" + tri + R"(,{"vertices": [["1/4","1/4",-1],["1/4","1/4",1],[2,2,0]], "triangles": [[0,1,2]]}])");
  REJECTED_AT(piercing, "/objects/0/triangles/0", "intersects the triangle at /objects/1/triangles/0");
  kvd::scene::Load_options allow;
  allow.allow_intersecting = true;
  CHECK(rejection(piercing, allow) == "");
  // Touching at a single point counts (different objects share nothing).
  REJECTED_AT(doc("[" + tri + R"(,{"vertices": [[1,0,0],[2,0,1],[2,1,1]], "triangles": [[0,1,2]]}])"),
              "/objects/0/triangles/0", "intersects");
  // Coplanar overlap.
  REJECTED_AT(doc("[" + tri + R"(,{"vertices": [["1/4","1/4",0],[3,0,0],[0,3,0]], "triangles": [[0,1,2]]}])"),
              "/objects/0/triangles/0", "intersects");
  // One object: a quad of two triangles sharing an edge is fine, and so is a
  // fan sharing a vertex; a folded pair overlapping beyond the edge is not.
  CHECK(rejection(doc(R"([{"vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]], "triangles": [[0,1,2],[0,2,3]]}])")) == "");
  CHECK(rejection(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0],[-1,0,1],[0,-1,1]], "triangles": [[0,1,2],[0,3,4]]}])")) == "");
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[1,1,0],[1,"1/2",0]], "triangles": [[0,1,2],[0,2,3]]}])"),
              "/objects/0/triangles/0", "intersects");
  // Sharing a vertex while crossing elsewhere.
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[2,0,0],[0,2,0],[1,1,-1],[1,1,1]], "triangles": [[0,1,2],[0,3,4]]}])"),
              "/objects/0/triangles/0", "intersects");
  // Two vertices at the same place but with different ids are not shared.
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,0],[-1,0,0],[0,-1,0]], "triangles": [[0,1,2],[3,4,5]]}])"),
              "/objects/0/triangles/0", "intersects");
}

TEST_CASE("numbers up to the digit cap load exactly, longer ones are refused", "[scene][reject]") {
  const std::string big(kvd::scene::max_digits - 1, '7');
  const auto s = read_scene(doc("[" + tri + "]", R"("time": {"start": ")" + big + R"(/3"}, )"), "big.json");
  CHECK(s.start == mpq_class(mpz_class(big), 3));
  const std::string longer(kvd::scene::max_digits + 1, '7');
  REJECTED_AT(doc("[" + tri + "]", R"("time": {"start": ")" + longer + R"("}, )"), "/time/start", "more than 10001 digits");
  REJECTED_AT(doc("[" + tri + "]", R"("time": {"start": "1.)" + longer + R"("}, )"), "/time/start", "digits");
  REJECTED_AT(doc("[" + tri + "]", R"("time": {"start": "1/)" + longer + R"("}, )"), "/time/start", "digits");
  // A million digits are refused before any arithmetic, quoted by their start.
  const std::string message = rejection(doc("[" + tri + "]", R"("time": {"start": ")" + std::string(1000000, '9') + R"("}, )"));
  CHECK(message.find("more than 10001 digits") != std::string::npos);
  CHECK(message.size() < 200);
}

TEST_CASE("motion polynomials above the degree cap are refused", "[scene][reject]") {
  const auto translation = [](std::size_t coefficients) {
    std::string c = "[";
    for (std::size_t i = 0; i < coefficients; ++i) c += i ? ",0" : "1";
    return doc("[" + tri + R"(,{"vertices": [[0,0,5],[1,0,5],[0,1,5]], "triangles": [[0,1,2]], "motion": {"translation": [)" +
               c + R"(], 0, 0]}}])");
  };
  CHECK(rejection(translation(kvd::scene::max_motion_degree + 1)) == "");
  REJECTED_AT(translation(kvd::scene::max_motion_degree + 2), "/objects/1/motion/translation/0", "at most 32");
  REJECTED_AT(translation(5001), "/objects/1/motion/translation/0", "5001 coefficients");
}

TEST_CASE("a point reaching infinity or a triangle flattening inside the span is rejected", "[scene][reject]") {
  // W = 1 - t: the mover passes through infinity at t = 1.
  const std::string w_vanishing = R"(,{"vertices": [[0,0,5],[1,0,5],[0,1,5]], "triangles": [[0,1,2]],
      "motion": {"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,[1,-1]]]}}])";
  REJECTED_AT(doc("[" + tri + w_vanishing, R"("time": {"start": 0, "end": 2}, )"), "/objects/1/vertices/0",
              "W vanishes at t = 1, inside the time span");
  // Without an end the whole future counts; the span's end itself counts.
  REJECTED_AT(doc("[" + tri + w_vanishing), "/objects/1/vertices/0", "W vanishes at t = 1, after the start");
  REJECTED_AT(doc("[" + tri + w_vanishing, R"("time": {"start": 0, "end": 1}, )"), "/objects/1/vertices/0", "t = 1,");
  CHECK(rejection(doc("[" + tri + w_vanishing, R"("time": {"start": 0, "end": "99/100"}, )")) == "");
  // An irrational instant, and a double root (W = (t - 1)^2 + 0 touches zero without changing sign).
  REJECTED_AT(doc("[" + tri + R"(,{"vertices": [[0,0,5],[1,0,5],[0,1,5]], "triangles": [[0,1,2]],
      "motion": {"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,[2,0,-1]]]}}])"),
              "/objects/1/vertices/0", "root of [2, 0, -1] in (1, 2) (about 1.41421356237309");
  REJECTED_AT(doc("[" + tri + R"(,{"vertices": [[0,0,5],[1,0,5],[0,1,5]], "triangles": [[0,1,2]],
      "motion": {"matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,[1,-2,1]]]}}])"),
              "/objects/1/vertices/0", "W vanishes at t = 1,");
  // A Euclidean decomposition point likewise.
  REJECTED_AT(doc("[" + tri + "]", R"("decomposition": {"z": [0, 0, 50, [1, -1]]}, )"), "/decomposition/z", "W vanishes at t = 1");
  REJECTED_AT(doc("[" + tri + "]", R"("decomposition": {"z": [0, 0, 50, [0, 1]]}, )"), "/decomposition/z", "zero at the start time");
  // A triangle whose third vertex reaches the line of the other two at t = 1/2.
  REJECTED_AT(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]],
      "motion": {"vertices": [[0,0,0,1],[1,0,0,1],[0,[1,-2],0,1]]}}])"),
              "/objects/0/triangles/0", "become collinear at t = 1/2");
  // A triangle that only rotates never flattens.
  CHECK(rejection(doc(R"([{"vertices": [[0,0,0],[1,0,0],[0,1,0]], "triangles": [[0,1,2]],
      "motion": {"matrix": [[[1,0,-1],[0,-2],0,0],[[0,2],[1,0,-1],0,0],[0,0,[1,0,1],0],[0,0,0,[1,0,1]]]}}])")) == "");
}
