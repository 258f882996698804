#include "kvd/scene/scene.hpp"

#include <algorithm>
#include <map>

#include "kvd/detail/scene/priority.hpp"

namespace kvd::scene {

QPoint evaluate(const Motion_point& p, const Q& t) { return {{p[0](t), p[1](t), p[2](t), p[3](t)}}; }

QPoly shifted(const QPoly& p, const Q& shift) {
  // Horner in the polynomial ring: p(t + shift) = (...(c_n (t+shift) + c_{n-1}) ...).
  const QPoly x{shift, Q(1)};
  QPoly r;
  for (auto it = p.coefficients().rbegin(); it != p.coefficients().rend(); ++it) r = r * x + QPoly(*it);
  return r;
}

namespace {
// Every polynomial of a motion replaced by f(polynomial).
template <class F>
void map_polynomials(Motion& m, F f) {
  for (auto& c : m.translation) c = f(c);
  for (auto& row : m.matrix)
    for (auto& c : row) c = f(c);
  for (auto& v : m.vertices)
    for (auto& c : v.c) c = f(c);
}
}  // namespace

Scene retimed(const Scene& s, const Q& shift) {
  Scene r = s;
  const auto shift_by = [&](const QPoly& p) { return shifted(p, shift); };
  r.start = s.start - shift;
  if (s.end) r.end = *s.end - shift;
  for (auto& c : r.x.c) c = shifted(c, shift);
  for (auto& c : r.z.c) c = shifted(c, shift);
  for (auto& o : r.objects) map_polynomials(o.motion, shift_by);
  r.derive();
  return r;
}

Motion reversed(const Motion& m, const Q& r) {
  // p(2r - t) = q(-t) for q(u) = p(u + 2r): q with its odd coefficients negated.
  Motion out = m;
  map_polynomials(out, [&](const QPoly& p) {
    std::vector<Q> c = shifted(p, 2 * r).coefficients();
    for (std::size_t i = 1; i < c.size(); i += 2) c[i] = -c[i];
    return QPoly(std::move(c));
  });
  return out;
}

namespace {

// Applies a Motion to the rest position of the object's `local`-th vertex.
Motion_point move(const Motion& m, const QPoint& rest, std::size_t local) {
  switch (m.kind) {
    case Motion::Kind::none:
      return {{QPoly(rest[0]), QPoly(rest[1]), QPoly(rest[2]), QPoly(rest[3])}};
    case Motion::Kind::translation:
      // rest + (dx, dy, dz), homogeneously: X + dx W.
      return {{QPoly(rest[0]) + m.translation[0] * QPoly(rest[3]),
               QPoly(rest[1]) + m.translation[1] * QPoly(rest[3]),
               QPoly(rest[2]) + m.translation[2] * QPoly(rest[3]), QPoly(rest[3])}};
    case Motion::Kind::matrix: {
      Motion_point r;
      for (int i = 0; i < 4; ++i) {
        QPoly s;
        for (int j = 0; j < 4; ++j) s += m.matrix[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] * QPoly(rest[j]);
        r[i] = s;
      }
      return r;
    }
    case Motion::Kind::vertices:
      return m.vertices.at(local);
  }
  return {};
}

int degree_of(const Motion& m) {
  int d = 0;
  auto see = [&](const QPoly& p) { d = std::max(d, p.degree()); };
  switch (m.kind) {
    case Motion::Kind::none: break;
    case Motion::Kind::translation:
      for (const auto& p : m.translation) see(p);
      break;
    case Motion::Kind::matrix:
      for (const auto& row : m.matrix)
        for (const auto& p : row) see(p);
      break;
    case Motion::Kind::vertices:
      for (const auto& v : m.vertices)
        for (const auto& p : v.c) see(p);
      break;
  }
  return d;
}

}  // namespace

bool Scene::is_moving(std::size_t object) const { return degree_of(objects.at(object).motion) > 0; }

std::size_t Scene::moving_triangle_count() const {
  std::size_t n = 0;
  for (std::size_t o = 0; o < objects.size(); ++o)
    if (is_moving(o)) n += objects[o].triangle_count;
  return n;
}

int Scene::max_motion_degree() const {
  int d = 0;
  for (const auto& o : objects) d = std::max(d, degree_of(o.motion));
  return d;
}

Motion_point Scene::position(std::size_t v) const {
  const Object& o = objects.at(vertex_object.at(v));
  return move(o.motion, rest.at(v), v - o.first_vertex);
}

QPoint Scene::position_at(std::size_t v, const Q& t) const { return evaluate(position(v), t); }

void Scene::derive() {
  const std::size_t nv = rest.size(), nt = triangles.size();
  vertex_object.assign(nv, 0);
  triangle_object.assign(nt, 0);
  for (std::size_t o = 0; o < objects.size(); ++o) {
    for (std::size_t i = 0; i < objects[o].vertex_count; ++i) vertex_object[objects[o].first_vertex + i] = o;
    for (std::size_t i = 0; i < objects[o].triangle_count; ++i) triangle_object[objects[o].first_triangle + i] = o;
  }
  // Edges in order of first appearance; vertex ids are global, so one map
  // serves all objects.
  edges.clear();
  edge_object.clear();
  triangle_edges.assign(nt, {});
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_id;
  for (std::size_t t = 0; t < nt; ++t)
    for (int s = 0; s < 3; ++s) {
      const std::size_t a = triangles[t][static_cast<std::size_t>(s)], b = triangles[t][static_cast<std::size_t>((s + 1) % 3)];
      const auto key = std::minmax(a, b);
      auto [it, fresh] = edge_id.emplace(key, edges.size());
      if (fresh) {
        edges.push_back({a, b});
        edge_object.push_back(triangle_object[t]);
      }
      triangle_edges[t][static_cast<std::size_t>(s)] = it->second;
    }
  vertex_edges.assign(nv, {});
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (std::size_t v : edges[e]) vertex_edges[v].push_back(e);
  edge_triangles.assign(edges.size(), {});
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t e : triangle_edges[t]) edge_triangles[e].push_back(t);

  // Priority order: the explicit list, or the seeded shuffle partitioned
  // static-first (stably).
  if (priority_spec.order) {
    priority_order = *priority_spec.order;
  } else {
    priority_order = shuffled_ids(nt, priority_spec.seed);
    std::stable_partition(priority_order.begin(), priority_order.end(),
                          [&](std::size_t t) { return !is_moving(triangle_object[t]); });
  }
  triangle_priority.assign(nt, 0);
  for (std::size_t p = 0; p < priority_order.size(); ++p) triangle_priority[priority_order[p]] = p;

  // Cut priorities: 7 TPO + slot; a shared vertex or edge takes the highest
  // priority (smallest number) among its triangles.
  const std::size_t none = static_cast<std::size_t>(-1);
  vertex_cut_priority.assign(nv, none);
  edge_cut_priority.assign(edges.size(), none);
  triangle_cut_priority.assign(nt, 0);
  for (std::size_t t = 0; t < nt; ++t) {
    const std::size_t base = 7 * triangle_priority[t];
    for (std::size_t s = 0; s < 3; ++s) {
      std::size_t& vp = vertex_cut_priority[triangles[t][s]];
      vp = std::min(vp, base + s);
      std::size_t& ep = edge_cut_priority[triangle_edges[t][s]];
      ep = std::min(ep, base + 3 + s);
    }
    triangle_cut_priority[t] = base + 6;
  }
}

}  // namespace kvd::scene
