// Generators of degenerate scenes: axis-aligned boxes, and a rotor.
#include "generator_support.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/detail/scene/priority.hpp"

namespace kvd::scene {

namespace {

// Adds an object made of the given vertices and triangles (local indices).
Object& add_object(Scene& s, const std::vector<QPoint>& vertices, const std::vector<std::array<std::size_t, 3>>& tris) {
  Object o;
  o.first_vertex = s.rest.size();
  o.vertex_count = vertices.size();
  o.first_triangle = s.triangles.size();
  o.triangle_count = tris.size();
  s.rest.insert(s.rest.end(), vertices.begin(), vertices.end());
  for (const auto& t : tris) s.triangles.push_back({o.first_vertex + t[0], o.first_vertex + t[1], o.first_vertex + t[2]});
  s.objects.push_back(o);
  return s.objects.back();
}

// The 12 triangles of a box with vertices indexed x + 2y + 4z, outward normals.
const std::vector<std::array<std::size_t, 3>> box_triangles = {
    {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};

}  // namespace

Scene boxes(std::size_t count, const Q& moving, std::uint64_t seed) {
  if (moving < 0 || moving > 1) throw Generator_error("--moving must be a fraction in [0, 1]");
  Split_mix64 g(seed);
  Scene s = empty_scene("boxes-" + std::to_string(count), seed);
  // Boxes in cells 4 units apart, all standing on z = 0; widths, depths and
  // heights in {1, 2, 3}, so gaps are at least 1 and coordinates repeat.
  std::size_t side = 1;
  while (side * side < count) ++side;
  for (std::size_t b = 0; b < count; ++b) {
    const long x0 = 4 * static_cast<long>(b % side), y0 = 4 * static_cast<long>(b / side);
    const long w = g.between(1, 3), d = g.between(1, 3), h = g.between(1, 3);
    std::vector<QPoint> v;
    for (long i = 0; i < 8; ++i) v.push_back({{Q(x0 + (i & 1) * w), Q(y0 + ((i >> 1) & 1) * d), Q(((i >> 2) & 1) * h), Q(1)}});
    add_object(s, v, box_triangles);
  }
  // Moving boxes rise or sink at speeds in {1/2, 1}: their faces stay parallel
  // to (and some coplanar with) the others' while they move.
  const std::vector<std::size_t> order = shuffled_ids(count, g.next());
  for (std::size_t k = 0; k < moving_count(moving, count); ++k) {
    Motion m;
    m.kind = Motion::Kind::translation;
    Q speed(g.between(1, 2), 2);
    speed.canonicalize();
    if (g.between(0, 1)) speed = -speed;
    m.translation = {QPoly(), QPoly(), QPoly{Q(0), speed}};
    s.objects[order[k]].motion = m;
  }
  s.derive();
  return s;
}

Scene rotor(std::size_t blades, std::uint64_t seed) {
  Split_mix64 g(seed);
  Scene s = empty_scene("rotor-" + std::to_string(blades), seed);
  add_object(s, {{{Q(-20), Q(-20), Q(-5), Q(1)}}, {{Q(20), Q(-20), Q(-5), Q(1)}}, {{Q(0), Q(20), Q(-5), Q(1)}}},
             {{0, 1, 2}});
  // Rotation by 2 atan(t) about z: exact and rational, degree 2.
  Motion spin;
  spin.kind = Motion::Kind::matrix;
  spin.matrix = {{{QPoly{1, 0, -1}, QPoly{0, -2}, QPoly(), QPoly()},
                  {QPoly{0, 2}, QPoly{1, 0, -1}, QPoly(), QPoly()},
                  {QPoly(), QPoly(), QPoly{1, 0, 1}, QPoly()},
                  {QPoly(), QPoly(), QPoly(), QPoly{1, 0, 1}}}};
  // Blades are horizontal triangles 2 units apart in height, each at a random
  // radius and angle offset (integers), so they turn in parallel planes and
  // never meet; their vertices cross each other's P- and E-planes.
  for (std::size_t b = 0; b < blades; ++b) {
    const long r = g.between(2, 9), a = g.between(-9, 9), c = g.between(-9, 9);
    const Q z(2 * static_cast<long>(b));
    // A right isosceles blade with legs r, its corner at (a, c).
    std::vector<QPoint> v{{{Q(a), Q(c), z, Q(1)}}, {{Q(a + r), Q(c), z, Q(1)}}, {{Q(a), Q(c + r), z, Q(1)}}};
    add_object(s, v, {{0, 1, 2}}).motion = spin;
  }
  s.derive();
  return s;
}

}  // namespace kvd::scene
