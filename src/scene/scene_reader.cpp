// The scene reader: JSON tree to Scene, with every rejection of the format
// page reported at its JSON place.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "kvd/detail/scene/json_reader.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/detail/scene/span_check.hpp"
#include "kvd/detail/scene/triangle_intersection.hpp"

namespace kvd::scene {

namespace {

using Kind = Json_value::Kind;

// The triangle scene's own parts; the shared ones come from Json_reader.
class Reader : public Json_reader {
public:
  using Json_reader::Json_reader;

  Motion_point point4(const Json_value& v, const std::string& at) const {
    const std::vector<QPoly> c = polys(v, at, 4);
    const Motion_point p{{c[0], c[1], c[2], c[3]}};
    if (p[0].is_zero() && p[1].is_zero() && p[2].is_zero() && p[3].is_zero())
      fail(at, "a point4 that is identically [0, 0, 0, 0]");
    return p;
  }

  Scene read(const Json_value& doc, const Load_options& options) const;

private:
  void read_object(const Json_value& v, const std::string& at, Scene& s) const;
  Motion read_motion(const Json_value& v, const std::string& at, std::size_t vertex_count) const;
  void read_priority(const Json_value& v, const std::string& at, Scene& s) const;
  void check_geometry(const Scene& s, const Load_options& options) const;
};

Motion Reader::read_motion(const Json_value& v, const std::string& at, std::size_t vertex_count) const {
  Motion m;
  if (v.kind == Kind::null) return m;
  expect_object(v, at, {"translation", "matrix", "vertices"}, {});
  if (v.members.size() != 1) fail(at, "expected exactly one of \"translation\", \"matrix\", \"vertices\"");
  const auto& [key, value] = v.members.front();
  const std::string here = at + "/" + key;
  if (key == "translation") {
    m.kind = Motion::Kind::translation;
    const std::vector<QPoly> d = polys(value, here, 3);
    std::copy(d.begin(), d.end(), m.translation.begin());
  } else if (key == "matrix") {
    m.kind = Motion::Kind::matrix;
    const auto rows = matrix(value, here, 4);
    for (std::size_t i = 0; i < 4; ++i) std::copy(rows[i].begin(), rows[i].end(), m.matrix[i].begin());
  } else {
    m.kind = Motion::Kind::vertices;
    const auto& items = array(value, here, vertex_count);
    for (std::size_t i = 0; i < items.size(); ++i) m.vertices.push_back(point4(items[i], here + "/" + std::to_string(i)));
  }
  return m;
}

void Reader::read_object(const Json_value& v, const std::string& at, Scene& s) const {
  expect_object(v, at, {"name", "vertices", "triangles", "motion"}, {"vertices", "triangles"});
  Object o;
  if (const auto* n = v.find("name")) {
    expect(*n, Kind::string, at + "/name");
    o.name = n->text;
  }
  o.first_vertex = s.rest.size();
  const auto& verts = array(*v.find("vertices"), at + "/vertices");
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const std::string here = at + "/vertices/" + std::to_string(i);
    const auto& c = array(verts[i], here);
    if (c.size() != 3 && c.size() != 4) fail(here, "expected [x, y, z] or a point4 [X, Y, Z, W] of numbers");
    QPoint p{{Q(0), Q(0), Q(0), Q(1)}};
    for (std::size_t k = 0; k < c.size(); ++k) p[static_cast<int>(k)] = number(c[k], here + "/" + std::to_string(k));
    if (p[3] == 0) fail(here, "a vertex must be a Euclidean point (W = 0 is a direction)");
    s.rest.push_back(p);
  }
  o.vertex_count = verts.size();
  o.first_triangle = s.triangles.size();
  const auto& tris = array(*v.find("triangles"), at + "/triangles");
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const std::string here = at + "/triangles/" + std::to_string(t);
    const auto& idx = array(tris[t], here, 3);
    std::array<std::size_t, 3> g;
    for (std::size_t k = 0; k < 3; ++k) g[k] = o.first_vertex + index(idx[k], here + "/" + std::to_string(k), verts.size(), "a vertex");
    if (g[0] == g[1] || g[1] == g[2] || g[0] == g[2]) fail(here, "a triangle with a repeated vertex");
    s.triangles.push_back(g);
  }
  o.triangle_count = tris.size();
  if (const auto* m = v.find("motion")) o.motion = read_motion(*m, at + "/motion", o.vertex_count);
  s.objects.push_back(std::move(o));
}

