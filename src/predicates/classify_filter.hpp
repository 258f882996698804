// Rule 2 of the classification (DESIGN.md section 4) behind the exact
// kernel's interval filter: the sign of dot(plane, point) times that of the
// point's W, with the Plücker joins and meets evaluated on intervals holding
// the positions at t, so that no polynomial in t is built. Decides only when
// every interval it needs excludes zero; the exact classification runs
// otherwise.
#pragma once

#include <gmpxx.h>

#include <memory>

#include "kvd/kernel/exact_time.hpp"
#include "kvd/kernel/poly.hpp"
#include "kvd/symbolic/scene_geometry.hpp"

namespace kvd::predicates {

class Classification_filter {
public:
  explicit Classification_filter(const symbolic::Scene_geometry<Poly<mpq_class>>& motion);
  ~Classification_filter();

  // The side of the canonical vertex v, not on p by construction, at t; 0
  // when the intervals cannot tell.
  int side(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p, const Exact_time& t);

private:
  struct State;  // keeps Boost.Interval out of this header
  std::unique_ptr<State> state_;
};

}  // namespace kvd::predicates
