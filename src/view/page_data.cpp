#include "page_data.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "frame_geometry.hpp"
#include "tree_table.hpp"

namespace kvd::view {

namespace {

using nlohmann::json;

// Coordinates as integers: 2^14 units across the first instant's box.
struct Grid {
  D3 origin;
  double unit;
  // Appends p's three integers to `out`.
  void point(const D3& p, json& out) const {
    for (std::size_t j = 0; j < 3; ++j) out.push_back(std::llround((p[j] - origin[j]) / unit));
  }
  json flat(const std::vector<D3>& ps) const {
    json out = json::array();
    for (const auto& p : ps) point(p, out);
    return out;
  }
  // The plane in grid coordinates, its normal scaled to a largest entry of
  // 1 and rounded to six digits, its offset to a hundredth of a unit.
  json plane(const std::array<double, 4>& p) const {
    const double m = std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    if (m == 0) return nullptr;
    json out = json::array();
    for (std::size_t j = 0; j < 3; ++j) out.push_back(std::stod(six_digits(p[j] / m)));
    out.push_back(std::round((p[0] * origin[0] + p[1] * origin[1] + p[2] * origin[2] + p[3]) / (unit * m) * 100) / 100);
    return out;
  }
  static std::string six_digits(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
  }
};

// A failing certificate with its features' shapes on the grid.
json features(const Failing_certificate& f, const Instant& in, const Grid& g) {
  const Feature_shapes shapes = feature_shapes(f, in);
  json points = json::array(), segments = json::array(), triangles = json::array(), names = json::array();
  for (const auto& p : f.planes) names.push_back(symbolic::to_string(p));
  for (const auto& p : shapes.points) points.push_back(g.flat({p}));
  for (const auto& e : shapes.segments) segments.push_back(g.flat({e[0], e[1]}));
  for (const auto& t : shapes.triangles) triangles.push_back(g.flat({t[0], t[1], t[2]}));
  return {{"type", kinetic::to_string(f.type)}, {"features", f.features}, {"planes", names},
          {"points", points},  {"segments", segments},                  {"triangles", triangles}};
}

}  // namespace

json page_data(const Page_input& in, const std::function<void(std::size_t, std::size_t)>& progress) {
  const Recorded_run& run = *in.run;
  const scene::Scene& s = run.scene;
  const auto spans = intervals(run);
  Tree_table table;
  json frames = json::array(), batches = json::array();
  std::optional<Grid> grid;
  // The nodes of the previous instant's tree, by cut and fragment: a node
  // whose pair the previous tree lacks is one its batch changed (a node that
  // only moved, or whose children changed, is not).
  std::set<std::pair<std::string, std::string>> before;
  for (std::size_t k = 0; k < spans.size(); ++k) {
    const Instant at = inside(run, spans[k]);
    const Box box = bounds(at);
    if (!grid) grid = Grid{box.lo, std::max({box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]}) / 16384};
    const std::vector<int> entry = table.add(at.tree());
    std::set<std::pair<std::string, std::string>> now;
    json changed = json::array();
    for (int e : std::set<int>(entry.begin(), entry.end())) {
      if (e < 0) continue;
      const auto& node = table.entries()[static_cast<std::size_t>(e)];
      now.emplace(node.cut, node.fragment);
      if (k > 0 && !before.count({node.cut, node.fragment})) changed.push_back(e);
    }
    // The planes by site kind and id ("P(3)" at planes.P[3]); null for sites not cut with.
    json planes = {{"P", json::array()}, {"E", json::array()}, {"T", json::array()}};
    for (const auto& [site, plane] : site_planes(at)) {
      json& list = planes[site.kind == symbolic::Symbolic_plane::Kind::P   ? "P"
                          : site.kind == symbolic::Symbolic_plane::Kind::E ? "E"
                                                                             : "T"];
      while (list.size() <= site.id) list.push_back(nullptr);
      list[site.id] = grid->plane(plane);
    }
    json vertices = json::array();
    for (std::size_t v = 0; v < s.rest.size(); ++v) grid->point(at.position(symbolic::Symbolic_vertex::endpoint(v)), vertices);
    frames.push_back({{"sample", at.time().get_str()},
                      {"sample_approx", at.time().get_d()},
                      {"root", at.tree().root < 0 ? -1 : entry[static_cast<std::size_t>(at.tree().root)]},
                      {"box", grid->flat({box.lo, box.hi})},
                      {"planes", planes},
                      {"vertices", vertices},
                      {"changed", changed}});
    if (k > 0) {
      const auto& b = run.sim.batches[k - 1];
      json failing = json::array();
      for (const auto& f : run.failing[k - 1]) failing.push_back(features(f, at, *grid));
      batches.push_back({{"time", b.time.to_string()}, {"approx", b.time.to_double()}, {"failing", failing},
                         {"tree_changed", b.changed}, {"structure", b.structure}, {"frame", k}});
    }
    before = std::move(now);
    if (progress) progress(k + 1, spans.size());
  }
  json entries = json::array(), edges = json::array();
  for (const auto& e : s.edges) edges.push_back(e);
  for (const auto& e : table.entries()) entries.push_back({e.cut, e.fragment, e.left, e.right});
  json changes = json::array();
  for (const auto& c : run.sim.motion_changes)
    changes.push_back({{"time", c.time.get_str()}, {"approx", c.time.get_d()}, {"objects", c.objects},
                       {"contact", c.contact}, {"batches_before", c.batches_before}});
  json triangles = json::array(), objects = json::array();
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    triangles.push_back(s.triangles[t]);
    objects.push_back(s.triangle_object[t]);
  }
  json page = {{"format", "kvd-view/1"},
               {"title", in.title},
               {"start", s.start.get_str()},
               {"origin", grid->origin},
               {"unit", grid->unit},
               {"triangles", triangles},
               {"edges", edges},
               {"objects", objects},
               {"entries", entries},
               {"frames", frames},
               {"batches", batches},
               {"motion_changes", changes},
               {"events", run.sim.failures},
               {"structure_hash", run.sim.structure_hash}};
  if (in.view) page["view"] = *in.view;
  if (in.diff) page["diff"] = *in.diff;
  return page;
}

}  // namespace kvd::view
