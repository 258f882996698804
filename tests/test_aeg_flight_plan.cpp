// Flight-plan changes of the run on the paper's certificates (seed 003,
// Lemma 3.1; Aeg_kinetic_bsp::set_motion): the certificates made again are
// exactly those naming the segment, the certificates after the change are a
// fresh run's on the changed scene from that instant, and the tree goes on
// changing where, and to what, the run keeping every sign changes it.
#include <catch2/catch.hpp>

#include "segment_scenes.hpp"
#include "kvd/detail/scene/priority.hpp"
#include "kvd/segments/aeg_certificates.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"

using namespace kvd;
using namespace kvd::segments;
using kvd::test::fixed;
using kvd::test::linear;
using kvd::test::moving;
using kvd::test::scene_of;

namespace {

const Exact_kernel kernel;  // the predicates keep its address
using Run = Aeg_kinetic_bsp<Exact_kernel>;

// Whether two runs hold the same certificates with the same failure times.
bool same_certificates(const Run& a, const Run& b) {
  const auto x = a.certificate_list(), y = b.certificate_list();
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i].first == y[i].first) || x[i].second.has_value() != y[i].second.has_value()) return false;
    if (x[i].second && kernel.compare(*x[i].second, *y[i].second) != 0) {
      UNSCOPED_INFO(aeg_certificate_subject(x[i].first) << " fails at " << x[i].second->to_string() << " against "
                                                        << y[i].second->to_string());
      return false;
    }
  }
  return true;
}

// The certificates in force naming segment s, counted from the outside: a
// transient cell's walls (the segments of their points), floor and roof; an
// endpoint's segment and its neighbours read off the tree; a flip's segment.
std::size_t naming(const Run& run, const Segment_scene& scene, std::size_t s) {
  const Segment_predicates<Exact_kernel> pred(kernel, scene);
  const Cylindrical_bsp tree = run.tree();
  std::size_t n = 0;
  for (const auto& [id, fails] : run.certificate_list()) {
    bool named = false;
    switch (id.kind) {
      case Aeg_certificate_kind::transient:
        for (const auto& p : {id.cell.left, id.cell.right}) named = named || (p && p->on(s));
        for (const auto& t : {id.cell.floor, id.cell.roof}) named = named || (t && *t == s);
        break;
      case Aeg_certificate_kind::endpoint:
        named = id.index / 2 == s;
        for (const std::int64_t t : aeg_neighbours(tree, pred, run.now(), id.index))
          named = named || t == static_cast<std::int64_t>(s);
        break;
      case Aeg_certificate_kind::flip: named = id.index == s; break;
    }
    n += named;
  }
  return n;
}

// The scene from `at` on (a rational instant), segment s following m.
Segment_scene changed(Segment_scene scene, std::size_t s, const Segment_motion& m, const mpq_class& at) {
  scene.segments[s].motion = m;
  scene.start = at;
  return scene;
}

// The run on the paper's set and the run keeping every sign, both at the
// same instant, go on to the span's end: the paper's run changes the tree at
// each of its batches, to the kept run's tree, validated between batches.
void go_on(Run& run, Kinetic_segment_bsp<Exact_kernel>& kept) {
  while (run.next_event_time()) {
    const auto b = run.advance();
    INFO("batch at t = " << b.time.to_string());
    for (const auto& k : kept.advance_to(b.time)) CHECK((k.changed == (kernel.compare(k.time, b.time) == 0)));
    CHECK(b.changed);
    CHECK(kept.tree().text() == run.tree().text());
  }
  while (kept.next_event_time()) CHECK_FALSE(kept.advance().changed);
  CHECK(run.validation_failures().empty());
}

Segment_motion endpoints_motion(const QPoly& x0, const QPoly& y0, const QPoly& x1, const QPoly& y1) {
  return moving(x0, y0, x1, y1).motion;
}

}  // namespace

