// The predicates of the cylindrical BSP of segments (seed 003, section 2.1),
// on (t, t + δ) and in a symbolically perturbed scene, over any kernel.
//
// Every sign goes through one entry point, `decide`, which records the rule
// that decided (as the KVD's classification does, DESIGN.md section 4):
//  1. identity: the point lies on the segment by construction (an endpoint of
//     it, or a crossing it defines), or two points are the same point: 0,
//     without arithmetic;
//  2. the sign at t of the value, a polynomial in t (in the exact kernel,
//     when no recorder wants the polynomials, first by a certified interval
//     filter that decides only when zero is excluded);
//  3. if that is zero, the sign just after t (kernel sign_after);
//  4. if the value is identically zero in t, the symbolic perturbation:
//     endpoint e moved by ε (λ_e, λ_e^2) (on the parabola), ε -> 0+ after
//     time; the sign of the first coefficient in ε that is not identically
//     zero, decided by rules 2-3. proofs/segment-perturbation.md proves that
//     with the λ of `perturbation_lambda` some coefficient never vanishes,
//     for every predicate here: a vanishing one is a bug (std::logic_error).
// A kinetic run may name the signs it already knows (`held`): the sign of a
// certificate in force, decided earlier by rules 2-4 and unchanged since
// (none of its polynomials has a root between then and t), is taken as is,
// without arithmetic (rule `held`). At an instant it remembers (`remember`),
// decide answers a key asked again from its first decision.
//
// Points are homogeneous (X, Y, W). Endpoints are scaled so that W > 0 on the
// whole span (the loader rejects a W that vanishes there); a derived point's
// W may have either sign and is taken into every sign it enters.
#pragma once

#include <algorithm>
#include <array>
#include <compare>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <boost/container/static_vector.hpp>

#include "kvd/segments/segment_scene.hpp"

namespace kvd::segments {

namespace detail {
class Segment_filter;  // src/segments/segment_filter.hpp
}

// A point of the arrangement that a cut passes through: an endpoint, or the
// crossing of two segments (a < b).
struct Site_point {
  enum class Kind : std::uint8_t { endpoint, crossing };
  Kind kind = Kind::endpoint;
  std::uint32_t a = 0, b = 0;

