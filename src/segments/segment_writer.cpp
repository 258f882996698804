// The segment scene writer: numbers as exact strings, polynomials as arrays
// (a constant as a plain number string), keys in the order of SEGMENT_FORMAT.md.
#include "../scene/json_writer.hpp"
#include "kvd/segments/segment_io.hpp"

namespace kvd::segments {

namespace {

using scene::Json_out;
using scene::number_json;
using scene::poly_json;

Json_out point3(const Motion_point3& p) { return Json_out::array({poly_json(p[0]), poly_json(p[1]), poly_json(p[2])}); }

Json_out motion(const Segment_motion& m) {
  switch (m.kind) {
    case Segment_motion::Kind::none: return nullptr;
    case Segment_motion::Kind::translation:
      return Json_out{{"translation", Json_out::array({poly_json(m.translation[0]), poly_json(m.translation[1])})}};
    case Segment_motion::Kind::matrix: {
      Json_out rows = Json_out::array();
      for (const auto& row : m.matrix) rows.push_back(point3(row));
      return Json_out{{"matrix", rows}};
    }
    case Segment_motion::Kind::endpoints:
      return Json_out{{"endpoints", Json_out::array({point3(m.endpoints[0]), point3(m.endpoints[1])})}};
  }
  return nullptr;
}

// A rest position as [x, y] when W = 1, [X, Y, W] otherwise.
Json_out rest(const Point3& p) {
  if (p[2] == 1) return Json_out::array({number_json(p[0]), number_json(p[1])});
  return Json_out::array({number_json(p[0]), number_json(p[1]), number_json(p[2])});
}

}  // namespace

std::string write_segments(const Segment_scene& s) {
  Json_out doc;
  doc["format"] = "kvd-segments/1";
  if (!s.name.empty()) doc["name"] = s.name;
  Json_out time{{"start", number_json(s.start)}};
  if (s.end) time["end"] = number_json(*s.end);
  doc["time"] = time;
  if (s.order) doc["priority"] = Json_out{{"order", *s.order}};
  else doc["priority"] = Json_out{{"seed", s.seed}};
  Json_out segments = Json_out::array();
  for (const Segment& g : s.segments) {
    Json_out j;
    if (!g.name.empty()) j["name"] = g.name;
    j["endpoints"] = Json_out::array({rest(g.rest[0]), rest(g.rest[1])});
    if (g.motion.kind != Segment_motion::Kind::none) j["motion"] = motion(g.motion);
    segments.push_back(j);
  }
  doc["segments"] = segments;
  return scene::pretty_json(doc);
}

}  // namespace kvd::segments