// The scene of test_kinetic_segments' flight-plan test: s1 sinks from
// (2, 2 - t)-(6, -t) over s0 = (0, 0)-(4, 0) and passes over s0.1 at t = 1.
// Turned upwards at t = 1/2, before that edge event: nothing fails, the
// certificates naming s1 are made again and no other, and the events go
// away. Turned back exactly at the edge event: the certificates of what the
// event made fail again at once, and the tree goes back to the one before.
TEST_CASE("a flight-plan change on the paper's certificates", "[segments][aeg]") {
  const auto s = scene_of({fixed(0, 0, 4, 0), moving(linear(2, 0), linear(2, -1), linear(6, 0), linear(0, -1))},
                          {0, 1}, 0, 3);
  const Segment_motion up = endpoints_motion(linear(2, 0), linear(1, 1), linear(6, 0), linear(-1, 1));
  {
    Run run(kernel, s, true);
    CHECK(run.advance_to(Exact_time(mpq_class(1, 2))).empty());
    const std::size_t before = run.certificates(), named = naming(run, s, 1);
    CHECK(named < before);
    const auto b = run.set_motion(1, up);
    CHECK(b.failing.empty());
    CHECK_FALSE(b.changed);
    CHECK(b.certificates_made == named);
    CHECK(run.certificates() == before);
    CHECK(same_certificates(run, Run(kernel, changed(s, 1, up, mpq_class(1, 2)))));
    CHECK_FALSE(run.next_event_time());
  }
  {
    Run run(kernel, s, true);
    const std::string before = run.tree().text();
    REQUIRE(run.advance_to(Exact_time(mpq_class(1))).size() == 1);
    const Segment_motion back = endpoints_motion(linear(2, 0), linear(0, 1), linear(6, 0), linear(-2, 1));
    const auto b = run.set_motion(1, back);
    CHECK(b.changed);
    // The two cells the event made between the crossing's cuts and s0.1's
    // wall collapse at once, and s0.1's segment above changes back.
    const Site_point x = Site_point::crossing(0, 1), s01 = Site_point::endpoint(1);
    CHECK(b.failing == std::vector<Aeg_certificate_id>{{Aeg_certificate_kind::transient, 0, Cell{x, s01, {}, 0}},
                                                       {Aeg_certificate_kind::transient, 0, Cell{x, s01, 0, {}}},
                                                       {Aeg_certificate_kind::endpoint, 1, {}}});
    CHECK(run.tree().text() == before);
    const Run fresh(kernel, changed(s, 1, back, mpq_class(1)));
    CHECK(same_certificates(run, fresh));
    // A motion that jumps is refused, and changes nothing.
    CHECK_THROWS_AS(run.set_motion(1, up), std::invalid_argument);
    CHECK(run.tree().text() == before);
    CHECK(same_certificates(run, fresh));
  }
}

// test_kinetic_segments' flip scene: s3 turns through vertical at t = 0.
// Turned back at that instant, its flip certificate fails again at once, and
// the tree and certificates are those of a fresh run on the changed scene.
TEST_CASE("a flight-plan change at a flip turns the segment back on the paper's certificates", "[segments][aeg]") {
  const auto s = scene_of({fixed(10, 0, 12, 1), fixed(14, 2, 16, 3), fixed(-3, 1, 3, 1),
                           moving(linear(0, -1), linear(-2, 0), linear(0, 1), linear(2, 0))},
                          {3, 0, 1, 2}, -1, 1);
  Run run(kernel, s, true);
  const std::string before = run.tree().text();
  REQUIRE(run.advance_to(Exact_time(0)).size() == 1);
  REQUIRE(run.tree().text() != before);
  const Segment_motion back = endpoints_motion(linear(0, 1), linear(-2, 0), linear(0, -1), linear(2, 0));
  const auto b = run.set_motion(3, back);
  CHECK(b.changed);
  CHECK(std::count_if(b.failing.begin(), b.failing.end(),
                      [](const Aeg_certificate_id& id) { return id.kind == Aeg_certificate_kind::flip; }) == 1);
  CHECK(run.tree().text() == before);
  const Run fresh(kernel, changed(s, 3, back, mpq_class(0)));
  CHECK(run.tree().text() == fresh.tree().text());
  CHECK(same_certificates(run, fresh));
  CHECK_FALSE(run.next_event_time());
  CHECK(run.validation_failures().empty());
}