void Reader::read_priority(const Json_value& v, const std::string& at, Scene& s) const {
  expect_object(v, at, {"seed", "order"}, {});
  if (v.members.size() != 1) fail(at, "expected exactly one of \"seed\" and \"order\"");
  if (const auto* seed = v.find("seed")) {
    s.priority_spec.seed = unsigned_integer(*seed, at + "/seed");
    return;
  }
  const auto& items = array(*v.find("order"), at + "/order");
  std::vector<std::size_t> order;
  std::vector<bool> seen(s.triangles.size(), false);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string here = at + "/order/" + std::to_string(i);
    const auto& pair = array(items[i], here, 2);
    const std::size_t o = index(pair[0], here + "/0", s.objects.size(), "an object");
    const std::size_t t = s.objects[o].first_triangle +
                          index(pair[1], here + "/1", s.objects[o].triangle_count, "a triangle");
    if (seen[t]) fail(here, "triangle listed twice");
    seen[t] = true;
    order.push_back(t);
  }
  if (order.size() != s.triangles.size())
    fail(at + "/order", "lists " + std::to_string(order.size()) + " of the " + std::to_string(s.triangles.size()) +
                            " triangles (every triangle exactly once)");
  s.priority_spec.order = std::move(order);
}

// The place of triangle t in the file.
std::string triangle_place(const Scene& s, std::size_t t) {
  const std::size_t o = s.triangle_object[t];
  return "/objects/" + std::to_string(o) + "/triangles/" + std::to_string(t - s.objects[o].first_triangle);
}

void Reader::check_geometry(const Scene& s, const Load_options& options) const {
  const std::string span = span_text(s.end);
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const std::size_t o = s.vertex_object[v];
    const std::string here = "/objects/" + std::to_string(o) + "/vertices/" + std::to_string(v - s.objects[o].first_vertex);
    if (s.position_at(v, s.start)[3] == 0)
      fail(here, "this vertex's W is zero at the start time (it must stay a Euclidean point)");
    if (!s.is_moving(o)) continue;
    if (const auto t = first_zero(s.position(v)[3], s.start, s.end))
      fail(here, "this vertex's W vanishes" + instant_text(*t) + ", " + span +
                     ": the point passes through infinity (end the span before it)");
  }
  for (const auto& [point, here] : {std::pair{&s.x, "/decomposition/x"}, std::pair{&s.z, "/decomposition/z"}}) {
    const QPoly& w = (*point)[3];
    if (w.is_zero()) continue;  // a direction
    if (w(s.start) == 0)
      fail(here, "W is zero at the start time but not identically (a point is a direction at every time or none)");
    if (const auto t = first_zero(w, s.start, s.end))
      fail(here, "W vanishes" + instant_text(*t) + ", " + span +
                     ": the point passes through infinity (end the span before it)");
  }
  const std::vector<Triangle3> tri = triangles_at(s, s.start);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Vec3 u{tri[t][1][0] - tri[t][0][0], tri[t][1][1] - tri[t][0][1], tri[t][1][2] - tri[t][0][2]};
    const Vec3 w{tri[t][2][0] - tri[t][0][0], tri[t][2][1] - tri[t][0][1], tri[t][2][2] - tri[t][0][2]};
    if (u[1] * w[2] - u[2] * w[1] == 0 && u[2] * w[0] - u[0] * w[2] == 0 && u[0] * w[1] - u[1] * w[0] == 0)
      fail(triangle_place(s, t), "the triangle's vertices are collinear at the start time");
    if (!s.is_moving(s.triangle_object[t])) continue;
    // Collinear exactly when the plane through the three points vanishes.
    const auto& [i, j, k] = s.triangles[t];
    const Plane4<QPoly> plane = join(s.position(i), s.position(j), s.position(k));
    if (const auto when = first_common_zero({plane.c.begin(), plane.c.end()}, s.start, s.end))
      fail(triangle_place(s, t), "the triangle's vertices become collinear" + instant_text(*when) + ", " + span);
  }
  if (options.allow_intersecting) return;
  if (const auto c = first_conflict(s, tri))
    fail(triangle_place(s, c->first), "intersects the triangle at " + triangle_place(s, c->second) +
                                          " at the start time (pass --allow-intersecting to accept this)");
}

