// The segment scene reader: JSON tree to Segment_scene, with every rejection
// of SEGMENT_FORMAT.md reported at its JSON place.
#include <algorithm>
#include <set>

#include "kvd/detail/scene/json_reader.hpp"
#include "kvd/detail/scene/span_check.hpp"
#include "kvd/segments/segment_io.hpp"

namespace kvd::segments {

namespace {

using scene::Json_value;
using Kind = Json_value::Kind;

class Reader : public scene::Json_reader {
public:
  using Json_reader::Json_reader;

  Segment_scene read(const Json_value& doc, const Segment_load_options& options) const;
  // `at`: the motion's JSON place, "" for a document of its own.
  Segment_motion read_motion(const Json_value& v, const std::string& at) const;

private:
  Point3 rest_point(const Json_value& v, const std::string& at) const;
  Motion_point3 point3(const Json_value& v, const std::string& at) const;
  Segment read_segment(const Json_value& v, const std::string& at) const;
  void read_priority(const Json_value& v, const std::string& at, Segment_scene& s) const;
  void check_geometry(const Segment_scene& s) const;
};

Point3 Reader::rest_point(const Json_value& v, const std::string& at) const {
  const auto& c = array(v, at);
  if (c.size() != 2 && c.size() != 3) fail(at, "expected [x, y] or a point3 [X, Y, W] of numbers");
  Point3 p{Q(0), Q(0), Q(1)};
  for (std::size_t k = 0; k < c.size(); ++k) p[k] = number(c[k], at + "/" + std::to_string(k));
  if (p[2] == 0) fail(at, "an endpoint must be a Euclidean point (W = 0 is a direction)");
  return p;
}

Motion_point3 Reader::point3(const Json_value& v, const std::string& at) const {
  const std::vector<QPoly> c = polys(v, at, 3);
  return {c[0], c[1], c[2]};
}

Segment_motion Reader::read_motion(const Json_value& v, const std::string& at) const {
  Segment_motion m;
  if (v.kind == Kind::null) return m;
  const std::string self = at.empty() ? "/" : at;
  expect_object(v, self, {"translation", "matrix", "endpoints"}, {});
  if (v.members.size() != 1) fail(self, "expected exactly one of \"translation\", \"matrix\", \"endpoints\"");
  const auto& [key, value] = v.members.front();
  const std::string here = at + "/" + key;
  if (key == "translation") {
    m.kind = Segment_motion::Kind::translation;
    const std::vector<QPoly> d = polys(value, here, 2);
    std::copy(d.begin(), d.end(), m.translation.begin());
  } else if (key == "matrix") {
    m.kind = Segment_motion::Kind::matrix;
    const auto rows = matrix(value, here, 3);
    for (std::size_t i = 0; i < 3; ++i) std::copy(rows[i].begin(), rows[i].end(), m.matrix[i].begin());
  } else {
    m.kind = Segment_motion::Kind::endpoints;
    const auto& items = array(value, here, 2);
    for (std::size_t k = 0; k < 2; ++k) m.endpoints[k] = point3(items[k], here + "/" + std::to_string(k));
  }
  return m;
}

Segment Reader::read_segment(const Json_value& v, const std::string& at) const {
  expect_object(v, at, {"name", "endpoints", "motion"}, {"endpoints"});
  Segment s;
  if (const auto* n = v.find("name")) {
    expect(*n, Kind::string, at + "/name");
    s.name = n->text;
  }
  const auto& ends = array(*v.find("endpoints"), at + "/endpoints", 2);
  for (std::size_t k = 0; k < 2; ++k) s.rest[k] = rest_point(ends[k], at + "/endpoints/" + std::to_string(k));
  if (const auto* m = v.find("motion")) s.motion = read_motion(*m, at + "/motion");
  return s;
}

void Reader::read_priority(const Json_value& v, const std::string& at, Segment_scene& s) const {
  expect_object(v, at, {"seed", "order"}, {});
  if (v.members.size() != 1) fail(at, "expected exactly one of \"seed\" and \"order\"");
  if (const auto* seed = v.find("seed")) {
    s.seed = unsigned_integer(*seed, at + "/seed");
    return;
  }
  const auto& items = array(*v.find("order"), at + "/order");
  std::vector<std::size_t> order;
  std::vector<bool> seen(s.segments.size(), false);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string here = at + "/order/" + std::to_string(i);
    const std::size_t id = index(items[i], here, s.segments.size(), "a segment");
    if (seen[id]) fail(here, "segment listed twice");
    seen[id] = true;
    order.push_back(id);
  }
  if (order.size() != s.segments.size())
    fail(at + "/order", "lists " + std::to_string(order.size()) + " of the " + std::to_string(s.segments.size()) +
                            " segments (every segment exactly once)");
  s.order = std::move(order);
}

void Reader::check_geometry(const Segment_scene& s) const {
  const std::string span = scene::span_text(s.end);
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    const std::string at = "/segments/" + std::to_string(i);
    const bool moving = s.is_moving(i);
    // An `endpoints` motion gives the points; otherwise the rest positions do.
    const std::string ends =
        at + (s.segments[i].motion.kind == Segment_motion::Kind::endpoints ? "/motion/endpoints/" : "/endpoints/");
    const std::array<Motion_point3, 2> p{s.endpoint(2 * i), s.endpoint(2 * i + 1)};
    for (std::size_t k = 0; k < 2; ++k) {
      const QPoly& w = p[k][2];
      if (w(s.start) == 0)
        fail(ends + std::to_string(k), "this endpoint's W is zero at the start time (it must stay a Euclidean point)");
      if (!moving) continue;
      if (const auto t = scene::first_zero(w, s.start, s.end))
        fail(ends + std::to_string(k), "this endpoint's W vanishes" + scene::instant_text(*t) + ", " + span +
                                           ": the point passes through infinity (end the span before it)");
    }
    // The endpoints coincide exactly when both cross differences vanish.
    const QPoly dx = p[0][0] * p[1][2] - p[1][0] * p[0][2], dy = p[0][1] * p[1][2] - p[1][1] * p[0][2];
    if (dx(s.start) == 0 && dy(s.start) == 0) fail(at, "the segment has zero length at the start time");
    if (!moving) continue;
    if (const auto t = scene::first_common_zero({dx, dy}, s.start, s.end))
      fail(at, "the segment's endpoints coincide" + scene::instant_text(*t) + ", " + span);
  }
}

