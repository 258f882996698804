#include "classify_filter.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "../kernel/interval.hpp"
#include "kvd/detail/flat_map.hpp"
#include "kvd/detail/geometry/plucker_impl.hpp"
#include "kvd/detail/symbolic/scene_geometry_impl.hpp"
#include "kvd/symbolic/incidence.hpp"

namespace kvd::predicates {

using filter::Interval;

namespace {

using Motion = std::array<std::vector<Interval>, 4>;  // a point's coordinates, coefficients as intervals

// The point scaled by one power of two (every sign stays), as intervals:
// after the shift every coefficient is within the filter's reach.
Motion enclose(const Point4<Poly<mpq_class>>& p) {
  const unsigned long shift = filter::shift_for(p.c);
  Motion m;
  for (int k = 0; k < 4; ++k) m[static_cast<std::size_t>(k)] = filter::enclose(p[k], shift).value();
  return m;
}

// The point at t; none when a coordinate exceeds filter::max_input.
std::optional<Point4<Interval>> at(const Motion& m, const Interval& t) {
  Point4<Interval> p;
  for (int k = 0; k < 4; ++k) {
    const auto v = filter::evaluate(m[static_cast<std::size_t>(k)], t);
    if (!v || !(v->upper() <= filter::max_input && v->lower() >= -filter::max_input)) return std::nullopt;
    p[k] = *v;
  }
  return p;
}

// Calls f with each scene vertex that the plane's (symbolic::for_each_vertex)
// or the point's coordinates are made from (scene_geometry_impl.hpp), besides
// x and z.
using symbolic::for_each_vertex;
template <class F>
void for_each_vertex(const scene::Scene& s, const symbolic::Symbolic_vertex& v, F&& f) {
  using P = symbolic::Symbolic_plane::Kind;
  symbolic::for_each_feature(
      v, f, [&](std::size_t e) { for_each_vertex(s, {P::E, e}, f); },
      [&](std::size_t t) { for_each_vertex(s, {P::T, t}, f); });
}

}  // namespace

struct Classification_filter::State {
  const scene::Scene* scene;
  std::vector<Motion> vertices;
  Motion x, z;
  // The geometry on the last instant's interval (valid for every instant in
  // it). Its vertices are evaluated when first needed at that instant, not
  // all at once: a batch classifies near a few sites, and a new instant
  // would otherwise cost the whole scene. `stamps[i]` is the epoch at which
  // vertex i was evaluated, negated when it was too large to filter.
  std::optional<Interval> instant;
  std::optional<symbolic::Scene_geometry<Interval>> positions;
  bool directions = false;  // x and z within the filter's reach at the instant
  std::vector<std::int64_t> stamps;
  // The last rational instant asked for, and its interval: most calls ask
  // again at the same instant, and converting it is not free.
  std::optional<mpq_class> last_rational;
  std::optional<Interval> last_enclosure;
  // The planes and derived points at the current instant, computed once:
  // a plane is valid while its stamp equals `epoch`, so that a new instant
  // costs nothing in the number of planes.
  std::int64_t epoch = 1;
  std::array<std::vector<std::pair<std::int64_t, Plane4<Interval>>>, 3> planes;  // by Symbolic_plane::Kind
  // The derived points met at the instant, in a direct-mapped cache: an
  // entry is valid while its stamp equals `epoch`, and a point that meets
  // an entry taken by another is computed again in its place. A build meets
  // every derived point of the tree at one instant (291,783 at 3200
  // triangles); a table of them all would have to be freed by the first
  // batch after it, and a new instant costs the cache nothing.
  struct Cached_point {
    std::int64_t stamp = 0;
    symbolic::Symbolic_vertex v{};
    Point4<Interval> at;
  };
  static constexpr int cache_bits = 15;
  std::vector<Cached_point> points = std::vector<Cached_point>(std::size_t{1} << cache_bits);

  std::optional<Interval> enclose(const Exact_time& t) {
    if (!t.is_rational()) return filter::enclose(t);
    if (!last_rational || *last_rational != t.rational()) {
      last_rational = t.rational();
      last_enclosure = filter::enclose(t.rational());
    }
    return last_enclosure;
  }

  // Whether vertex i is evaluated at the instant and within reach; inside a
  // Rounding_scope.
  bool evaluated(std::size_t i) {
    std::int64_t& stamp = stamps[i];
    if (stamp == epoch || stamp == -epoch) return stamp > 0;
    const auto p = at(vertices[i], *instant);
    stamp = p ? epoch : -epoch;
    if (p) positions->set_vertex(i, *p);
    return p.has_value();
  }
  template <class Feature>
  bool within_reach(const Feature& f) {
    bool all = true;
    for_each_vertex(*scene, f, [&](std::size_t i) { all = evaluated(i) && all; });
    return all;
  }

  // Inside a Rounding_scope, for features within reach.
  const Plane4<Interval>& plane(const symbolic::Symbolic_plane& p) {
    auto& of_kind = planes[static_cast<std::size_t>(p.kind)];
    if (of_kind.size() <= p.id) of_kind.resize(p.id + 1);
    auto& [stamp, plane] = of_kind[p.id];
    if (stamp != epoch) {
      plane = positions->plane(p);
      stamp = epoch;
    }
    return plane;
  }
  const Point4<Interval>& point(const symbolic::Symbolic_vertex& v) {
    if (v.kind == symbolic::Symbolic_vertex::Kind::endpoint) return positions->vertex(v.ids[0]);
    Cached_point& c = points[kvd::detail::fibonacci_slot(symbolic::Symbolic_hash()(v), cache_bits)];
    if (c.stamp != epoch || c.v != v) c = {epoch, v, positions->point(v)};
    return c.at;
  }

  void move_to(const Interval& t) {
    if (instant && instant->lower() == t.lower() && instant->upper() == t.upper()) return;
    instant = t;
    ++epoch;
    const filter::Rounding_scope upward;
    auto px = at(x, t), pz = at(z, t);
    directions = px && pz;
    if (directions) positions->set_directions(*px, *pz);
  }
};

Classification_filter::Classification_filter(const symbolic::Scene_geometry<Poly<mpq_class>>& motion)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.scene = &motion.scene();
  s.x = enclose(motion.x());
  s.z = enclose(motion.z());
  for (const auto& p : motion.vertices()) s.vertices.push_back(enclose(p));
  s.stamps.assign(s.vertices.size(), 0);
  s.positions.emplace(*s.scene, std::vector<Point4<Interval>>(s.vertices.size()), Point4<Interval>{}, Point4<Interval>{});
}

Classification_filter::~Classification_filter() = default;

int Classification_filter::side(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p,
                                const Exact_time& t) {
  State& s = *state_;
  const auto when = s.enclose(t);
  if (!when) return 0;
  s.move_to(*when);
  const filter::Rounding_scope upward;
  if (!s.directions || !s.within_reach(p) || !s.within_reach(v)) return 0;
  const Point4<Interval>& x = s.point(v);
  const int value = filter::sign(dot(s.plane(p), x));
  // A scene vertex has W > 0 (scene_geometry.hpp); a derived one needs its sign.
  const int w = v.kind == symbolic::Symbolic_vertex::Kind::endpoint ? 1 : filter::sign(x[3]);
  return value * w;
}

}  // namespace kvd::predicates
