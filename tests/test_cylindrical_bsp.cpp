// The static cylindrical BSP of segments (seed 003, section 2.1): whole trees
// derived by hand, the invariants, agreement between kernels, and the
// symbolic perturbation against an explicit small one.
#include <catch2/catch.hpp>
#include <algorithm>

#include "kernels.hpp"
#include "segment_scenes.hpp"
#include "kvd/detail/scene/priority.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/segments/cylindrical_bsp.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"

using namespace kvd;
using namespace kvd::segments;
using kvd::test::fixed;
using kvd::test::linear;
using kvd::test::moving;
using kvd::test::scene_of;

namespace {

template <class K>
Cylindrical_bsp build_at(const Segment_scene& s, const mpq_class& t, const K& k = K()) {
  const Segment_predicates<K> pred(k, s);
  const auto time = k.time(from_rational<typename K::FT>(t));
  Cylindrical_bsp b = build_cylindrical_bsp(pred, time);
  const auto violations = bsp_violations(b, pred, time);
  INFO(b.text());
  for (const auto& v : violations) UNSCOPED_INFO(v);
  CHECK(violations.empty());
  return b;
}

// Small integer coordinates: shared x-coordinates, collinear triples and
// concurrent crossings are frequent.
Segment_scene random_scene(std::uint64_t seed, std::size_t n, long range) {
  scene::Split_mix64 g(seed);
  std::vector<Segment> segs;
  while (segs.size() < n) {
    const long x0 = g.between(-range, range), y0 = g.between(-range, range);
    const long x1 = g.between(-range, range), y1 = g.between(-range, range);
    if (x0 != x1 || y0 != y1) segs.push_back(fixed(x0, y0, x1, y1));
  }
  Segment_scene s;
  s.segments = std::move(segs);
  s.seed = seed;
  s.derive();
  return s;
}

// The scene with endpoint e moved by eps (λ_e, λ_e^2): the perturbation of
// the predicates made explicit.
Segment_scene explicitly_perturbed(const Segment_scene& s, const mpq_class& eps) {
  Segment_scene p = s;
  for (std::size_t e = 0; e < s.endpoint_count(); ++e) {
    Point3& r = p.segments[e / 2].rest[e % 2];
    const mpq_class g(perturbation_lambda(e, s.segments.size()));
    r[0] += eps * g * r[2];
    r[1] += eps * g * g * r[2];
  }
  return p;
}

}  // namespace

// Figure 1 of seed 003 in its smallest form: s1 crosses s0 once. Derived by
// following the three phases: s0 gets two vertex cuts and one edge cut;
// s1's vertex cuts fall above s0 (s1.0) and right of s0.1; the crossing gets
// an intersection cut above and below s0; s1's edge cut falls in the three
// leaves it then meets.
TEMPLATE_TEST_CASE("two crossing segments: the tree derived by hand", "[segments][bsp]", KVD_ALL_KERNELS) {
  const auto s = scene_of({fixed(0, 0, 4, 4), fixed(1, 4, 5, 0)}, {0, 1});
  const Cylindrical_bsp b = build_at<TestType>(s, 0);
  CHECK(b.text() ==
        "(V s0.0 . (V s0.1 (E s0 (I s0xs1 . (E s1 . .)) (V s1.0 . (I s0xs1 (E s1 . .) .))) (V s1.1 (E s1 . .) .)))");
  const Bsp_counts c = b.counts();
  CHECK(c.vertex_cuts == 4);
  CHECK(c.intersection_cuts == 2);
  CHECK(c.edge_cuts == 4);
  CHECK(c.nodes == 21);
  CHECK(c.height == 7);
}

// The first edge event of seed 003, section 3.1.2: s1 passes over the right
// endpoint of s0 (priority j = 0 < i = 1) at t = 1 and crosses s0 after it.
// Before: s1 lies above s0 in its cell. At t = 1 the tree is the one just
// after (sign_after decides that s0.1 is above s1), the same as for two
// crossing segments.
TEMPLATE_TEST_CASE("a segment over an endpoint: the trees before and after", "[segments][bsp]", KVD_ALL_KERNELS) {
  // s1 from (2, 2 - t) to (6, -t); at x = 4 it is at height 1 - t.
  const auto s = scene_of({fixed(0, 0, 4, 0), moving(linear(2, 0), linear(2, -1), linear(6, 0), linear(0, -1))}, {0, 1});
  CHECK(build_at<TestType>(s, 0).text() == "(V s0.0 . (V s0.1 (E s0 . (V s1.0 . (E s1 . .))) (V s1.1 (E s1 . .) .)))");
  const std::string after =
      "(V s0.0 . (V s0.1 (E s0 (I s0xs1 . (E s1 . .)) (V s1.0 . (I s0xs1 (E s1 . .) .))) (V s1.1 (E s1 . .) .)))";
  CHECK(build_at<TestType>(s, 1).text() == after);
  CHECK(build_at<TestType>(s, mpq_class(3, 2)).text() == after);
}

