// The factors of the segment predicates (kvd/segments/segment_predicates.hpp),
// written once over any ring R: the polynomials in t of the exact and the
// floating-point kernels, the polynomials in ε of the perturbation, and the
// intervals of the exact kernel's filter (src/segments/segment_filter.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <forward_list>
#include <type_traits>
#include <vector>

#include "kvd/segments/segment_predicates.hpp"

namespace kvd::segments::detail {

template <class R>
using H = std::array<R, 3>;

// The join of two points (a line) or the meet of two lines (a point).
template <class R>
H<R> wedge(const H<R>& a, const H<R>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class R>
R dot(const H<R>& a, const H<R>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The endpoints over one ring, with the lines and crossings made from them,
// kept when `cache` is set (the unperturbed ring: a construction asks for the
// same lines and crossings many times). Over a ring whose numbers copy
// without allocating (the filter's intervals) they are handed out by value;
// over polynomials by reference, into the cache or, without one, into this
// view's own store: a copy of three polynomials from the cache was a tenth
// of the kept set's construction.
template <class R>
class View {
  static constexpr bool by_value = std::is_trivially_copyable_v<R>;

public:
  using Coordinates = std::conditional_t<by_value, H<R>, const H<R>&>;

  View(const std::vector<H<R>>& e, Geometry_cache<R>* cache) : e_(e), cache_(cache) {}

  const H<R>& endpoint(std::size_t k) const { return e_[k]; }
  Coordinates line(std::size_t s) const {
    if (!cache_) return made(wedge(e_[2 * s], e_[2 * s + 1]));
    auto& l = cache_->lines[s];
    if (!l) l = wedge(e_[2 * s], e_[2 * s + 1]);
    return *l;
  }
  Coordinates point(const Site_point& p) const {
    if (p.kind == Site_point::Kind::endpoint) return e_[p.a];
    if (!cache_) return made(wedge(line(p.a), line(p.b)));
    const std::uint64_t key = (std::uint64_t(p.a) << 32) | p.b;
    auto it = cache_->crossings.find(key);
    if (it == cache_->crossings.end()) it = cache_->crossings.emplace(key, wedge(line(p.a), line(p.b))).first;
    return it->second;
  }
  // x(P1) - x(P0) of segment s, times W0 W1 > 0.
  R dx(std::size_t s) const { return e_[2 * s + 1][0] * e_[2 * s][2] - e_[2 * s][0] * e_[2 * s + 1][2]; }

  // The factors of side(q, s) for a point q given by coordinates:
  // det[P0; P1; q] is the orientation of (P0, P1, q) times W0 W1 W_q, and
  // "left of P0 -> P1" is "above" when x(P0) < x(P1).
  std::vector<R> side_factors(const H<R>& q, std::size_t s, bool q_is_endpoint) const {
    std::vector<R> f{dot(line(s), q), dx(s)};
    if (!q_is_endpoint) f.push_back(q[2]);
    return f;
  }

private:
  Coordinates made(H<R>&& h) const {
    if constexpr (by_value) return h;
    else return made_.emplace_front(std::move(h));  // a list: what it handed out stays where it is
  }

  const std::vector<H<R>>& e_;
  Geometry_cache<R>* cache_;
  mutable std::forward_list<H<R>> made_;  // empty, it allocates nothing
};

// The factors of a certificate: the sign of their product is its sign.
//  x_order(a, b): x(a) - x(b) times W_a W_b, with the W of a crossing;
//  side(p, s): see side_factors;
//  order_at(p, i, j): the point of the line of i above or below p, then its
//  side of j.
// Keys whose point lies on a named segment are decided by identity and
// never reach here.
template <class R>
std::vector<R> factors_of(const Segment_certificate_key& key, const View<R>& e) {
  using Kind = Segment_certificate_key::Kind;
  switch (key.kind) {
    case Kind::x_order: {
      const H<R>&pa = e.point(key.p), &pb = e.point(key.q);
      std::vector<R> f{pa[0] * pb[2] - pb[0] * pa[2]};
      if (key.p.kind == Site_point::Kind::crossing) f.push_back(pa[2]);
      if (key.q.kind == Site_point::Kind::crossing) f.push_back(pb[2]);
      return f;
    }
    case Kind::side: return e.side_factors(e.point(key.p), key.i, key.p.kind == Site_point::Kind::endpoint);
    case Kind::order_at: {
      const H<R>& q = e.point(key.p);
      const H<R> vertical{q[2], R(), -q[0]};
      return e.side_factors(wedge(e.line(key.i), vertical), key.j, false);
    }
  }
  return {};
}

}  // namespace kvd::segments::detail
