#include "kvd/scene/mesh_io.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "kvd/detail/scene/exact_number.hpp"
#include "kvd/scene/scene_io.hpp"

namespace kvd::scene {

namespace {

// The words of one line, without its comment.
std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

class Mesh_reader {
public:
  explicit Mesh_reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw Scene_error(source_ + ": line " + std::to_string(line_) + ": " + what);
  }

  Q number(const std::string& text) const {
    std::string why;
    const auto q = parse_exact_number(text[0] == '+' ? text.substr(1) : text, why);
    if (!q) fail(why + ": \"" + (text.size() > 40 ? text.substr(0, 40) + "..." : text) + "\"");
    return *q;
  }

  // A count ("the number of WHAT") from its text: digits only, below 10^9.
  std::size_t count_of(const std::string& t, const char* what) const {
    if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos || t.size() > 9)
      fail(std::string("expected the number of ") + what + ", found \"" + t + "\"");
    return static_cast<std::size_t>(std::stoul(t));
  }

  // A 0-based index from its text; `count` is how many there are so far.
  std::size_t index(const std::string& text, std::size_t count, bool one_based) const {
    std::size_t end = 0;
    long long i = 0;
    try {
      i = std::stoll(text, &end);
    } catch (const std::exception&) {
      end = 0;
    }
    if (end == 0 || end != text.size()) fail("not a vertex index: \"" + text + "\"");
    // OBJ: 1-based, or negative counting back from the last vertex read.
    const long long k = one_based ? (i < 0 ? static_cast<long long>(count) + i : i - 1) : i;
    if (k < 0 || k >= static_cast<long long>(count) || (one_based && i == 0))
      fail("vertex index " + text + " out of range (" + std::to_string(count) + " vertices so far)");
    return static_cast<std::size_t>(k);
  }

  // Adds the polygon (global vertex ids) to the current object as a fan.
  void face(const std::vector<std::size_t>& corners) {
    if (corners.size() < 3) fail("a face needs at least three corners");
    for (std::size_t a = 0; a < corners.size(); ++a)
      for (std::size_t b = a + 1; b < corners.size(); ++b)
        if (corners[a] == corners[b]) fail("a face repeats a corner");
    if (objects_.empty()) objects_.push_back({});
    Mesh_object& o = objects_.back();
    std::array<std::size_t, 3> local{};
    for (std::size_t k = 2; k < corners.size(); ++k) {
      const std::size_t fan[3] = {corners[0], corners[k - 1], corners[k]};
      for (std::size_t c = 0; c < 3; ++c) local[c] = local_vertex(o, fan[c]);
      o.triangles.push_back(local);
    }
  }

