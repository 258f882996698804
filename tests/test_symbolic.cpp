// Symbolic geometry: incidence by construction is sound (the predicted
// incidences vanish identically in t) and, on scenes in general position,
// complete; evaluation at an instant commutes with the motion polynomials.
#include <catch2/catch.hpp>

#include <optional>
#include <string>

#include "kvd/geometry/plucker.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/symbolic/incidence.hpp"
#include "kvd/symbolic/scene_geometry.hpp"
#include "symbolic_samples.hpp"

using namespace kvd;
using namespace kvd::symbolic;

namespace {
scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }
bool is_zero_point(const Point4<Poly<mpq_class>>& p) {
  return p[0].is_zero() && p[1].is_zero() && p[2].is_zero() && p[3].is_zero();
}
}  // namespace

TEST_CASE("what lies on a plane by construction vanishes identically in t", "[symbolic]") {
  for (const char* name : {"two-triangles.json", "cycle3.json", "viewpoint.json", "boxes.json", "rotor.json", "random-20.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    const bool z_euclidean = !s.z[3].is_zero();
    const auto g = motion_geometry<mpq_class>(s);
    long on = 0, checked = 0;
    for (const auto& v : kvd::test::sample_vertices(s, z_euclidean)) {
      const auto x = g.point(v);
      if (is_zero_point(x)) continue;  // an ill-defined meet (parallel planes): no incidence to check
      for (const auto& p : kvd::test::all_planes(s)) {
        ++checked;
        if (!on_by_construction(s, v, p, z_euclidean)) continue;
        ++on;
        INFO(to_string(v) << " on " << to_string(p));
        CHECK(dot(g.plane(p), x).is_zero());
      }
    }
    CHECK(on > 0);
    CHECK(checked > on);
  }
}

TEST_CASE("in general position nothing else vanishes identically", "[symbolic]") {
  const scene::Scene s = load("random-20.json");
  const auto g = motion_geometry<mpq_class>(s);
  long pairs = 0, spurious = 0;
  for (const auto& v : kvd::test::sample_vertices(s, false)) {
    const auto x = g.point(v);
    if (is_zero_point(x)) continue;
    for (const auto& p : kvd::test::all_planes(s)) {
      if (on_by_construction(s, v, p, false)) continue;
      ++pairs;
      if (dot(g.plane(p), x).is_zero()) {
        ++spurious;
        UNSCOPED_INFO(to_string(v) << " on " << to_string(p) << " without a reason");
      }
    }
  }
  CHECK(pairs > 1000);
  CHECK(spurious == 0);
}

TEST_CASE("the geometry at an instant is the motion evaluated there", "[symbolic]") {
  const scene::Scene s = load("viewpoint.json");
  const auto g = motion_geometry<mpq_class>(s);
  const mpq_class t(3, 7);
  const auto gt = at_instant(g, t);
  for (const auto& v : kvd::test::sample_vertices(s, true))
    for (const auto& p : kvd::test::all_planes(s)) CHECK(dot(g.plane(p), g.point(v))(t) == dot(gt.plane(p), gt.point(v)));
  // Scene vertices are scaled to W > 0.
  for (const auto& p : g.vertices()) CHECK(p[3](s.start) > 0);
}

TEST_CASE("P-planes of the default directions have +y on their positive side", "[symbolic]") {
  const scene::Scene s = load("single-triangle.json");
  const auto g = at_instant(motion_geometry<mpq_class>(s), mpq_class(0));
  const auto m = g.plane({Symbolic_plane::Kind::P, 0});
  Point4<mpq_class> above = g.vertex(0);
  above[1] += above[3];  // one unit further along +y
  CHECK(dot(m, above) > 0);
}

// The exact field's vertices are the scene's scaled by a positive rational to
// primitive integer coefficients (signs kept, GMP spared its gcds); the
// floating-point fields keep the scene's numbers.
TEST_CASE("exact vertices are positive multiples of the scene's with primitive integer coefficients", "[symbolic]") {
  for (const char* name : {"uniform-scale-25.json", "viewpoint.json", "rotor.json", "random-20.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    const auto g = motion_geometry<mpq_class>(s);
    const auto d = motion_geometry<double>(s);
    long scaled = 0;
    for (std::size_t i = 0; i < s.rest.size(); ++i) {
      const scene::Motion_point p = s.position(i);
      const Point4<Poly<mpq_class>>& x = g.vertex(i);
      mpz_class content = 0;
      std::optional<mpq_class> factor;  // x = factor * p, coordinate by coordinate
      for (int k = 0; k < 4; ++k) {
        REQUIRE(x[k].coefficients().size() == p[k].coefficients().size());
        for (std::size_t j = 0; j < x[k].coefficients().size(); ++j) {
          const mpq_class& c = x[k].coefficients()[j];
          CHECK(c.get_den() == 1);
          mpz_gcd(content.get_mpz_t(), content.get_mpz_t(), c.get_num_mpz_t());
          const mpq_class& q = p[k].coefficients()[j];
          if (q == 0) {
            CHECK(c == 0);
            continue;
          }
          const mpq_class f = c / q;
          if (!factor) factor = f;
          CHECK(f == *factor);
        }
        for (std::size_t j = 0; j < p[k].coefficients().size(); ++j)
          CHECK(d.vertex(i)[k].coefficients()[j] == from_rational<double>(p[k].coefficients()[j]));
      }
      REQUIRE(factor);
      CHECK(*factor > 0);
      CHECK(content == 1);
      scaled += *factor != 1;
    }
    // The generated scene has rational coordinates: they were scaled.
    if (std::string(name) == "uniform-scale-25.json") CHECK(scaled > 0);
  }
}
