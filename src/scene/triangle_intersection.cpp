#include "kvd/detail/scene/triangle_intersection.hpp"

#include <algorithm>

namespace kvd::scene {

namespace {

using Vec2 = std::array<mpq_class, 2>;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
mpq_class dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

mpq_class orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Drops the coordinate `axis`; injective on any plane whose normal has a
// non-zero component along it.
Vec2 project(const Vec3& p, int axis) {
  return axis == 0 ? Vec2{p[1], p[2]} : axis == 1 ? Vec2{p[0], p[2]} : Vec2{p[0], p[1]};
}

// Sutherland–Hodgman clipping of a (possibly degenerate) convex polygon by the
// closed triangle t; boundary contact is kept.
std::vector<Vec2> clip(std::vector<Vec2> poly, const std::array<Vec2, 3>& t) {
  const int s = sgn(orient(t[0], t[1], t[2]));
  for (int e = 0; e < 3 && !poly.empty(); ++e) {
    const Vec2& p = t[static_cast<std::size_t>(e)];
    const Vec2& q = t[static_cast<std::size_t>((e + 1) % 3)];
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2& c = poly[i];
      const Vec2& n = poly[(i + 1) % poly.size()];
      const mpq_class fc = s * orient(p, q, c), fn = s * orient(p, q, n);
      if (fc >= 0) out.push_back(c);
      if ((fc > 0 && fn < 0) || (fc < 0 && fn > 0)) {
        const mpq_class u = fc / (fc - fn);
        out.push_back({c[0] + u * (n[0] - c[0]), c[1] + u * (n[1] - c[1])});
      }
    }
    poly = std::move(out);
  }
  return poly;
}

bool in_allowed(const Vec2& x, const std::vector<Vec2>& s) {
  if (s.empty()) return false;
  if (s.size() == 1) return x == s[0];
  const Vec2 &u = s[0], &v = s[1];
  if (orient(u, v, x) != 0) return false;
  const mpq_class a = (x[0] - u[0]) * (v[0] - u[0]) + (x[1] - u[1]) * (v[1] - u[1]);
  const mpq_class b = (x[0] - v[0]) * (u[0] - v[0]) + (x[1] - v[1]) * (u[1] - v[1]);
  return a >= 0 && b >= 0;
}

bool boxes_disjoint(const Triangle3& a, const Triangle3& b) {
  for (std::size_t k = 0; k < 3; ++k) {
    const auto [alo, ahi] = std::minmax({a[0][k], a[1][k], a[2][k]});
    const auto [blo, bhi] = std::minmax({b[0][k], b[1][k], b[2][k]});
    if (ahi < blo || bhi < alo) return true;
  }
  return false;
}

}  // namespace

bool triangles_conflict(const Triangle3& a, const Triangle3& b, const std::vector<Vec3>& shared) {
  if (shared.size() >= 3) return true;
  if (boxes_disjoint(a, b)) return false;
  const Vec3 n = cross(sub(a[1], a[0]), sub(a[2], a[0]));
  // The coordinate to drop: the largest component of A's normal.
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (abs(n[static_cast<std::size_t>(k)]) > abs(n[static_cast<std::size_t>(axis)])) axis = k;
  const std::array<Vec2, 3> a2{project(a[0], axis), project(a[1], axis), project(a[2], axis)};

  std::array<mpq_class, 3> d;  // signed distances (scaled) of B's vertices to A's plane
  for (std::size_t i = 0; i < 3; ++i) d[i] = dot3(n, sub(b[i], a[0]));
  std::vector<Vec2> candidates;
  if (d[0] == 0 && d[1] == 0 && d[2] == 0) {
    // Coplanar: A clipped by B.
    const std::array<Vec2, 3> b2{project(b[0], axis), project(b[1], axis), project(b[2], axis)};
    candidates = clip({a2[0], a2[1], a2[2]}, b2);
  } else {
    if ((d[0] > 0 && d[1] > 0 && d[2] > 0) || (d[0] < 0 && d[1] < 0 && d[2] < 0)) return false;
    // B ∩ plane(A): vertices on the plane and edge crossings, all on one line.
    std::vector<Vec2> cut;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t j = (i + 1) % 3;
      if (d[i] == 0) cut.push_back(project(b[i], axis));
      if ((d[i] > 0 && d[j] < 0) || (d[i] < 0 && d[j] > 0)) {
        const mpq_class u = d[i] / (d[i] - d[j]);
        Vec3 p;
        for (std::size_t k = 0; k < 3; ++k) p[k] = b[i][k] + u * (b[j][k] - b[i][k]);
        cut.push_back(project(p, axis));
      }
    }
    candidates = clip(std::move(cut), a2);
  }
  std::vector<Vec2> allowed;
  for (const auto& s : shared) allowed.push_back(project(s, axis));
  for (const auto& c : candidates)
    if (!in_allowed(c, allowed)) return true;
  return false;
}