  std::vector<Mesh_object> obj(const std::string& text) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      ++line_;
      const auto w = words(line);
      if (w.empty()) continue;
      const std::string& key = w[0];
      if (key == "v") {
        if (w.size() != 4 && w.size() != 5) fail("a vertex is 'v x y z' or 'v x y z w'");
        const Q weight = w.size() == 5 ? number(w[4]) : Q(1);
        if (weight == 0) fail("a vertex with w = 0 is a direction, not a point");
        vertices_.push_back({{number(w[1]), number(w[2]), number(w[3]), weight}});
      } else if (key == "f") {
        std::vector<std::size_t> corners;
        for (std::size_t i = 1; i < w.size(); ++i)
          corners.push_back(index(w[i].substr(0, w[i].find('/')), vertices_.size(), true));
        face(corners);
      } else if (key == "o" || key == "g") {
        start_object(w.size() > 1 ? line.substr(line.find(w[1])) : "");
      } else if (key == "l" || key == "p" || key == "curv" || key == "surf") {
        fail("'" + key + "' elements are not triangles");
      } else if (key != "vt" && key != "vn" && key != "vp" && key != "s" && key != "usemtl" && key != "mtllib") {
        fail("unknown statement '" + key + "'");
      }
    }
    return finish();
  }

  std::vector<Mesh_object> off(const std::string& text) {
    // The words of the file after "OFF", each with its line.
    std::vector<std::pair<std::string, std::size_t>> tokens;
    std::istringstream in(text);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) {
      ++n;
      for (const std::string& w : words(line)) tokens.emplace_back(w, n);
    }
    std::size_t at = 0;
    const auto next = [&]() -> const std::string& {
      if (at >= tokens.size()) {
        line_ = n;
        fail("the file ends early");
      }
      line_ = tokens[at].second;
      return tokens[at++].first;
    };
    const auto count = [&](const char* what) { return count_of(next(), what); };
    if (next() != "OFF") fail("an OFF file starts with 'OFF'");
    const std::size_t nv = count("vertices"), nf = count("faces");
    count("edges");
    for (std::size_t i = 0; i < nv; ++i) {
      const Q x = number(next()), y = number(next()), z = number(next());
      vertices_.push_back({{x, y, z, Q(1)}});
    }
    for (std::size_t f = 0; f < nf; ++f) {
      const std::size_t k = count("corners of a face");
      const std::size_t face_line = line_;
      std::vector<std::size_t> corners;
      for (std::size_t c = 0; c < k; ++c) corners.push_back(index(next(), vertices_.size(), false));
      // A colour may follow on the face's line.
      while (at < tokens.size() && tokens[at].second == face_line) ++at;
      face(corners);
    }
    if (at < tokens.size()) {
      line_ = tokens[at].second;
      fail("unexpected text after the last face");
    }
    return finish();
  }

  // ASCII PLY: the header declares elements and their properties; the data
  // has one line per element instance. Only vertex x, y, z and the faces'
  // index list are used; other elements and properties are skipped.
  std::vector<Mesh_object> ply(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    const auto next_line = [&]() -> std::vector<std::string> {
      if (!std::getline(in, line)) fail("the file ends early");
      ++line_;
      std::istringstream ws(line);
      std::vector<std::string> w;
      for (std::string x; ws >> x;) w.push_back(x);
      return w;
    };
    if (next_line() != std::vector<std::string>{"ply"}) fail("a PLY file starts with 'ply'");
    struct Element {
      std::string name;
      std::size_t count = 0;
      std::vector<std::string> properties;  // names; a list property is "list:NAME"
    };
    std::vector<Element> elements;
    for (;;) {
      const auto w = next_line();
      if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
      if (w[0] == "end_header") break;
      if (w[0] == "format") {
        if (w.size() < 2 || w[1] != "ascii") fail("only ASCII PLY is read (convert a binary one to ASCII)");
      } else if (w[0] == "element" && w.size() == 3) {
        elements.push_back({w[1], count_of(w[2], "elements"), {}});
      } else if (w[0] == "property" && !elements.empty() && w.size() == 3) {
        elements.back().properties.push_back(w[2]);
      } else if (w[0] == "property" && !elements.empty() && w.size() == 5 && w[1] == "list") {
        elements.back().properties.push_back("list:" + w[4]);
      } else {
        fail("unexpected header line \"" + line + "\"");
      }
    }
    for (const Element& e : elements) {
      const auto at = [&](const std::string& name) {
        const auto it = std::find(e.properties.begin(), e.properties.end(), name);
        return it == e.properties.end() ? e.properties.size() : static_cast<std::size_t>(it - e.properties.begin());
      };
      for (std::size_t i = 0; i < e.count; ++i) {
        const auto w = next_line();
        if (e.name == "vertex") {
          const std::size_t x = at("x"), y = at("y"), z = at("z");
          if (x == e.properties.size() || y == e.properties.size() || z == e.properties.size())
            fail("vertices need the properties x, y and z");
          if (w.size() != e.properties.size()) fail("a vertex has " + std::to_string(e.properties.size()) + " values");
          vertices_.push_back({{number(w[x]), number(w[y]), number(w[z]), Q(1)}});
        } else if (e.name == "face") {
          // The index list must be the face's first property.
          if (e.properties.empty() || (e.properties[0] != "list:vertex_indices" && e.properties[0] != "list:vertex_index"))
            fail("a face's first property must be the list vertex_indices");
          if (w.empty()) fail("an empty face line");
          const std::size_t k = count_of(w[0], "corners of a face");
          if (w.size() != k + 1) fail("a face declares " + w[0] + " corners and lists " + std::to_string(w.size() - 1));
          std::vector<std::size_t> corners;
          for (std::size_t c = 1; c <= k; ++c) corners.push_back(index(w[c], vertices_.size(), false));
          face(corners);
        }
      }
    }
    while (std::getline(in, line)) {
      ++line_;
      if (!words(line).empty()) fail("unexpected text after the last element");
    }
    return finish();
  }

