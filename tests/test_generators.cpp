// The scene generators: determinism, exact congruence, the density scaling,
// moving fractions and degrees, and the bundled data sets' reproducibility.
#include <catch2/catch.hpp>
#include <fstream>
#include <set>
#include <sstream>

#include "kvd/scene/generators.hpp"
#include "kvd/scene/scene_io.hpp"

using namespace kvd::scene;

namespace {

// The sorted squared edge lengths of triangle t at rest: equal for congruent triangles.
std::array<Q, 3> shape(const Scene& s, std::size_t t) {
  std::array<Q, 3> d;
  for (std::size_t e = 0; e < 3; ++e) {
    const QPoint& a = s.rest[s.triangles[t][e]];
    const QPoint& b = s.rest[s.triangles[t][(e + 1) % 3]];
    d[e] = 0;
    for (int i = 0; i < 3; ++i) d[e] += (a[i] - b[i]) * (a[i] - b[i]);
  }
  std::sort(d.begin(), d.end());
  return d;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("uniform scenes are deterministic and their triangles exactly congruent", "[generate]") {
  Uniform_params p;
  p.triangles = 60;
  p.seed = 5;
  const Scene a = uniform_scale(p), b = uniform_scale(p);
  CHECK(write_scene(a) == write_scene(b));
  p.seed = 6;
  CHECK(write_scene(uniform_scale(p)) != write_scene(a));
  std::set<std::array<Q, 3>> shapes;
  std::set<std::vector<QPoint>> orientations;
  for (std::size_t t = 0; t < a.triangles.size(); ++t) shapes.insert(shape(a, t));
  CHECK(shapes.size() == 1);
  // The generator's own output passes the loader's validation, disjointness included.
  CHECK(read_scene(write_scene(a), "generated") == a);
}

TEST_CASE("uniform-density scales by (100/N)^(1/3), rounded to 1/1000", "[generate]") {
  Uniform_params p;
  p.seed = 2;
  p.triangles = 100;
  CHECK(write_scene(uniform_density(p)) == write_scene(uniform_scale(p)));
  const auto edge_ratio = [&](std::size_t n) -> Q {  // not auto: GMP expressions would dangle
    p.triangles = n;
    return shape(uniform_density(p), 0)[0] / shape(uniform_scale(p), 0)[0];  // the square of the scale
  };
  CHECK(edge_ratio(800) == Q(1, 4));                 // (1/2)^2 exactly
  CHECK(edge_ratio(25) == Q(1587 * 1587) / 1000000);  // 4^(1/3) = 1.5874...
  CHECK(edge_ratio(200) == Q(794 * 794) / 1000000);   // 0.5^(1/3) = 0.7937...
}

TEST_CASE("moving fraction and motion degree are honoured", "[generate]") {
  Uniform_params p;
  p.triangles = 100;
  p.moving = Q(1, 10);
  p.degree = 3;
  const Scene s = uniform_scale(p);
  CHECK(s.moving_triangle_count() == 10);
  CHECK(s.max_motion_degree() == 3);
  // Static triangles come first in the priority order.
  for (std::size_t i = 0; i < 90; ++i) CHECK_FALSE(s.is_moving(s.triangle_object[s.priority_order[i]]));
  p.moving = 0;
  CHECK(uniform_scale(p).moving_triangle_count() == 0);
  p.moving = 2;
  CHECK_THROWS_AS(uniform_scale(p), Generator_error);
}

TEST_CASE("boxes share coordinates and have coplanar faces; rotor turns exactly", "[generate]") {
  const Scene b = boxes(16, Q(1, 4), 3);
  CHECK(b.triangles.size() == 16 * 12);
  CHECK(b.moving_triangle_count() == 4 * 12);
  // Every box stands on z = 0: bottom faces of different objects are coplanar.
  std::size_t on_floor = 0;
  for (const auto& p : b.rest) on_floor += p[2] == 0;
  CHECK(on_floor == 16 * 4);
  CHECK(read_scene(write_scene(b), "boxes") == b);
  const Scene r = rotor(4, 1);
  CHECK(r.max_motion_degree() == 2);
  CHECK(r.moving_triangle_count() == 4);
  // A quarter turn at t = 1: (x, y) -> (-y, x), with W = 1 + t^2 = 2.
  const QPoint rest = r.rest[3];
  CHECK(r.position_at(3, 1) == QPoint{{-2 * rest[1], 2 * rest[0], 2 * rest[2], Q(2)}});
  CHECK(read_scene(write_scene(r), "rotor") == r);
}

TEST_CASE("the bundled data sets regenerate byte for byte", "[generate][data]") {
  for (const char* family : {"uniform-scale", "uniform-density"})
    for (std::size_t n : {25, 50, 100}) {
      Uniform_params p;
      p.triangles = n;
      p.seed = 1;
      const Scene s = std::string(family) == "uniform-scale" ? uniform_scale(p) : uniform_density(p);
      const std::string path = std::string(KVD_SOURCE_DIR) + "/data/" + family + "-" + std::to_string(n) + ".json";
      INFO(path);
      CHECK(read_file(path) == write_scene(s));
    }
}