// Generated scenes (random and rotating, and the small-integer ones whose
// events are rational instants): a moving segment given a new linear motion
// from where it is, at the middle of the span and at a rational event
// instant. The certificates made again are those naming it (all of them,
// when none fails), the certificates after are a fresh run's, and from there
// the tree changes where and to what the kept run, given the same change,
// changes it.
TEST_CASE("flight-plan changes on generated scenes", "[segments][aeg]") {
  const auto scenes = kvd::test::generated_and_small(12, 6, 3);
  std::size_t quiet = 0, at_events = 0, failed_now = 0;
  for (const auto& [name, s] : scenes) {
    scene::Split_mix64 g(name.size() * 7919 + s.segments.size());
    std::size_t seg = 0;
    while (!s.is_moving(seg)) ++seg;
    // The middle of the span, and the first event at a rational instant.
    std::vector<mpq_class> instants{(s.start + *s.end) / 2};
    {
      Run probe(kernel, s);
      while (const auto t = probe.next_event_time()) {
        if (t->is_rational()) {
          instants.push_back(t->rational());
          break;
        }
        probe.advance();
      }
    }
    for (const mpq_class& at : instants) {
      INFO(name << ", segment " << seg << " changed at t = " << at.get_str());
      Run run(kernel, s, true);
      Kinetic_segment_bsp<Exact_kernel> kept(kernel, s, false);
      const auto done = run.advance_to(Exact_time(at));
      const bool event = !done.empty() && kernel.compare(done.back().time, Exact_time(at)) == 0;
      kept.advance_to(Exact_time(at));
      // From where each endpoint is at `at`, a new velocity.
      Segment_motion m;
      m.kind = Segment_motion::Kind::endpoints;
      for (const std::size_t k : {0, 1}) {
        const Point3 p = s.endpoint_at(2 * seg + k, at);
        for (const std::size_t c : {0, 1}) {
          const mpq_class v(static_cast<long>(g.between(-3, 3)));
          m.endpoints[k][c] = QPoly({mpq_class(p[c] / p[2]) - v * at, v});
        }
        m.endpoints[k][2] = QPoly(1);
      }
      const std::size_t named = naming(run, s, seg);
      const auto b = run.set_motion(seg, m);
      const bool kept_changed = kept.set_motion(seg, m);
      CHECK(b.changed == kept_changed);
      CHECK(run.tree().text() == kept.tree().text());
      if (b.failing.empty()) {
        CHECK(b.certificates_made == named);
        ++quiet;
      } else {
        ++failed_now;
      }
      at_events += event;
      CHECK(same_certificates(run, Run(kernel, changed(s, seg, m, at))));
      go_on(run, kept);
    }
  }
  // Both kinds of instant, and changes that fail certificates at once, occur.
  CHECK(quiet > 20);
  CHECK(at_events > 20);
  CHECK(failed_now > 5);
}

// A batch's simultaneous failures are taken in the order of what they are
// about, not the order in which they come off the heap of failure times.
// Setting a moving segment's own motion again at an instant changes
// nothing but that heap (its certificates are made again, with their
// failures pushed anew), so from there on the run decides the same signs,
// in the same parts of each update, as a run left alone; taken in the
// heap's order, the small-integer scenes' batches of several failures did
// not.
TEST_CASE("a run's batches do not depend on the order of its heap", "[segments][aeg]") {
  std::size_t compared = 0, several = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto s = kvd::test::small_integer_scene(seed);
    if (!s) continue;
    std::size_t seg = 0;
    while (!s->is_moving(seg)) ++seg;
    INFO("small " << seed << ", segment " << seg << " given its motion again");
    Run left(kernel, *s), touched(kernel, *s);
    const Exact_time at(mpq_class((s->start + *s->end) / 2));
    CHECK(left.advance_to(at).size() == touched.advance_to(at).size());
    CHECK(touched.set_motion(seg, s->segments[seg].motion).failing.empty());
    while (left.next_event_time()) {
      REQUIRE(touched.next_event_time());
      const auto a = left.advance(), b = touched.advance();
      INFO("batch at t = " << a.time.to_string());
      CHECK(a.failing == b.failing);
      CHECK(a.signs == b.signs);
      CHECK(a.phases.named() == b.phases.named());
      ++compared;
      several += a.failing.size() > 1;
    }
    CHECK_FALSE(touched.next_event_time());
  }
  CHECK(compared > 50);
  CHECK(several > 10);
}