private:
  std::size_t local_vertex(Mesh_object& o, std::size_t global) {
    auto [it, added] = local_.try_emplace(global, o.vertices.size());
    if (added) o.vertices.push_back(vertices_[global]);
    return it->second;
  }

  void start_object(std::string name) {
    if (!objects_.empty() && objects_.back().triangles.empty()) objects_.pop_back();
    objects_.push_back({std::move(name), {}, {}});
    local_.clear();
  }

  std::vector<Mesh_object> finish() {
    if (!objects_.empty() && objects_.back().triangles.empty()) objects_.pop_back();
    if (objects_.empty()) fail("no faces");
    return std::move(objects_);
  }

  std::string source_;
  std::size_t line_ = 0;
  std::vector<QPoint> vertices_;  // every vertex read, global ids
  std::vector<Mesh_object> objects_;
  std::map<std::size_t, std::size_t> local_;  // global id -> the current object's vertex
};

bool ends_with(const std::string& s, const std::string& tail) {
  if (s.size() < tail.size()) return false;
  std::string end = s.substr(s.size() - tail.size());
  for (char& c : end) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return end == tail;
}

}  // namespace

std::vector<Mesh_object> read_mesh(const std::string& text, const std::string& source) {
  Mesh_reader r(source);
  if (ends_with(source, ".obj")) return r.obj(text);
  if (ends_with(source, ".off")) return r.off(text);
  if (ends_with(source, ".ply")) return r.ply(text);
  throw Scene_error(source + ": unknown mesh format (expected a .obj, .off or .ply file)");
}

Scene mesh_scene(const std::vector<Mesh_object>& objects, const std::string& name) {
  Scene s;
  s.name = name;
  s.x = {{QPoly(1), QPoly(), QPoly(), QPoly()}};
  s.z = {{QPoly(), QPoly(), QPoly(1), QPoly()}};
  std::map<std::string, int> seen;
  for (const Mesh_object& m : objects) {
    Object o;
    // Object names must be unique: a repeated group name gets a suffix.
    const int n = seen[m.name]++;
    o.name = m.name.empty() || n == 0 ? m.name : m.name + "-" + std::to_string(n + 1);
    o.first_vertex = s.rest.size();
    o.vertex_count = m.vertices.size();
    o.first_triangle = s.triangles.size();
    o.triangle_count = m.triangles.size();
    s.rest.insert(s.rest.end(), m.vertices.begin(), m.vertices.end());
    for (const auto& t : m.triangles) s.triangles.push_back({o.first_vertex + t[0], o.first_vertex + t[1], o.first_vertex + t[2]});
    s.objects.push_back(std::move(o));
  }
  s.derive();
  return s;
}

Motion rotation_about_centroid(const Scene& s, std::size_t object, const std::array<Q, 3>& u) {
  const Object& o = s.objects[object];
  std::array<Q, 3> c{};
  for (std::size_t i = 0; i < o.vertex_count; ++i)
    for (int a = 0; a < 3; ++a) c[static_cast<std::size_t>(a)] += s.rest[o.first_vertex + i][a] / s.rest[o.first_vertex + i][3];
  for (Q& x : c) x /= static_cast<long>(o.vertex_count);
  const Q uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  const QPoly t{Q(0), Q(1)}, t2{Q(0), Q(0), Q(1)};
  const QPoly w = QPoly(Q(1)) + t2 * QPoly(uu);
  // N = (1 - t^2 |u|^2) I + 2 t^2 u u^T + 2 t [u]x, [u]x the cross-product matrix.
  const Q cross[3][3] = {{0, -u[2], u[1]}, {u[2], 0, -u[0]}, {-u[1], u[0], 0}};
  Motion m;
  m.kind = Motion::Kind::matrix;
  for (std::size_t i = 0; i < 3; ++i) {
    QPoly shift = w * QPoly(c[i]);
    for (std::size_t j = 0; j < 3; ++j) {
      QPoly n = t2 * QPoly(2 * u[i] * u[j]) + t * QPoly(2 * cross[i][j]);
      if (i == j) n += QPoly(Q(1)) - t2 * QPoly(uu);
      shift -= n * QPoly(c[j]);
      m.matrix[i][j] = n;
    }
    m.matrix[i][3] = shift;  // w c - N c: the centroid stays where it is
  }
  m.matrix[3] = {QPoly(), QPoly(), QPoly(), w};
  return m;
}

}  // namespace kvd::scene
