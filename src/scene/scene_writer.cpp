// The scene writer: numbers as exact strings, polynomials as arrays (a
// constant as a plain number string), keys in the order of the format page.
#include "json_writer.hpp"
#include "kvd/scene/scene_io.hpp"

namespace kvd::scene {

namespace {

using J = Json_out;

J point4(const Motion_point& p) {
  return J::array({poly_json(p[0]), poly_json(p[1]), poly_json(p[2]), poly_json(p[3])});
}

J motion(const Motion& m) {
  switch (m.kind) {
    case Motion::Kind::none: return nullptr;
    case Motion::Kind::translation:
      return J{{"translation",
                J::array({poly_json(m.translation[0]), poly_json(m.translation[1]), poly_json(m.translation[2])})}};
    case Motion::Kind::matrix: {
      J rows = J::array();
      for (const auto& row : m.matrix)
        rows.push_back(J::array({poly_json(row[0]), poly_json(row[1]), poly_json(row[2]), poly_json(row[3])}));
      return J{{"matrix", rows}};
    }
    case Motion::Kind::vertices: {
      J vs = J::array();
      for (const auto& v : m.vertices) vs.push_back(point4(v));
      return J{{"vertices", vs}};
    }
  }
  return nullptr;
}

}  // namespace

std::string write_motion(const Motion& m) { return motion(m).dump(); }

std::string write_scene(const Scene& s) {
  J doc;
  doc["format"] = "kvd-scene/1";
  if (!s.name.empty()) doc["name"] = s.name;
  J time{{"start", number_json(s.start)}};
  if (s.end) time["end"] = number_json(*s.end);
  doc["time"] = time;
  doc["decomposition"] = J{{"x", point4(s.x)}, {"z", point4(s.z)}};
  if (s.priority_spec.order) {
    J order = J::array();
    for (std::size_t t : *s.priority_spec.order) {
      const std::size_t o = s.triangle_object.at(t);
      order.push_back(J::array({o, t - s.objects[o].first_triangle}));
    }
    doc["priority"] = J{{"order", order}};
  } else {
    doc["priority"] = J{{"seed", s.priority_spec.seed}};
  }
  J objects = J::array();
  for (const auto& o : s.objects) {
    J obj;
    if (!o.name.empty()) obj["name"] = o.name;
    J verts = J::array();
    for (std::size_t v = o.first_vertex; v < o.first_vertex + o.vertex_count; ++v) {
      const QPoint& p = s.rest[v];
      if (p[3] == 1) verts.push_back(J::array({number_json(p[0]), number_json(p[1]), number_json(p[2])}));
      else verts.push_back(J::array({number_json(p[0]), number_json(p[1]), number_json(p[2]), number_json(p[3])}));
    }
    obj["vertices"] = verts;
    J tris = J::array();
    for (std::size_t t = o.first_triangle; t < o.first_triangle + o.triangle_count; ++t)
      tris.push_back(J::array({s.triangles[t][0] - o.first_vertex, s.triangles[t][1] - o.first_vertex,
                               s.triangles[t][2] - o.first_vertex}));
    obj["triangles"] = tris;
    if (o.motion.kind != Motion::Kind::none) obj["motion"] = motion(o.motion);
    objects.push_back(obj);
  }
  doc["objects"] = objects;
  return pretty_json(doc);
}

}  // namespace kvd::scene
