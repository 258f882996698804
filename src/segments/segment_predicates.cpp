#include "kvd/segments/segment_predicates.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/segments/segment_factors.hpp"
#include "segment_filter.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/cylindrical_bsp.hpp"

namespace kvd::segments {

using detail::View;

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
  if constexpr (std::is_same_v<K, Exact_kernel>)
    if (k.filtered()) filter_ = std::make_shared<detail::Segment_filter>(endpoints_);
}

// Endpoint e from the scene, negated when its W has the sign `w` < 0. In
// the exact kernel it is scaled by the least common multiple of its
// coefficients' denominators: a positive constant, so no sign changes, and
// every polynomial built from it has integer coefficients (Poly's integer
// path: no gcd).
template <class K>
void Segment_predicates<K>::load(std::size_t e, int w) {
  using FT = typename K::FT;
  Motion_point3 m = s_->endpoint(e);
  if constexpr (std::is_same_v<FT, mpq_class>) {
    mpz_class den(1);
    for (const QPoly& c : m)
      for (const mpq_class& x : c.coefficients()) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), x.get_den_mpz_t());
    for (QPoly& c : m) c = c * QPoly(mpq_class(den));
  }
  H<P> p;
  for (std::size_t i = 0; i < 3; ++i) p[i] = poly_from_rational<FT>(w < 0 ? QPoly(-m[i]) : m[i]);
  const mpq_class g(perturbation_lambda(e, s_->segments.size()));
  const P gx(from_rational<FT>(g)), gy(from_rational<FT>(g * g));
  perturbed_[e] = {Poly<P>(std::vector<P>{p[0], p[2] * gx}), Poly<P>(std::vector<P>{p[1], p[2] * gy}),
                   Poly<P>(std::vector<P>{p[2]})};
  endpoints_[e] = std::move(p);
  if constexpr (std::is_same_v<K, Exact_kernel>)
    if (filter_) filter_->refresh(e, endpoints_[e]);
}

template <class K>
void Segment_predicates<K>::refresh(std::size_t segment, const Time& at) {
  for (const std::size_t e : {2 * segment, 2 * segment + 1})
    load(e, k_->sign_at(poly_from_rational<typename K::FT>(s_->endpoint(e)[2]), at));
  cache_.lines[segment].reset();
  cache_.crossings.clear();
  forget();
}

template <class K>
bool Segment_predicates<K>::vanishes(const P& f) const {
  return std::all_of(f.coefficients().begin(), f.coefficients().end(),
                     [&](const auto& c) { return k_->sign(c) == 0; });
}