// A flip (section 3.1.4): s0 runs from (-t, -2) to (t, 2), vertical at t = 0.
// At t = 0 the tree is the one of t > 0, where s0.0 is the left endpoint and
// the crossing with s1 (at x = t/2) lies between s0.0 and s0.1.
TEMPLATE_TEST_CASE("a segment turning vertical: the tree at the flip", "[segments][bsp]", KVD_ALL_KERNELS) {
  const auto s = scene_of({moving(linear(0, -1), linear(-2, 0), linear(0, 1), linear(2, 0)), fixed(-3, 1, 3, 1)}, {1, 0});
  const std::string after =
      "(V s1.0 . (V s1.1 (E s1 (V s0.0 . (I s0xs1 (E s0 . .) .)) (V s0.1 (I s0xs1 . (E s0 . .)) .)) .))";
  CHECK(build_at<TestType>(s, 0).text() == after);
  CHECK(build_at<TestType>(s, 1).text() == after);
}

TEST_CASE("the symbolic perturbation equals an explicit small one", "[segments][bsp][perturbation]") {
  long perturbed = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Segment_scene s = random_scene(seed, 10, 4);
    const Exact_kernel k;
    const Segment_predicates<Exact_kernel> symbolic(k, s);
    const std::string expected = build_cylindrical_bsp(symbolic, k.time(0)).text();
    const Segment_scene p = explicitly_perturbed(s, mpq_class(1, mpz_class(1) << 60));
    const Segment_predicates<Exact_kernel> explicit_pred(k, p);
    INFO("seed " << seed);
    CHECK(build_cylindrical_bsp(explicit_pred, k.time(0)).text() == expected);
    CHECK(explicit_pred.counts().perturbation == 0);
    perturbed += symbolic.counts().perturbation;
  }
  CHECK(perturbed > 100);  // the scenes are degenerate enough to test it
}

// Three segments through the origin. The perturbation moves endpoint e by
// eps (λ_e, λ_e^2) with λ = 1, 2 (s0), 15, 16 (s1), 27, 28 (s2) (three
// segments: p = 3, a = 0, 7, 13). To first order in eps the lines become
// y = x + eps (s0), y = -x + 264 eps (s1), y = -x/4 + 763.4 eps (s2), so the
// crossings part into a small triangle with x(s1xs2) = -665.8 eps <
// x(s0xs1) = 131.5 eps < x(s0xs2) = 609.9 eps, s1xs2 above s0 and s0xs2
// above s1. Following the three phases with these positions gives the tree
// below (s2's crossing walk meets s0 first, then s1 above s0 left of s0xs1).
TEST_CASE("three concurrent segments: the tree derived by hand under the perturbation", "[segments][bsp][perturbation]") {
  const auto s = scene_of({fixed(-2, -2, 2, 2), fixed(-3, 3, 1, -1), fixed(-4, 1, 4, -1)}, {0, 1, 2});
  CHECK(build_at<Exact_kernel>(s, 0).text() ==
        "(V s0.0 (V s1.0 (V s2.0 . (E s2 . .)) (E s1 (E s2 . .) .)) (V s0.1 (E s0 (V s1.1 (I s0xs1 . (E s1 . (I "
        "s0xs2 . (E s2 . .)))) (E s2 . .)) (I s0xs1 (E s1 (I s1xs2 (E s2 . .) .) (I s1xs2 . (E s2 . .))) (I s0xs2 "
        "(E s2 . .) .))) (V s2.1 (E s2 . .) .)))");
}

TEST_CASE("the invariants catch a tree that is not a BSP of its segments", "[segments][bsp]") {
  const auto s = scene_of({fixed(0, 0, 4, 4), fixed(1, 4, 5, 0)}, {0, 1});
  const Exact_kernel k;
  const Segment_predicates<Exact_kernel> pred(k, s);
  const Cylindrical_bsp good = build_cylindrical_bsp(pred, k.time(0));
  CHECK(bsp_violations(good, pred, k.time(0)).empty());
  // The children of s0's edge cut swapped: cells no longer match their cuts,
  // and s1's fragments lie in the wrong cells.
  Cylindrical_bsp swapped = good;
  for (Bsp_node& n : swapped.nodes)
    if (n.kind == Cut_kind::edge && n.segment == 0) std::swap(n.child[0], n.child[1]);
  // Among them a cell of s0 and s1 upside down, named with the wall where
  // it is: at x = 1 (s1's endpoint 0) s0 is at y = 1 and s1 at y = 4.
  const auto w = bsp_violations(swapped, pred, k.time(0));
  CHECK(std::find(w.begin(), w.end(), "node 18: its roof s0 passes below its floor s1 at the wall through s1.0") !=
        w.end());
  // A fragment of s1 dropped (its edge cut made a leaf): a gap in the tiling,
  // and s1 meets a leaf's interior.
  Cylindrical_bsp dropped = good;
  dropped.nodes[dropped.fragments(1).back()].kind = Cut_kind::leaf;
  const auto v = bsp_violations(dropped, pred, k.time(0));
  CHECK(std::any_of(v.begin(), v.end(), [](const std::string& m) { return m.find("meets the leaf") != std::string::npos; }));
}

