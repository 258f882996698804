#include "kvd/segments/segment_predicates.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

namespace {

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
// same lines and crossings many times).
template <class R>
class View {
public:
  View(const std::vector<H<R>>& e, Geometry_cache<R>* cache) : e_(e), cache_(cache) {}

  const H<R>& endpoint(std::size_t k) const { return e_[k]; }
  H<R> line(std::size_t s) const {
    if (!cache_) return wedge(e_[2 * s], e_[2 * s + 1]);
    auto& l = cache_->lines[s];
    if (!l) l = wedge(e_[2 * s], e_[2 * s + 1]);
    return *l;
  }
  H<R> point(const Site_point& p) const {
    if (p.kind == Site_point::Kind::endpoint) return e_[p.a];
    if (!cache_) return wedge(line(p.a), line(p.b));
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
  const std::vector<H<R>>& e_;
  Geometry_cache<R>* cache_;
};

}  // namespace

long perturbation_lambda(std::size_t e, std::size_t n) {
  long p = std::max<long>(2, static_cast<long>(n));
  const auto prime = [](long q) {
    for (long d = 2; d * d <= q; ++d)
      if (q % d == 0) return false;
    return true;
  };
  while (!prime(p)) ++p;
  const long i = static_cast<long>(e / 2);
  const long a = 2 * p * i + (i * i) % p;
  return 2 * a + 1 + static_cast<long>(e % 2);
}

template <class K>
Segment_predicates<K>::Segment_predicates(const K& k, const Segment_scene& s)
    : k_(&k), s_(&s), endpoints_(s.endpoint_count()), perturbed_(s.endpoint_count()) {
  for (std::size_t e = 0; e < s.endpoint_count(); ++e) load(e, sgn(s.endpoint(e)[2](s.start)));
  cache_.lines.resize(s.segments.size());
}

// Endpoint e from the scene, negated when its W has the sign `w` < 0.
template <class K>
void Segment_predicates<K>::load(std::size_t e, int w) {
  using FT = typename K::FT;
  const Motion_point3 m = s_->endpoint(e);
  H<P> p;
  for (std::size_t i = 0; i < 3; ++i) p[i] = poly_from_rational<FT>(w < 0 ? QPoly(-m[i]) : m[i]);
  const mpq_class g(perturbation_lambda(e, s_->segments.size()));
  const P gx(from_rational<FT>(g)), gy(from_rational<FT>(g * g));
  perturbed_[e] = {Poly<P>(std::vector<P>{p[0], p[2] * gx}), Poly<P>(std::vector<P>{p[1], p[2] * gy}),
                   Poly<P>(std::vector<P>{p[2]})};
  endpoints_[e] = std::move(p);
}

template <class K>
void Segment_predicates<K>::refresh(std::size_t segment, const Time& at) {
  for (const std::size_t e : {2 * segment, 2 * segment + 1})
    load(e, k_->sign_at(poly_from_rational<typename K::FT>(s_->endpoint(e)[2]), at));
  cache_.lines[segment].reset();
  cache_.crossings.clear();
}

template <class K>
bool Segment_predicates<K>::vanishes(const P& f) const {
  return std::all_of(f.coefficients().begin(), f.coefficients().end(),
                     [&](const auto& c) { return k_->sign(c) == 0; });
}

std::vector<std::size_t> named_segments(const Segment_certificate_key& k) {
  using Kind = Segment_certificate_key::Kind;
  std::vector<std::size_t> out;
  const auto add = [&](const Site_point& p) {
    if (p.kind == Site_point::Kind::endpoint) return out.push_back(p.a / 2);
    out.push_back(p.a);
    out.push_back(p.b);
  };
  add(k.p);
  if (k.kind == Kind::x_order) add(k.q);
  else out.push_back(k.i);
  if (k.kind == Kind::order_at) out.push_back(k.j);
  return out;
}

std::string point_name(const Site_point& p) {
  if (p.kind == Site_point::Kind::endpoint) return "s" + std::to_string(p.a / 2) + "." + std::to_string(p.a % 2);
  return "s" + std::to_string(p.a) + "xs" + std::to_string(p.b);
}

const char* kind_name(Segment_certificate_key::Kind k) {
  static const char* const names[] = {"x_order", "side", "order_at"};
  return names[static_cast<int>(k)];
}

std::string features(const Segment_certificate_key& k) {
  using Kind = Segment_certificate_key::Kind;
  std::string out = point_name(k.p) + " ";
  if (k.kind == Kind::x_order) return out + point_name(k.q);
  out += "s" + std::to_string(k.i);
  if (k.kind == Kind::order_at) out += " s" + std::to_string(k.j);
  return out;
}

Segment_event event_of(const Segment_certificate_key& k, const std::vector<std::size_t>& rank) {
  using Kind = Segment_certificate_key::Kind;
  const bool endpoint = k.p.kind == Site_point::Kind::endpoint;
  switch (k.kind) {
    case Kind::x_order: {
      const bool both = endpoint && k.q.kind == Site_point::Kind::endpoint;
      if (both && k.p.a / 2 == k.q.a / 2) return Segment_event::flip;
      return endpoint || k.q.kind == Site_point::Kind::endpoint ? Segment_event::vertex : Segment_event::edge;
    }
    case Kind::side:
      return endpoint && rank[k.i] < rank[k.p.a / 2] ? Segment_event::intersection : Segment_event::edge;
    case Kind::order_at: return Segment_event::edge;
  }
  return Segment_event::edge;
}

template <class K>
template <class F>
Segment_sign Segment_predicates<K>::decide(const Segment_certificate_key& key, const F& factors,
                                           const Time& t) const {
  const std::vector<P> v = factors(View<P>(endpoints_, &cache_));
  std::optional<std::vector<Poly<P>>> expanded;
  std::vector<P> deciding;
  int sign = 1;
  Segment_rule rule = Segment_rule::value;
  for (std::size_t f = 0; f < v.size(); ++f) {
    if (!vanishes(v[f])) {
      int s = k_->sign_at(v[f], t);
      if (s == 0) {
        s = k_->sign_after(v[f], t);
        rule = std::max(rule, Segment_rule::after);
      }
      sign *= s;
      if (recorder_ && v[f].degree() > 0) deciding.push_back(v[f]);
      continue;
    }
    if (!expanded) expanded = factors(View<Poly<P>>(perturbed_, nullptr));
    int s = 0;
    for (const P& c : (*expanded)[f].coefficients()) {
      if (vanishes(c)) continue;
      s = k_->sign_at(c, t);
      if (s == 0) s = k_->sign_after(c, t);
      if (recorder_ && c.degree() > 0) deciding.push_back(c);
      break;
    }
    if (s == 0) throw std::logic_error("segment predicate: every ε-coefficient vanishes (see proofs/segment-perturbation.md)");
    rule = Segment_rule::perturbation;
    sign *= s;
  }
  ++(rule == Segment_rule::value ? counts_.value : rule == Segment_rule::after ? counts_.after : counts_.perturbation);
  if (recorder_) recorder_(key, std::move(deciding), node_, sign);
  return {sign, rule};
}

template <class K>
Segment_sign Segment_predicates<K>::compare_x(const Site_point& a, const Site_point& b, const Time& t) const {
  if (a == b) {
    ++counts_.identity;
    return {0, Segment_rule::identity};
  }
  // One certificate for the pair, decided in key order whichever way round
  // it is asked, so that its sign and factors are the key's.
  if (b < a) {
    const Segment_sign r = compare_x(b, a, t);
    return {-r.sign, r.rule};
  }
  return decide(
      {Segment_certificate_key::Kind::x_order, a, b, 0, 0},
      [&](const auto& e) {
        const auto pa = e.point(a), pb = e.point(b);
        std::vector<std::decay_t<decltype(pa[0])>> f{pa[0] * pb[2] - pb[0] * pa[2]};
        if (a.kind == Site_point::Kind::crossing) f.push_back(pa[2]);
        if (b.kind == Site_point::Kind::crossing) f.push_back(pb[2]);
        return f;
      },
      t);
}

template <class K>
Segment_sign Segment_predicates<K>::side(const Site_point& p, std::size_t s, const Time& t) const {
  if (p.on(s)) {
    ++counts_.identity;
    return {0, Segment_rule::identity};
  }
  return decide({Segment_certificate_key::Kind::side, p, {}, static_cast<std::uint32_t>(s), 0},
                [&](const auto& e) { return e.side_factors(e.point(p), s, p.kind == Site_point::Kind::endpoint); }, t);
}

template <class K>
Segment_sign Segment_predicates<K>::order_at(const Site_point& p, std::size_t i, std::size_t j, const Time& t) const {
  if (p.on(i)) return side(p, j, t);
  if (p.on(j)) {
    const Segment_sign r = side(p, i, t);
    return {-r.sign, r.rule};
  }
  // The point of the line of i above or below p, then its side of j.
  return decide(
      {Segment_certificate_key::Kind::order_at, p, {}, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)},
      [&](const auto& e) {
        const auto q = e.point(p);
        using R = std::decay_t<decltype(q[0])>;
        const H<R> vertical{q[2], R(), -q[0]};
        return e.side_factors(wedge(e.line(i), vertical), j, false);
      },
      t);
}

template <class K>
bool Segment_predicates<K>::cross(std::size_t i, std::size_t j, const Time& t) const {
  const auto straddles = [&](std::size_t a, std::size_t b) {
    return side(Site_point::endpoint(2 * b), a, t).sign * side(Site_point::endpoint(2 * b + 1), a, t).sign < 0;
  };
  return straddles(i, j) && straddles(j, i);
}

template <class K>
std::size_t Segment_predicates<K>::left_endpoint(std::size_t s, const Time& t) const {
  return compare_x(Site_point::endpoint(2 * s), Site_point::endpoint(2 * s + 1), t).sign < 0 ? 2 * s : 2 * s + 1;
}

#define KVD_INSTANTIATE_SEGMENT_PREDICATES(K) template class Segment_predicates<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SEGMENT_PREDICATES)

}  // namespace kvd::segments