boost::container::static_vector<std::size_t, 4> named_segments(const Segment_certificate_key& k) {
  using Kind = Segment_certificate_key::Kind;
  boost::container::static_vector<std::size_t, 4> out;
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

std::vector<std::size_t> turning_segments(const std::vector<Segment_certificate_key>& failing) {
  std::vector<std::size_t> out;
  for (const auto& k : failing)
    if (k.kind == Segment_certificate_key::Kind::x_order && k.p.kind == Site_point::Kind::endpoint &&
        k.q.kind == Site_point::Kind::endpoint && k.p.a / 2 == k.q.a / 2)
      out.push_back(k.p.a / 2);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool part_of_flip(const Segment_certificate_key& k, const std::vector<std::size_t>& turning) {
  return k.kind == Segment_certificate_key::Kind::x_order &&
         std::any_of(turning.begin(), turning.end(), [&](std::size_t s) { return k.p.on(s) && k.q.on(s); });
}

Segment_event event_in_batch(const Segment_certificate_key& k, const std::vector<std::size_t>& rank,
                             const std::vector<std::size_t>& turning) {
  return part_of_flip(k, turning) ? Segment_event::flip : event_of(k, rank);
}

template <class K>
Segment_sign Segment_predicates<K>::decide(const Segment_certificate_key& key, const Time& t) const {
  if (remembered_at_ != &t || held_) return decide_by_rules(key, t);
  if (!(recorder_ && record_polynomials_))
    if (const auto at = remembered_.find(key); at != remembered_.end()) {
      ++counts_.repeated;
      if (recorder_) recorder_(key, {}, node_, at->second.sign);
      return at->second;
    }
  const Segment_sign s = decide_by_rules(key, t);
  remembered_.insert_or_assign(key, s);
  return s;
}

template <class K>
Segment_sign Segment_predicates<K>::decide_by_rules(const Segment_certificate_key& key, const Time& t) const {
  if constexpr (std::is_same_v<K, Exact_kernel>) {
    // Unless a recorder wants them, no polynomial is needed: a sign the
    // interval filter certifies is the value's sign (rule 2).
    if (filter_ && !(recorder_ && record_polynomials_))
      if (const int s = filter_->sign(key, t)) {
        ++counts_.value;
        ++counts_.filtered;
        if (recorder_) recorder_(key, {}, node_, s);
        return {s, Segment_rule::value};
      }
  }
  if (held_)
    if (const std::optional<int> s = held_(key)) {
      ++counts_.held;
      if (recorder_) recorder_(key, {}, node_, *s);
      return {*s, Segment_rule::held};
    }
  std::vector<P> v = detail::factors_of(key, View<P>(endpoints_, &cache_));
  std::optional<std::vector<Poly<P>>> expanded;
  std::vector<P> deciding;
  int sign = 1;
  Segment_rule rule = Segment_rule::value;
  bool at_root = false;
  for (std::size_t f = 0; f < v.size(); ++f) {
    if (!vanishes(v[f])) {
      int s = k_->sign_at(v[f], t);
      if (s == 0) {
        s = k_->sign_after(v[f], t);
        rule = std::max(rule, Segment_rule::after);
        at_root = true;
      }
      sign *= s;
      if (recorder_ && v[f].degree() > 0) deciding.push_back(std::move(v[f]));  // v[f] is not read again
      continue;
    }
    if (!expanded) expanded = detail::factors_of(key, View<Poly<P>>(perturbed_, nullptr));
    int s = 0;
    for (const P& c : (*expanded)[f].coefficients()) {
      if (vanishes(c)) continue;
      s = k_->sign_at(c, t);
      if (s == 0) {
        s = k_->sign_after(c, t);
        at_root = true;
      }
      if (recorder_ && c.degree() > 0) deciding.push_back(c);
      break;
    }
    if (s == 0) {
      // Proved impossible in exact arithmetic; in floating point, the
      // kernel's epsilon swamped the coefficients, which its run repairs or
      // reports as a contradiction.
      if constexpr (std::is_same_v<K, Exact_kernel>)
        throw std::logic_error("segment predicate: every ε-coefficient vanishes (see proofs/segment-perturbation.md)");
      else
        throw Bsp_contradiction("segment predicate: every ε-coefficient is within the kernel's epsilon of 0");
    }
    rule = Segment_rule::perturbation;
    sign *= s;
  }
  ++(rule == Segment_rule::value ? counts_.value : rule == Segment_rule::after ? counts_.after : counts_.perturbation);
  if (recorder_) recorder_(key, std::move(deciding), node_, sign);
  return {sign, rule, at_root};
}

template <class K>
Segment_sign Segment_predicates<K>::sign_of(const Segment_certificate_key& key, const Time& t) const {
  switch (key.kind) {
    case Segment_certificate_key::Kind::x_order: return compare_x(key.p, key.q, t);
    case Segment_certificate_key::Kind::side: return side(key.p, key.i, t);
    case Segment_certificate_key::Kind::order_at: return order_at(key.p, key.i, key.j, t);
  }
  throw std::logic_error("sign_of: a key of no kind");
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
    return {-r.sign, r.rule, r.at_root};
  }
  return decide({Segment_certificate_key::Kind::x_order, a, b, 0, 0}, t);
}

template <class K>
Segment_sign Segment_predicates<K>::side(const Site_point& p, std::size_t s, const Time& t) const {
  if (p.on(s)) {
    ++counts_.identity;
    return {0, Segment_rule::identity};
  }
  return decide({Segment_certificate_key::Kind::side, p, {}, static_cast<std::uint32_t>(s), 0}, t);
}

template <class K>
Segment_sign Segment_predicates<K>::order_at(const Site_point& p, std::size_t i, std::size_t j, const Time& t) const {
  if (p.on(i)) return side(p, j, t);
  if (p.on(j)) {
    const Segment_sign r = side(p, i, t);
    return {-r.sign, r.rule, r.at_root};
  }
  return decide(
      {Segment_certificate_key::Kind::order_at, p, {}, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)}, t);
}

template <class K>
std::size_t Segment_predicates<K>::left_endpoint(std::size_t s, const Time& t) const {
  return compare_x(Site_point::endpoint(2 * s), Site_point::endpoint(2 * s + 1), t).sign < 0 ? 2 * s : 2 * s + 1;
}

#define KVD_INSTANTIATE_SEGMENT_PREDICATES(K) template class Segment_predicates<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SEGMENT_PREDICATES)

}  // namespace kvd::segments