Segment_scene Reader::read(const Json_value& doc, const Segment_load_options& options) const {
  // The format before the keys: a scene of triangles is told so, not that
  // "objects" is an unknown key.
  const Json_value* format = doc.kind == Kind::object ? doc.find("format") : nullptr;
  if (format && (format->kind != Kind::string || format->text != "kvd-segments/1"))
    fail("/format", "unknown format (expected the string \"kvd-segments/1\")");
  expect_object(doc, "", {"format", "name", "time", "priority", "segments"}, {"format", "segments"});
  Segment_scene s;
  if (const auto* n = doc.find("name")) {
    expect(*n, Kind::string, "/name");
    s.name = n->text;
  }
  if (const auto* t = doc.find("time")) {
    expect_object(*t, "/time", {"start", "end"}, {});
    if (const auto* st = t->find("start")) s.start = number(*st, "/time/start");
    if (const auto* en = t->find("end")) s.end = number(*en, "/time/end");
    if (s.end && !(s.start < *s.end)) fail("/time", "time.start must be less than time.end");
  }
  const auto& segments = array(*doc.find("segments"), "/segments");
  if (segments.empty()) fail("/segments", "a scene needs at least one segment");
  std::set<std::string> names;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string at = "/segments/" + std::to_string(i);
    s.segments.push_back(read_segment(segments[i], at));
    const std::string& n = s.segments.back().name;
    if (!n.empty() && !names.insert(n).second) fail(at + "/name", "segment name \"" + n + "\" is used twice");
  }
  if (const auto* p = doc.find("priority")) read_priority(*p, "/priority", s);
  if (options.seed) {
    s.seed = *options.seed;
    s.order.reset();
  }
  s.derive();
  check_geometry(s);
  return s;
}

Json_value parsed(const std::string& text, const std::string& source) {
  Json_value doc;
  std::string error;
  if (!scene::parse_json(text, doc, error)) throw scene::Scene_error(source + ": " + error);
  return doc;
}

}  // namespace

Segment_scene read_segments(const std::string& text, const std::string& source, const Segment_load_options& options) {
  return Reader(source).read(parsed(text, source), options);
}

Segment_motion read_segment_motion(const std::string& text, const std::string& source) {
  return Reader(source).read_motion(parsed(text, source), "");
}

Segment_scene load_segments(const std::string& path, const Segment_load_options& options) {
  return read_segments(scene::read_input(path), scene::input_name(path), options);
}

std::string scene_format(const std::string& text) { return scene::top_level_string(text, "format"); }

}  // namespace kvd::segments
