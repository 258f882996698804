#include "frame_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace kvd::view {

Box bounds(const Instant& in) {
  const scene::Scene& s = in.scene();
  Box b{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  for (const auto& tri : s.triangles)
    for (std::size_t v : tri) {
      const D3 p = in.position(symbolic::Symbolic_vertex::endpoint(v));
      for (std::size_t j = 0; j < 3; ++j) b.lo[j] = std::min(b.lo[j], p[j]), b.hi[j] = std::max(b.hi[j], p[j]);
    }
  for (std::size_t j = 0; j < 3; ++j) {
    const double margin = std::max(b.hi[j] - b.lo[j], 1e-9) * 0.1;
    b.lo[j] -= margin, b.hi[j] += margin;
  }
  return b;
}

std::map<symbolic::Symbolic_plane, std::array<double, 4>> site_planes(const Instant& in) {
  std::map<symbolic::Symbolic_plane, std::array<double, 4>> out;
  for (const auto& n : in.tree().nodes) {
    if (out.count(n.cut)) continue;
    const Plane4<mpq_class> p = in.classifier().plane_after(n.cut, in.time());
    out[n.cut] = {p[0].get_d(), p[1].get_d(), p[2].get_d(), p[3].get_d()};
  }
  return out;
}

}  // namespace kvd::view