void for_each_close_pair(const std::vector<Triangle3>& tris,
                         const std::function<bool(std::size_t, std::size_t)>& visit) {
  const std::size_t n = tris.size();
  if (n < 2) return;
  std::vector<std::array<std::pair<mpq_class, mpq_class>, 3>> box(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [lo, hi] = std::minmax({tris[i][0][k], tris[i][1][k], tris[i][2][k]});
      box[i][k] = {lo, hi};
    }
  // The sweep axis: the one where the boxes' extents are smallest relative
  // to the scene's span.
  std::size_t axis = 0;
  mpq_class best = -1;
  for (std::size_t k = 0; k < 3; ++k) {
    mpq_class lo = box[0][k].first, hi = box[0][k].second, total = 0;
    for (const auto& b : box) {
      lo = std::min(lo, b[k].first);
      hi = std::max(hi, b[k].second);
      total += b[k].second - b[k].first;
    }
    if (hi == lo) continue;  // every triangle meets the same plane across this axis
    const mpq_class ratio = total / (hi - lo);
    if (best < 0 || ratio < best) best = ratio, axis = k;
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return box[a][axis].first < box[b][axis].first || (box[a][axis].first == box[b][axis].first && a < b);
  });
  auto boxes_meet = [&](std::size_t a, std::size_t b) {
    for (std::size_t k = 0; k < 3; ++k)
      if (box[a][k].second < box[b][k].first || box[b][k].second < box[a][k].first) return false;
    return true;
  };
  std::vector<std::size_t> active;
  for (std::size_t i : order) {
    const mpq_class& start = box[i][axis].first;
    std::erase_if(active, [&](std::size_t j) { return box[j][axis].second < start; });
    for (std::size_t j : active)
      if (boxes_meet(i, j) && visit(std::min(i, j), std::max(i, j))) return;
    active.push_back(i);
  }
}

std::vector<Triangle3> triangles_at(const Scene& s, const Q& t) {
  std::vector<Vec3> at(s.rest.size());
  for (std::size_t v = 0; v < s.rest.size(); ++v) {
    const QPoint p = s.position_at(v, t);
    at[v] = {p[0] / p[3], p[1] / p[3], p[2] / p[3]};
  }
  std::vector<Triangle3> tri(s.triangles.size());
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) tri[i][k] = at[s.triangles[i][k]];
  return tri;
}

std::optional<std::pair<std::size_t, std::size_t>> first_conflict(const Scene& s, const std::vector<Triangle3>& tri) {
  std::optional<std::pair<std::size_t, std::size_t>> found;
  for_each_close_pair(tri, [&](std::size_t a, std::size_t b) {
    // Triangles of one object may share vertices, and with them the edge between.
    std::vector<Vec3> shared;
    if (s.triangle_object[a] == s.triangle_object[b])
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
          if (s.triangles[a][i] == s.triangles[b][j]) shared.push_back(tri[a][i]);
    if (triangles_conflict(tri[a], tri[b], shared)) found = std::pair{a, b};
    return found.has_value();
  });
  return found;
}

}  // namespace kvd::scene
