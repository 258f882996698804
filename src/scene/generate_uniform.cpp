// The thesis's uniform-scale and uniform-density data sets.
#include "generator_support.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/detail/scene/priority.hpp"
#include "kvd/detail/scene/triangle_intersection.hpp"

namespace kvd::scene {

namespace {

constexpr long box_side = 100;
// The base triangle (a scalene one, about 7 units across), before scaling.
const long base_triangle[3][2] = {{-3, -2}, {4, -1}, {0, 3}};
constexpr int max_attempts = 20000;

using Matrix3 = std::array<std::array<Q, 3>, 3>;

// The rotation of the unit quaternion q/|q| for integer q != 0: an exact
// rational orthogonal matrix (every rational rotation arises this way).
Matrix3 rotation(long a, long b, long c, long d) {
  const Q n = a * a + b * b + c * c + d * d;
  Matrix3 r = {{{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
                {2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)},
                {2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d}}};
  for (auto& row : r)
    for (auto& x : row) x /= n;
  return r;
}

Triangle3 place(const Q& scale, const Matrix3& r, const Vec3& centre) {
  Triangle3 t;
  for (std::size_t v = 0; v < 3; ++v)
    for (std::size_t i = 0; i < 3; ++i)
      t[v][i] = centre[i] + scale * (r[i][0] * base_triangle[v][0] + r[i][1] * base_triangle[v][1]);
  return t;
}

// The name records what fixes the scene (not the family: the two families
// give the same scene, byte for byte, at N = 100).
bool general_position(const Triangle3& t) {
  for (std::size_t i = 0; i < 3; ++i)
    if (t[0][i] == t[1][i] || t[1][i] == t[2][i] || t[0][i] == t[2][i]) return false;
  return true;
}

Scene uniform(const Uniform_params& p, const Q& scale) {
  if (p.moving < 0 || p.moving > 1) throw Generator_error("--moving must be a fraction in [0, 1]");
  if (p.degree < 1) throw Generator_error("--degree must be at least 1");
  Split_mix64 g(p.seed);
  Scene s = empty_scene("uniform N=" + std::to_string(p.triangles) + " scale=" + scale.get_str() +
                            " moving=" + p.moving.get_str() + " degree=" + std::to_string(p.degree) +
                            " seed=" + std::to_string(p.seed),
                        p.seed);
  std::vector<Triangle3> placed;
  for (std::size_t i = 0; i < p.triangles; ++i) {
    Triangle3 t;
    for (int attempt = 0;; ++attempt) {
      if (attempt == max_attempts)
        throw Generator_error("could not place triangle " + std::to_string(i) + " without intersections after " +
                              std::to_string(max_attempts) + " attempts: the box is too crowded");
      // Orientations in general position for the default directions: no two
      // vertices of a triangle share a coordinate (equal y would make their
      // P-cuts coincide, equal x and y an edge vertical).
      long q[4];
      Matrix3 r;
      do {
        for (long& c : q) c = g.between(-20, 20);
        if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) continue;
        r = rotation(q[0], q[1], q[2], q[3]);
      } while (!general_position(place(Q(1), r, Vec3{})));
      Vec3 centre;
      for (auto& c : centre) c = Q(g.between(0, 100 * box_side), 100);
      for (auto& c : centre) c.canonicalize();
      t = place(scale, r, centre);
      bool clear = true;
      for (std::size_t j = 0; j < placed.size() && clear; ++j) clear = !triangles_conflict(t, placed[j], {});
      if (clear) break;
    }
    placed.push_back(t);
    if (p.progress) p.progress(placed.size());
    Object o;
    o.first_vertex = s.rest.size();
    o.vertex_count = 3;
    o.first_triangle = s.triangles.size();
    o.triangle_count = 1;
    for (const auto& v : t) s.rest.push_back({{v[0], v[1], v[2], Q(1)}});
    s.triangles.push_back({o.first_vertex, o.first_vertex + 1, o.first_vertex + 2});
    s.objects.push_back(o);
  }
  // The moving triangles: a seeded choice of round(moving * N) of them, each
  // translating by a random polynomial of the given degree (coefficients in
  // [-1, 1] with step 1/100, divided by k! for t^k so that speeds stay tame).
  const std::vector<std::size_t> order = shuffled_ids(p.triangles, g.next());
  for (std::size_t k = 0; k < moving_count(p.moving, p.triangles); ++k) {
    Motion m;
    m.kind = Motion::Kind::translation;
    for (auto& axis : m.translation) {
      std::vector<Q> c{Q(0)};
      long factorial = 1;
      for (int d = 1; d <= p.degree; ++d) {
        factorial *= d;
        Q coefficient(g.between(-100, 100), 100 * factorial);
        coefficient.canonicalize();
        c.push_back(coefficient);
      }
      axis = QPoly(std::move(c));
    }
    s.objects[order[k]].motion = m;
  }
  s.derive();
  return s;
}

}  // namespace

Scene uniform_scale(const Uniform_params& p) { return uniform(p, Q(1)); }

Scene uniform_density(const Uniform_params& p) {
  if (p.triangles == 0) return uniform(p, Q(1));
  // (100/N)^(1/3) rounded to the nearest k/1000, in integers: the largest k
  // with k^3 N <= 10^11, plus one if (k + 1/2)^3 N < 10^11. All triangles of
  // a scene share this exact scale, so they stay exactly congruent.
  const mpz_class n = static_cast<unsigned long>(p.triangles), target = mpz_class("100000000000");
  mpz_class k;
  mpz_class lower = target / n;
  mpz_root(k.get_mpz_t(), lower.get_mpz_t(), 3);  // close; adjust exactly below
  while (k * k * k * n > target) --k;
  while ((k + 1) * (k + 1) * (k + 1) * n <= target) ++k;
  if ((2 * k + 1) * (2 * k + 1) * (2 * k + 1) * n < 8 * target) ++k;
  Q scale(k, 1000);
  scale.canonicalize();
  return uniform(p, scale);
}

}  // namespace kvd::scene