TEST_CASE("random segment scenes satisfy the BSP invariants", "[segments][bsp]") {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    INFO("seed " << seed);
    build_at<Exact_kernel>(random_scene(seed, 12, 20), 0);
  }
}

// Small integers: the floating-point kernels compute every value exactly,
// so they must build the exact tree, degenerate cases included.
TEMPLATE_TEST_CASE("random segment scenes: every kernel builds the exact tree", "[segments][bsp]", Double_kernel,
                   Mpfr_kernel) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const Segment_scene s = random_scene(seed, 12, 20);
    INFO("seed " << seed);
    const Exact_kernel exact;
    const TestType k;
    const std::string expected = build_cylindrical_bsp(Segment_predicates<Exact_kernel>(exact, s), exact.time(0)).text();
    CHECK(build_cylindrical_bsp(Segment_predicates<TestType>(k, s), k.time(0)).text() == expected);
  }
}

// The exact kernel's interval filter decides a sign only when its interval
// excludes zero: with and without it, the same tree and the same rules, on
// degenerate scenes (where it must leave zeros and perturbations alone), on
// rotating ones at rational instants and at the algebraic instants of their
// events (where signs are zero or near it).
TEST_CASE("the segment predicates' interval filter changes no tree", "[segments][bsp][filter]") {
  const auto same = [](const Segment_scene& s, const Exact_time& t) {
    const Exact_kernel on(true), off(false);
    const Segment_predicates<Exact_kernel> a(on, s), b(off, s);
    CHECK(build_cylindrical_bsp(a, t).text() == build_cylindrical_bsp(b, t).text());
    CHECK(a.counts().value == b.counts().value);
    CHECK(a.counts().after == b.counts().after);
    CHECK(a.counts().perturbation == b.counts().perturbation);
    CHECK(b.counts().filtered == 0);
    return a.counts().filtered;
  };
  long filtered = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) filtered += same(random_scene(seed, 12, 20), Exact_time(mpq_class(0)));
  const Segment_scene s = kvd::test::generated(Segment_family::rotating, 12, 3, 2);
  for (const mpq_class& t : {mpq_class(0), mpq_class(1, 3), mpq_class(5, 4)}) filtered += same(s, Exact_time(t));
  Kinetic_segment_bsp<Exact_kernel> kin(Exact_kernel(), s, false);
  std::size_t algebraic = 0;
  for (int n = 0; n < 12 && kin.next_event_time(); ++n) {
    const Exact_time t = kin.advance().time;
    algebraic += !t.is_rational();
    INFO("t = " << t.to_string());
    filtered += same(s, t);
  }
  CHECK(algebraic > 0);
  CHECK(filtered > 1000);
}

