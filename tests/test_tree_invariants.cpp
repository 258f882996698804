// BSP invariants of built trees, checked exactly at the build instant: every
// fragment lies in its node's region (each vertex on the closed side of each
// ancestor plane it descends to), the edge fragments of an edge tile it, and
// the triangle fragments of a triangle tile it.
#include <catch2/catch.hpp>
#include <map>

#include "kvd/kernel/kernel.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"

using namespace kvd;
using symbolic::Symbolic_vertex;

namespace {

scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }

using V3 = std::array<mpq_class, 3>;

V3 euclidean(const Point4<mpq_class>& p) { return {p[0] / p[3], p[1] / p[3], p[2] / p[3]}; }

std::vector<Symbolic_vertex> vertices_of(const tree::Fragment& f) {
  if (const auto* v = std::get_if<Symbolic_vertex>(&f)) return {*v};
  if (const auto* e = std::get_if<tree::Edge_fragment>(&f)) return {e->a, e->b};
  return std::get<tree::Triangle_fragment>(f).corners;
}

// Twice the signed area of a polygon projected by dropping coordinate `axis`.
mpq_class projected_area(const std::vector<V3>& poly, int axis) {
  const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2;
  mpq_class a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const V3& p = poly[i];
    const V3& q = poly[(i + 1) % poly.size()];
    a += p[u] * q[w] - q[u] * p[w];
  }
  return a;
}

void check_invariants(const scene::Scene& s, const mpq_class& t) {
  const Exact_kernel k;
  const predicates::Classifier<Exact_kernel> c(k, s);
  const Exact_time when(t);
  const tree::Kvd_tree tr = tree::build(c, when);
  const auto g = symbolic::at_instant(c.motion(), t);
  auto at_t = [&](const Symbolic_vertex& v) -> V3 {
    const auto p = c.position(v);
    return euclidean(Point4<mpq_class>{{p[0](t), p[1](t), p[2](t), p[3](t)}});
  };
  // Region: walk with the ancestors' planes and the side taken.
  std::vector<std::tuple<int, std::vector<std::pair<symbolic::Symbolic_plane, int>>>> stack{{tr.root, {}}};
  long checked = 0, outside = 0;
  std::map<std::size_t, std::vector<std::pair<mpq_class, mpq_class>>> edge_pieces;
  std::map<std::size_t, mpq_class> triangle_area;
  while (!stack.empty()) {
    auto [i, path] = stack.back();
    stack.pop_back();
    if (i < 0) continue;
    const tree::Node& n = tr.nodes[static_cast<std::size_t>(i)];
    for (const auto& v : vertices_of(n.fragment))
      for (const auto& [plane, side] : path) {
        ++checked;
        const int got = c.side(v, plane, when);
        if (got != 0 && got != side) {
          ++outside;
          UNSCOPED_INFO(symbolic::to_string(v) << " of " << symbolic::to_string(n.cut) << " is outside "
                                               << symbolic::to_string(plane));
        }
      }
    if (const auto* e = std::get_if<tree::Edge_fragment>(&n.fragment)) {
      // Parameters along the edge from its first to its second endpoint.
      const V3 a = euclidean(g.vertex(s.edges[n.cut.id][0])), b = euclidean(g.vertex(s.edges[n.cut.id][1]));
      auto lambda = [&](const Symbolic_vertex& v) -> mpq_class {
        const V3 p = at_t(v);
        mpq_class num = 0, den = 0;
        for (int j = 0; j < 3; ++j) {
          num += (p[j] - a[j]) * (b[j] - a[j]);
          den += (b[j] - a[j]) * (b[j] - a[j]);
        }
        return num / den;
      };
      const mpq_class la = lambda(e->a), lb = lambda(e->b);
      edge_pieces[n.cut.id].emplace_back(std::min(la, lb), std::max(la, lb));
    }
    if (const auto* f = std::get_if<tree::Triangle_fragment>(&n.fragment)) {
      std::vector<V3> poly;
      for (const auto& v : f->corners) poly.push_back(at_t(v));
      triangle_area[n.cut.id] += projected_area(poly, 2) + projected_area(poly, 1) * 3 + projected_area(poly, 0) * 7;
    }
    auto left = path, right = path;
    left.emplace_back(n.cut, -1);
    right.emplace_back(n.cut, +1);
    stack.emplace_back(n.left, left);
    stack.emplace_back(n.right, right);
  }
  CHECK(checked > 0);
  CHECK(outside == 0);
  // Edge fragments tile [0, 1].
  for (auto& [e, pieces] : edge_pieces) {
    std::sort(pieces.begin(), pieces.end());
    INFO("edge " << e);
    CHECK(pieces.front().first == 0);
    CHECK(pieces.back().second == 1);
    for (std::size_t j = 1; j < pieces.size(); ++j) CHECK(pieces[j].first == pieces[j - 1].second);
  }
  CHECK(edge_pieces.size() == s.edges.size());
  // Triangle fragments tile their triangle: signed projected areas (a fixed
  // combination of the three projections, so that no triangle projects to
  // zero in all of them) add up to the triangle's.
  for (const auto& [t_id, area] : triangle_area) {
    std::vector<V3> whole;
    for (std::size_t v : s.triangles[t_id]) whole.push_back(euclidean(g.vertex(v)));
    INFO("triangle " << t_id);
    CHECK(area == projected_area(whole, 2) + projected_area(whole, 1) * 3 + projected_area(whole, 0) * 7);
  }
  CHECK(triangle_area.size() == s.triangles.size());
}

}  // namespace

TEST_CASE("built trees satisfy the BSP invariants", "[build][invariants]") {
  for (const char* name : {"single-triangle.json", "two-triangles.json", "cycle3.json", "viewpoint.json", "rotor.json",
                           "boxes.json", "random-20.json", "uniform-scale-25.json", "degenerate-shared-y.json",
                           "degenerate-vertical-edge.json", "degenerate-z-on-plane.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    check_invariants(s, s.start);
    check_invariants(s, s.start + mpq_class(1, 3));
  }
}
