// The back-to-front order against an exact z-buffer: rays from the viewpoint
// through a grid of pixels; at every pixel the last fragment painted must be
// the nearest one hit, with depths compared exactly.
#include <catch2/catch.hpp>

#include "kvd/kernel/kernel.hpp"
#include "kvd/query/visibility.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"

using namespace kvd;
using V3 = std::array<mpq_class, 3>;

namespace {

scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }

V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
mpq_class dot3(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The ray parameter s > 0 where view + s d meets the closed convex polygon, if it does.
std::optional<mpq_class> hit(const V3& view, const V3& d, const std::vector<V3>& poly) {
  V3 n{0, 0, 0};
  for (std::size_t i = 1; i + 1 < poly.size() && n == V3{0, 0, 0}; ++i) n = cross(sub(poly[i], poly[0]), sub(poly[i + 1], poly[0]));
  const mpq_class nd = dot3(n, d);
  if (nd == 0) return std::nullopt;  // seen edge-on
  const mpq_class s = dot3(n, sub(poly[0], view)) / nd;
  if (s <= 0) return std::nullopt;
  const V3 x{view[0] + s * d[0], view[1] + s * d[1], view[2] + s * d[2]};
  // Inside: x on the same side of every edge (within the polygon's plane).
  int sign = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const int o = sgn(dot3(cross(sub(poly[(i + 1) % poly.size()], poly[i]), sub(x, poly[i])), n));
    if (o == 0) continue;
    if (sign != 0 && o != sign) return std::nullopt;
    sign = o;
  }
  return s;
}

// Returns how many pixels the reversed order would paint wrongly, to show
// that the check has teeth.
long check_order(const scene::Scene& s, const mpq_class& t, const V3& view, int resolution) {
  const Exact_kernel k;
  const predicates::Classifier<Exact_kernel> c(k, s);
  const tree::Kvd_tree tr = tree::build(c, Exact_time(t));
  const auto order = query::back_to_front(c, tr, Point4<mpq_class>{{view[0], view[1], view[2], mpq_class(1)}}, t);
  std::vector<std::vector<V3>> polys;
  for (int i : order) {
    std::vector<V3> p;
    for (const auto& v : std::get<tree::Triangle_fragment>(tr.nodes[static_cast<std::size_t>(i)].fragment).corners) {
      const auto x = c.position(v);
      const mpq_class w = x[3](t);
      p.push_back({x[0](t) / w, x[1](t) / w, x[2](t) / w});
    }
    polys.push_back(p);
  }
  // Look at the centroid of all vertices; the pixel grid spans the scene.
  V3 centre{0, 0, 0};
  mpq_class extent = 0;
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const auto p = s.position_at(v, t);
    for (int j = 0; j < 3; ++j) centre[static_cast<std::size_t>(j)] += p[j] / p[3] / static_cast<long>(s.rest.size());
  }
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const auto p = s.position_at(v, t);
    for (int j = 0; j < 3; ++j) extent = std::max(extent, mpq_class(abs(p[j] / p[3] - centre[static_cast<std::size_t>(j)])));
  }
  const V3 forward = sub(centre, view);
  V3 right = cross(forward, V3{0, 0, 1});
  if (right == V3{0, 0, 0}) right = cross(forward, V3{0, 1, 0});
  const V3 up = cross(right, forward);
  // Scale the image axes to about the scene's extent at the centre's distance.
  const mpq_class fr = extent / (abs(right[0]) + abs(right[1]) + abs(right[2]));
  const mpq_class fu = extent / (abs(up[0]) + abs(up[1]) + abs(up[2]));
  long pixels_hit = 0, wrong = 0, wrong_reversed = 0;
  for (int a = 0; a < resolution; ++a)
    for (int b = 0; b < resolution; ++b) {
      const mpq_class u = mpq_class(2 * a + 1 - resolution, resolution), w = mpq_class(2 * b + 1 - resolution, resolution);
      V3 d;
      for (std::size_t j = 0; j < 3; ++j) d[j] = forward[j] + u * fr * right[j] + w * fu * up[j];
      std::optional<mpq_class> nearest, first, last;
      for (const auto& p : polys)
        if (const auto h = hit(view, d, p)) {
          if (!first) first = h;
          last = h;
          if (!nearest || *h < *nearest) nearest = h;
        }
      if (!last) continue;
      ++pixels_hit;
      wrong += *last != *nearest;
      wrong_reversed += *first != *nearest;
    }
  INFO(pixels_hit << " pixels hit");
  CHECK(pixels_hit > 0);
  CHECK(wrong == 0);
  return wrong_reversed;
}

}  // namespace

TEST_CASE("back-to-front order agrees with an exact z-buffer", "[visibility]") {
  const struct {
    const char* scene;
    V3 view;
  } cases[] = {{"two-triangles.json", {3, -7, 9}},  {"cycle3.json", {1, 2, 30}},     {"cycle3.json", {-5, 4, -20}},
               {"viewpoint.json", {0, 0, 10}},      {"boxes.json", {-9, -7, 11}},    {"random-20.json", {15, -20, 12}},
               {"rotor.json", {2, 3, 8}},           {"uniform-scale-25.json", {-40, 150, 170}}};
  long reversed_wrong = 0;
  for (const auto& cs : cases) {
    INFO(cs.scene);
    const scene::Scene s = load(cs.scene);
    reversed_wrong += check_order(s, s.start, cs.view, 24);
    reversed_wrong += check_order(s, s.start + mpq_class(1, 2), cs.view, 16);
  }
  CHECK(reversed_wrong > 100);  // front-to-back painting is caught
}