  static Site_point endpoint(std::size_t e) { return {Kind::endpoint, static_cast<std::uint32_t>(e), 0}; }
  static Site_point crossing(std::size_t i, std::size_t j) {
    const auto lo = static_cast<std::uint32_t>(i < j ? i : j), hi = static_cast<std::uint32_t>(i < j ? j : i);
    return {Kind::crossing, lo, hi};
  }
  // Whether the point lies on segment s by construction.
  bool on(std::size_t s) const { return kind == Kind::endpoint ? a / 2 == s : (a == s || b == s); }
  friend auto operator<=>(const Site_point&, const Site_point&) = default;
};

// λ_e of endpoint e in a scene of n segments: segment i has λ = 2 a_i + 1
// and 2 a_i + 2, where a_i = 2 p i + (i^2 mod p) for the smallest prime
// p >= n (Erdős–Turán), a Sidon set: no two pairs of a's have the same sum.
// That is what makes every predicate's leading ε-coefficient non-zero.
long perturbation_lambda(std::size_t e, std::size_t n);

enum class Segment_rule { identity, value, after, perturbation, held };

// A predicate with its arguments: the identity of a certificate.
struct Segment_certificate_key {
  enum class Kind : std::uint8_t { x_order, side, order_at };
  Kind kind = Kind::x_order;
  Site_point p, q;              // x_order: p against q; side and order_at: p
  std::uint32_t i = 0, j = 0;   // side: the segment i; order_at: the lines of i and j
  friend auto operator<=>(const Segment_certificate_key&, const Segment_certificate_key&) = default;
};

// The key of the x order of points p and q, whichever way round they are
// asked (Segment_predicates::compare_x decides it in this order).
inline Segment_certificate_key x_order_key(const Site_point& p, const Site_point& q) {
  return {Segment_certificate_key::Kind::x_order, std::min(p, q), std::max(p, q), 0, 0};
}

// A hash of keys, for the tables of certificates a kinetic run looks up
// for every sign it decides.
struct Segment_certificate_key_hash {
  std::size_t operator()(const Segment_certificate_key& k) const noexcept {
    const auto mix = [](std::uint64_t h, std::uint64_t x) {  // splitmix64's finaliser on h ^ x
      h ^= x + 0x9e3779b97f4a7c15ULL;
      h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
      h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
      return h ^ (h >> 31);
    };
    const auto point = [](const Site_point& p) {
      return (std::uint64_t(p.a) << 32 | p.b) ^ (std::uint64_t(p.kind) << 63);
    };
    std::uint64_t h = mix(std::uint64_t(k.kind), point(k.p));
    h = mix(h, point(k.q));
    return static_cast<std::size_t>(mix(h, std::uint64_t(k.i) << 32 | k.j));
  }
};

// The segments a certificate names (its points' segments, and i and j), with
// repeats; at most four (two crossings, or a crossing and two lines), kept
// in place: the interval filter asks for them at every sign.
boost::container::static_vector<std::size_t, 4> named_segments(const Segment_certificate_key& k);

// Names for printing only: "s3.0" (endpoint 0 of segment 3), "s1xs4" (a
// crossing); a key's kind ("x_order", "side", "order_at") and its features
// ("s3.0 s1xs4", "s3.0 s2", "s1xs4 s2 s5": the points, then the segments).
std::string point_name(const Site_point& p);
const char* kind_name(Segment_certificate_key::Kind k);
std::string features(const Segment_certificate_key& k);

// The kinds of critical events of seed 003, section 3.1.
enum class Segment_event { vertex, edge, intersection, flip };
inline constexpr const char* segment_event_names[] = {"vertex", "edge", "intersection", "flip"};
// The event a certificate's failure is (`rank`: the segments' priority
// places): the x order of a segment's own endpoints, a flip; of an endpoint
// and another point, a vertex event; an endpoint of s_i crossing s_j, an
// intersection event when j has the higher priority (j < i) and an edge event
// (s_j passes over a corner of a cell of s_i's) otherwise; anything about a
// crossing or the order of two lines at a point, an edge event.
Segment_event event_of(const Segment_certificate_key& k, const std::vector<std::size_t>& rank);
// The segments that turn through vertical in a batch: those whose endpoints'
// x order is among its failing keys, sorted.
std::vector<std::size_t> turning_segments(const std::vector<Segment_certificate_key>& failing);
// Whether a failure is part of a flip of the batch (`turning`): the x order
// of two points of a turning segment, which all reach one abscissa together.
bool part_of_flip(const Segment_certificate_key& k, const std::vector<std::size_t>& turning);
// The event a failure of a batch is: a flip when part_of_flip (so the x order
// of an endpoint and a crossing of the turning segment is not a vertex
// event, nor that of two of its crossings an edge event), else event_of.
Segment_event event_in_batch(const Segment_certificate_key& k, const std::vector<std::size_t>& rank,
                             const std::vector<std::size_t>& turning);

struct Segment_sign {
  int sign;           // -1, 0, +1
  Segment_rule rule;  // the rule that decided
  // Whether a polynomial that decided it (a factor, or the first ε-coefficient
  // of one that vanishes for good) vanishes at the instant asked: the sign may
  // change there. Not known for a held sign.
  bool at_root = false;
};

struct Segment_rule_counts {
  long identity = 0, value = 0, after = 0, perturbation = 0;
  long filtered = 0;  // of `value`, decided by the exact kernel's interval filter
  long held = 0;      // taken from a certificate in force (Segment_predicates::held)
  long repeated = 0;  // asked again at a remembered instant (Segment_predicates::remember)
  // The signs decided by any rule but `held` (a repeat is not decided again).
  long decided() const { return identity + value + after + perturbation; }
};

// The lines of the segments and the crossings of two, made once.
template <class R>
struct Geometry_cache {
  std::vector<std::optional<std::array<R, 3>>> lines;
  std::unordered_map<std::uint64_t, std::array<R, 3>> crossings;
};

template <class K>
class Segment_predicates {
public:
  using P = typename K::Poly;
  using Time = typename K::Time;
  // The homogeneous coordinates of a point or a line, over a ring R.
  template <class R>
  using H = std::array<R, 3>;

  Segment_predicates(const K& k, const Segment_scene& s);

  const K& kernel() const { return *k_; }
  const Segment_scene& scene() const { return *s_; }
  std::size_t size() const { return s_->segments.size(); }