// Segment_predicates::remember: a key asked again at the remembered instant
// gets the sign, rule and root flag that the rules gave it (checked against
// predicates that remember nothing), without being decided again, and a
// recorder still hears of it (without polynomials); a recorder that wants
// polynomials, held signs, another instant object, another `remember`,
// `refresh` and `forget` are decided afresh. Keys of endpoints and of the
// crossings present at the instant, asked both ways round. Degenerate
// scenes (zeros at the instant, perturbation) and, in the exact kernel, the
// algebraic instants of a rotating scene's events (signs just after).
TEMPLATE_TEST_CASE("a remembered instant answers a key asked again as the rules did", "[segments][predicates]",
                   KVD_ALL_KERNELS) {
  using Key = Segment_certificate_key;
  const TestType k;
  const auto check = [&](const Segment_scene& s, const typename TestType::Time& t) {
    const std::size_t n = s.segments.size();
    std::vector<Site_point> points;
    for (std::size_t e = 0; e < 2 * n; ++e) points.push_back(Site_point::endpoint(e));
    {
      const Segment_predicates<TestType> pick(k, s);  // (its signs are not counted below)
      const auto apart = [&](std::size_t i, std::size_t j) {
        return pick.side(Site_point::endpoint(2 * i), j, t).sign * pick.side(Site_point::endpoint(2 * i + 1), j, t).sign < 0;
      };
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
          if (apart(i, j) && apart(j, i)) points.push_back(Site_point::crossing(i, j));
    }
    std::vector<Key> keys;
    for (std::size_t a = 0; a < points.size(); ++a) {
      const Site_point& p = points[a];
      for (std::size_t b = a + 1; b < points.size(); ++b) keys.push_back({Key::Kind::x_order, p, points[b], 0, 0});
      for (std::uint32_t i = 0; i < n; ++i) {
        if (p.on(i)) continue;
        keys.push_back({Key::Kind::side, p, {}, i, 0});
        for (std::uint32_t j = i + 1; j < n; ++j)
          if (!p.on(j)) keys.push_back({Key::Kind::order_at, p, {}, i, j});
      }
    }
    Segment_predicates<TestType> remembering(k, s);
    const Segment_predicates<TestType> plain(k, s);
    remembering.remember(t);
    const auto same = [&](const Segment_sign& a, const Segment_sign& b) {
      return a.sign == b.sign && a.rule == b.rule && a.at_root == b.at_root;
    };
    for (const Key& key : keys) CHECK(same(remembering.sign_of(key, t), plain.sign_of(key, t)));
    const long decided = remembering.counts().decided();
    CHECK(decided == plain.counts().decided());
    // Asked again, the other way round where a key has two: the same signs,
    // none decided, and a recorder without polynomials hears each.
    std::vector<std::pair<Key, int>> heard;
    remembering.record([&](const Key& key, std::vector<typename TestType::Poly>&& polys, std::int32_t, int sign) {
      CHECK(polys.empty());
      heard.emplace_back(key, sign);
    }, false);
    long asked = 0;
    for (const Key& key : keys) {
      const Segment_sign r = key.kind == Key::Kind::x_order ? remembering.compare_x(key.q, key.p, t)
                                                             : remembering.sign_of(key, t);
      const Segment_sign p = key.kind == Key::Kind::x_order ? plain.compare_x(key.q, key.p, t) : plain.sign_of(key, t);
      CHECK(same(r, p));
      asked += r.rule != Segment_rule::identity;
    }
    CHECK(remembering.counts().decided() == decided);
    CHECK(remembering.counts().repeated == asked);
    CHECK(static_cast<long>(heard.size()) == asked);
    for (const auto& [key, sign] : heard) CHECK(sign == plain.sign_of(key, t).sign);
    // A recorder that wants polynomials gets every key decided again.
    remembering.record([](const Key&, std::vector<typename TestType::Poly>&&, std::int32_t, int) {});
    for (const Key& key : keys) remembering.sign_of(key, t);
    remembering.record({});
    CHECK(remembering.counts().decided() == decided + asked);
    CHECK(remembering.counts().repeated == asked);
    // Held signs are the caller's: while held is set, nothing is remembered
    // (the exact kernel's filter still comes first).
    remembering.held([](const Key&) { return std::optional<int>(1); });
    for (const Key& key : keys) remembering.sign_of(key, t);
    remembering.held({});
    CHECK(remembering.counts().held > 0);
    CHECK(remembering.counts().decided() + remembering.counts().held == decided + 2 * asked);
    CHECK(remembering.counts().repeated == asked);
    long now = remembering.counts().decided();
    const typename TestType::Time copy = t;  // the same instant, another object: not remembered
    remembering.sign_of(keys.front(), copy);
    CHECK(remembering.counts().decided() == ++now);
    remembering.remember(copy);  // another instant ends the first one
    remembering.sign_of(keys.front(), t);
    CHECK(remembering.counts().decided() == ++now);
    remembering.sign_of(keys.front(), copy);
    remembering.remember(copy);  // remembering an instant again starts afresh (its value may have moved)
    remembering.sign_of(keys.front(), copy);
    CHECK(remembering.counts().decided() == (now += 2));
    remembering.remember(t);
    remembering.sign_of(keys.front(), t);
    remembering.refresh(0, t);
    remembering.sign_of(keys.front(), t);
    CHECK(remembering.counts().decided() == (now += 2));
    remembering.remember(t);
    remembering.sign_of(keys.front(), t);
    remembering.forget();
    remembering.sign_of(keys.front(), t);
    CHECK(remembering.counts().decided() == (now += 2));
    return plain.counts();
  };
  Segment_rule_counts rules;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Segment_rule_counts c = check(random_scene(seed, 8, 6), k.time(0));
    rules.perturbation += c.perturbation;
  }
  CHECK(rules.perturbation > 0);
  if constexpr (std::is_same_v<TestType, Exact_kernel>) {
    const Segment_scene s = kvd::test::generated(Segment_family::rotating, 8, 3, 2);
    Kinetic_segment_bsp<Exact_kernel> kin(k, s, false);
    for (int n = 0; n < 6 && kin.next_event_time(); ++n) rules.after += check(s, kin.advance().time).after;
    CHECK(rules.after > 0);
  }
}