Scene Reader::read(const Json_value& doc, const Load_options& options) const {
  // The format before the keys: a document of another format (say
  // kvd-segments/2) is told its format is unknown, not that its keys are.
  // Any format but kvd-segments/1 comes here (scene_format).
  expect(doc, Kind::object, "");
  const Json_value* format = doc.find("format");
  if (!format) fail("", "missing required key \"format\" (\"kvd-scene/1\", or \"kvd-segments/1\" for segments)");
  if (format->kind != Kind::string || format->text != "kvd-scene/1")
    fail("/format", "unknown format (expected the string \"kvd-scene/1\", or \"kvd-segments/1\" for segments)");
  expect_object(doc, "", {"format", "name", "time", "decomposition", "priority", "objects"}, {"format", "objects"});
  Scene s;
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
  s.x = {{QPoly(1), QPoly(), QPoly(), QPoly()}};
  s.z = {{QPoly(), QPoly(), QPoly(1), QPoly()}};
  if (const auto* d = doc.find("decomposition")) {
    expect_object(*d, "/decomposition", {"x", "z"}, {});
    if (const auto* x = d->find("x")) s.x = point4(*x, "/decomposition/x");
    if (const auto* z = d->find("z")) s.z = point4(*z, "/decomposition/z");
    bool proportional = true;  // all 2x2 minors identically zero
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) proportional = proportional && (s.x[i] * s.z[j] - s.x[j] * s.z[i]).is_zero();
    if (proportional) fail("/decomposition", "x and z are the same projective point");
  }
  const auto& objects = array(*doc.find("objects"), "/objects");
  if (objects.empty()) fail("/objects", "a scene needs at least one object");
  std::set<std::string> names;
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const std::string at = "/objects/" + std::to_string(o);
    read_object(objects[o], at, s);
    const std::string& n = s.objects.back().name;
    if (!n.empty() && !names.insert(n).second) fail(at + "/name", "object name \"" + n + "\" is used twice");
  }
  if (const auto* p = doc.find("priority")) read_priority(*p, "/priority", s);
  if (options.seed) s.priority_spec = Priority_spec{*options.seed, std::nullopt};
  s.derive();
  check_geometry(s, options);
  return s;
}

}  // namespace

Scene read_scene(const std::string& text, const std::string& source, const Load_options& options) {
  Json_value doc;
  std::string error;
  if (!parse_json(text, doc, error)) throw Scene_error(source + ": " + error);
  return Reader(source).read(doc, options);
}

std::string input_name(const std::string& path) { return path == "-" ? "(stdin)" : path; }

std::string read_input(const std::string& path) {
  const std::string name = input_name(path);
  std::error_code ec;
  if (path != "-") {
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) throw Scene_error(name + ": no such file");
    if (std::filesystem::is_directory(status)) throw Scene_error(name + ": is a directory");
  }
  std::ifstream file;
  if (path != "-") {
    file.open(path, std::ios::binary);
    if (!file) throw Scene_error(name + ": cannot open the file");
  }
  std::istream& in = path == "-" ? std::cin : file;
  // Read in blocks and stop past the cap: the source may be a pipe of any size.
  std::string text;
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    text.append(block, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_file_bytes)
      throw Scene_error(name + ": larger than " + std::to_string(max_file_bytes >> 20) + " MiB; refused");
  }
  if (in.bad()) throw Scene_error(name + ": cannot read the file");
  return text;
}

Scene load_scene(const std::string& path, const Load_options& options) {
  return read_scene(read_input(path), input_name(path), options);
}

}  // namespace kvd::scene