  // sign(x(a) - x(b)); 0 by identity when a == b.
  Segment_sign compare_x(const Site_point& a, const Site_point& b, const Time& t) const;
  // sign(y(p) - y_s(x(p))): +1 when p is above the line of s; 0 by identity
  // when p lies on s.
  Segment_sign side(const Site_point& p, std::size_t s, const Time& t) const;
  // sign(y_i(x(p)) - y_j(x(p))): the vertical order of the lines of i and j
  // at the abscissa of p; 0 by identity when p lies on both.
  Segment_sign order_at(const Site_point& p, std::size_t i, std::size_t j, const Time& t) const;
  // The sign of a key's predicate: compare_x, side or order_at by its kind.
  Segment_sign sign_of(const Segment_certificate_key& key, const Time& t) const;
  // The endpoint of s with the smaller x, and the other one.
  std::size_t left_endpoint(std::size_t s, const Time& t) const;
  std::size_t right_endpoint(std::size_t s, const Time& t) const { return left_endpoint(s, t) ^ 1U; }

  // How many signs each rule decided.
  const Segment_rule_counts& counts() const { return counts_; }

  // While set, every sign decided by arithmetic is reported with the
  // polynomials in t that decided it (each factor's value or its first
  // ε-coefficient that does not vanish, constants left out: the sign stays
  // until one of them changes sign) and the node `at_node` last named (-1:
  // none). A construction reports its complete certificate set this way,
  // since it branches on nothing else. Without `polynomials`, the recorder
  // may get no polynomial (for a caller that compares signs, not failure
  // times): in the exact kernel the interval filter may decide the sign
  // first, and at a remembered instant a key asked again is not decided.
  using Recorder =
      std::function<void(const Segment_certificate_key&, std::vector<P>&&, std::int32_t node, int sign)>;
  void record(Recorder r, bool polynomials = true) const {
    recorder_ = std::move(r);
    record_polynomials_ = polynomials;
  }
  void at_node(std::int32_t n) const { node_ = n; }
  // While set, a key it gives a sign for is decided by that sign, reported
  // to the recorder with no polynomial (the caller holds them). Only for the
  // certificates in force, whose sign holds until their failure time, and
  // for a key already decided at the same instant in a construction under
  // way.
  using Held = std::function<std::optional<int>(const Segment_certificate_key&)>;
  void held(Held h) const { held_ = std::move(h); }
  // While set, the signs decided at instant `t` (that very object: the
  // caller's own, which must outlive it and keep its value meanwhile) are
  // kept, and a key asked there again is answered from them without
  // arithmetic (counted `repeated`, not decided), unless a recorder wants
  // its polynomials or `held` is set (a held sign is the caller's to give).
  // A kinetic update asks many keys more than once at its instant: the
  // crossing bounding two parts of a segment, a key its guards ask and its
  // replay decides. `forget` ends it, and so do another `remember` and
  // `refresh` (a motion changed).
  void remember(const Time& t) const {
    forget();
    remembered_at_ = &t;
  }
  void forget() const {
    if (!remembered_.empty()) remembered_.clear();  // (clear costs the buckets even when empty)
    remembered_at_ = nullptr;
  }
  // Reads segment s's endpoints from the scene again (its motion changed),
  // with the sign of their W at `at`.
  void refresh(std::size_t segment, const Time& at);

private:
  // The single entry point: the sign of the product of the key's factors
  // (detail/segments/segment_factors.hpp), each decided by rules 2-4; in the
  // exact kernel, unless a recorder wants polynomials, first by the interval
  // filter; at a remembered instant, a key asked again from its first
  // decision (remember).
  Segment_sign decide(const Segment_certificate_key& key, const Time& t) const;
  // decide's rules, without the remembered signs.
  Segment_sign decide_by_rules(const Segment_certificate_key& key, const Time& t) const;
  bool vanishes(const P& f) const;
  void load(std::size_t e, int w);

  const K* k_;
  const Segment_scene* s_;
  std::vector<H<P>> endpoints_;           // W > 0 on the span
  std::vector<H<Poly<P>>> perturbed_;     // endpoint + ε g_e
  mutable Geometry_cache<P> cache_;
  mutable Segment_rule_counts counts_;
  mutable Recorder recorder_;
  mutable bool record_polynomials_ = true;
  mutable Held held_;
  mutable std::int32_t node_ = -1;
  mutable const Time* remembered_at_ = nullptr;
  mutable std::unordered_map<Segment_certificate_key, Segment_sign, Segment_certificate_key_hash> remembered_;
  std::shared_ptr<detail::Segment_filter> filter_;  // the exact kernel's, unless built without
};

}  // namespace kvd::segments
