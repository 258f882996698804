// The kinetic segment BSP run on the paper's certificates alone
// (kvd/segments/aeg_kinetic_bsp.hpp): the failures derived by hand on a small
// scene, and on bundled and generated scenes the same tree changes, at the
// same exact instants, as the run that keeps every sign of its construction.
#include <catch2/catch.hpp>

#include "segment_scenes.hpp"
#include "kvd/detail/segments/bsp_builder.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/segments/aeg_certificates.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "kvd/segments/segment_io.hpp"

using namespace kvd;
using namespace kvd::segments;
using kvd::test::fixed;
using kvd::test::linear;
using kvd::test::moving;
using kvd::test::scene_of;

namespace {

const Exact_kernel kernel;  // the predicates keep its address

Aeg_certificate_id endpoint(std::size_t e) { return {Aeg_certificate_kind::endpoint, e, {}}; }
Aeg_certificate_id transient(std::optional<Site_point> left, std::optional<Site_point> right,
                             std::optional<std::uint32_t> floor, std::optional<std::uint32_t> roof) {
  return {Aeg_certificate_kind::transient, 0, Cell{left, right, floor, roof}};
}

}  // namespace

// The scene of test_aeg_certificates' hand derivation: s0 from (0, 0) to
// (4, 0); s1 from (2, 2 - t) to (6, -t), 1 - t above x = 4. At t = 1 s1
// passes over s0.1 (an edge event): the side of s0.1 to its segment above,
// s1, changes, and that is the only certificate of the tree before that
// fails (the two cells the event makes are born, not collapsed). At t = 2
// s1.0 passes down through s0 (an intersection event): the side of s1.0 to
// its segment below, s0, changes, and the transient cell between s1.0's wall
// and the crossing s0xs1, above s0, collapses as the crossing passes left of
// s1.0. Nothing else fails up to the end at t = 3: the segments do not flip,
// and s0.0 and s1.1 have no segment above or below.
TEST_CASE("a segment over an endpoint: the paper's certificates fail at the two events", "[segments][aeg]") {
  const auto s = scene_of({fixed(0, 0, 4, 0), moving(linear(2, 0), linear(2, -1), linear(6, 0), linear(0, -1))},
                          {0, 1}, 0, 3);
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, s);
  // Five transient nodes, four endpoints and two segments.
  CHECK(run.certificates() == 11);
  const Site_point s10 = Site_point::endpoint(2), x = Site_point::crossing(0, 1);

  REQUIRE(run.next_event_time());
  const auto edge = run.advance();
  CHECK(edge.time.to_string() == "1");
  CHECK(edge.failing == std::vector<Aeg_certificate_id>{endpoint(1)});
  CHECK(edge.changed);
  // s1 crosses s0 just left of s0.1: the crossing's cuts below and above s0.
  CHECK(run.tree().text() == "(V s0.0 . (V s0.1 (E s0 (I s0xs1 . (E s1 . .)) (V s1.0 . (I s0xs1 (E s1 . .) .))) "
                             "(V s1.1 (E s1 . .) .)))");

  REQUIRE(run.next_event_time());
  const auto intersection = run.advance();
  CHECK(intersection.time.to_string() == "2");
  CHECK(intersection.failing == std::vector<Aeg_certificate_id>{transient(s10, x, 0, {}), endpoint(2)});
  CHECK(intersection.changed);
  CHECK_FALSE(run.next_event_time());
}

namespace {

// Whether the run's log is a fresh construction's just after t, node by
// node in pre-order: what the flips done in place and the replays edit is
// what later replays start from.
bool same_log(const Aeg_kinetic_bsp<Exact_kernel>& run, const Segment_predicates<Exact_kernel>& pred, const Exact_time& t) {
  Cylindrical_bsp fresh;
  Build_log log;
  Bsp_builder<Exact_kernel> builder(pred, t, fresh, &log);
  builder.start();
  for (const std::size_t s : pred.scene().priority_order) builder.insert(static_cast<std::uint32_t>(s));
  const std::vector<std::size_t> a = run.edited_tree().preorder(), b = fresh.preorder();
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (run.log().at[a[k]] != log.at[b[k]]) {
      UNSCOPED_INFO("the logs differ at the node " << k << " in pre-order");
      return false;
    }
  return true;
}

// After the last batch b of a hand scene: the tree a fresh construction
// makes at `mid` (after b), its log, the leaf beside every endpoint, and
// nothing more to fail or found wrong by validation.
void ends_as_fresh(Aeg_kinetic_bsp<Exact_kernel>& run, const Segment_predicates<Exact_kernel>& pred,
                   const Aeg_kinetic_bsp<Exact_kernel>::Batch& b, const mpq_class& mid) {
  CHECK(run.tree().text() == build_cylindrical_bsp(pred, Exact_time(mid)).text());
  CHECK(same_log(run, pred, b.time));
  for (std::size_t e = 0; e < 2 * pred.size(); ++e) CHECK(run.leaf_beside(e) == aeg_leaf(run.edited_tree(), pred, b.time, e));
  CHECK_FALSE(run.next_event_time());
  CHECK(run.validation_failures().empty());
}

// The run's next batch, which must be at `at`, stepped to from `before`.
Aeg_kinetic_bsp<Exact_kernel>::Batch batch_at(Aeg_kinetic_bsp<Exact_kernel>& run, const mpq_class& before,
                                              const mpq_class& at) {
  run.advance_to(Exact_time(before));
  REQUIRE(kernel.compare(*run.next_event_time(), Exact_time(at)) == 0);
  return run.advance();
}

// After a batch at `at` of scene s: the tree the subtree update of a run
// started at `at` holds, and a fresh construction's log.
void as_fresh_at(const Aeg_kinetic_bsp<Exact_kernel>& run, const Segment_predicates<Exact_kernel>& pred,
                 const Segment_scene& s, const mpq_class& at) {
  const Kinetic_segment_bsp<Exact_kernel> fresh(kernel, s, false, Segment_update::subtree, Exact_time(at));
  CHECK(run.tree().text() == fresh.tree().text());
  CHECK(same_log(run, pred, Exact_time(at)));
}

// The validated run of small-integer scene `seed`: its batch at `at`,
// stepped to from `before`, given to expect(scene, batch), then as_fresh_at
// `at`; with `to_end`, the run goes on to its span's end. No validation
// fails.
template <class Expect>
void small_integer_batch(std::uint64_t seed, const mpq_class& before, const mpq_class& at, Expect expect,
                         bool to_end = true) {
  const auto s = kvd::test::small_integer_scene(seed);
  REQUIRE(s);
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, *s, true);
  const Segment_predicates<Exact_kernel> pred(kernel, *s);
  expect(*s, batch_at(run, before, at));
  as_fresh_at(run, pred, *s, at);
  if (to_end)
    while (run.next_event_time()) run.advance();
  CHECK(run.validation_failures().empty());
}

// What side_by_side counts.
struct Compared {
  std::size_t batches = 0, kept_batches = 0, replays = 0, nodes_rebuilt = 0, flipped = 0, frontier = 0;
  std::size_t apart = 0;  // batches some of whose certificates were rerouted, the others' subtrees made again
  std::array<std::size_t, 3> caught{};  // batches where a certificate of each kind fails
};

// Runs scene s on the paper's certificates (validated against fresh builds
// between batches) beside the run keeping every sign, up to `end` (or the
// span's end): the kept run changes the tree at exactly the batches of the
// paper's run, and to its tree. With `neighbours`, at every batch the
// neighbours read off the tree are those of the scan over all segments.
void side_by_side(const std::string& name, const Segment_scene& s, bool neighbours, Compared& c,
                  const std::optional<Exact_time>& end = std::nullopt) {
  Kinetic_segment_bsp<Exact_kernel> kept(kernel, s, false);
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, s, true);
  const Segment_predicates<Exact_kernel> pred(kernel, s);
  const auto next = [&](auto& r) {
    const auto t = r.next_event_time();
    return t && (!end || kernel.compare(*t, *end) <= 0) ? t : std::nullopt;
  };
  while (next(run) || next(kept)) {
    // The kept run's batches that leave the tree as it was come first.
    while (next(kept) && (!next(run) || kernel.compare(*next(kept), *next(run)) < 0)) {
      const auto b = kept.advance();
      ++c.kept_batches;
      INFO(name << ": the tree changes at t = " << b.time.to_string() << " with no paper certificate failing");
      CHECK_FALSE(b.changed);
    }
    if (!next(run)) break;
    const auto b = run.advance();
    ++c.batches;
    c.replays += b.replays;
    c.nodes_rebuilt += b.nodes_rebuilt;
    c.flipped += b.flipped_in_place > 0;
    c.frontier += b.frontier_replays > 0;
    c.apart += b.frontier_replays > 0 && b.frontier_replays < b.replays;
    INFO(name << ": batch at t = " << b.time.to_string());
    CHECK(b.changed);
    // Where its signs were decided accounts for some of them, never more.
    const auto& p = b.phases;
    CHECK(p.own_guard + p.other_guard + p.ties + p.certificates + p.leaves + p.walls <= b.signs);
    CHECK(p.certificates > 0);  // the failing ones, at least, are read at the instant
    CHECK(same_log(run, pred, b.time));
    // The leaf each endpoint's certificate reads is the one beside it.
    for (std::size_t e = 0; e < 2 * s.segments.size(); ++e) {
      INFO("the leaf beside " << point_name(Site_point::endpoint(e)));
      CHECK(run.leaf_beside(e) == aeg_leaf(run.edited_tree(), pred, b.time, e));
    }
    REQUIRE(next(kept));
    REQUIRE(kernel.compare(*next(kept), b.time) == 0);
    kept.advance();
    ++c.kept_batches;
    CHECK(kept.tree().text() == run.tree().text());
    std::array<bool, 3> kinds{};
    for (const auto& id : b.failing) kinds[static_cast<std::size_t>(id.kind)] = true;
    for (std::size_t k = 0; k < 3; ++k) c.caught[k] += kinds[k];
    if (!neighbours) continue;
    const Aeg_state scan = aeg_state(pred, b.time);
    for (std::size_t e = 0; e < scan.neighbours.size(); ++e) {
      INFO("the neighbours of " << point_name(Site_point::endpoint(e)));
      CHECK(aeg_neighbours(run.tree(), pred, b.time, e) == scan.neighbours[e]);
    }
  }
  INFO(name);
  CHECK(run.validation_failures().empty());
}

}  // namespace

// The paper's claim and its converse (proofs/segment-certificates.md), with
// exact failure times instead of samples: the run on the paper's set has a
// batch exactly where the run keeping every sign changes the tree, the same
// tree after it (made by its own local update), and no other batch. The
// bundled scenes, and generated ones of the three families (the degenerate
// one: shared x-coordinates, concurrent crossings, collinear overlaps,
// resolved by the perturbation).
TEST_CASE("the paper's certificates fail exactly where the tree changes", "[segments][aeg]") {
  Compared c;
  for (const auto& [name, s] : kvd::test::certificate_scenes()) side_by_side(name, s, true, c);
  CHECK(c.batches > 150);
  // Every batch of the kept run changes the tree on these scenes.
  CHECK(c.kept_batches == c.batches);
  for (const std::size_t k : c.caught) CHECK(k > 0);
  // The update replays subtrees, not the tree, or turns a flip in place.
  CHECK(c.replays + c.flipped >= c.batches);
  CHECK(c.flipped > 0);
  // Some batches are walls crossing, remade at the frontier of the later wall's segment.
  CHECK(c.frontier > 0);
}

// The same on the 49 valid scenes of seven segments on small integers (seeds
// 1 to 50), half or all moving (test_kinetic_segments' random scenes), up to
// t = 1: ties and
// simultaneous events at rational instants everywhere.
TEST_CASE("the paper's certificates on small integer scenes", "[segments][aeg]") {
  Compared c;
  for (std::uint64_t seed = 1; seed <= 50; ++seed)
    if (const auto s = kvd::test::small_integer_scene(seed))
      side_by_side("seed " + std::to_string(seed), *s, false, c, Exact_time(1));
  CHECK(c.batches > 100);
  CHECK(c.frontier > 0);
  CHECK(c.apart > 0);
}

// The same over whole spans (to t = 2) on the next thousand seeds: an
// independent sweep over seeds 1 to 12,000 found three guards of the reroute
// missing (seeds 207, 967, 1591, 3649 and 4828 among them, each ending a
// batch in another tree), so many more scenes run here than above. In
// seeds 3929, 7469 and 11662 a crossing goes below a frontier node that the
// kept run remakes: its intersection arrivals, kept for below the
// frontier, reached a cell its segment does not reach (Subtree_fit, in_cell).
// In seed 9511 a key of the rerouted segment's steps at the root is a tie
// for good whose perturbation's leading coefficient vanishes at t = 1,
// while its key against the side of the cell it reaches, a tie for good
// too, is decided by a coefficient that does not vanish then: the guard
// over its own steps asks every node above there
// (proofs/segment-local-update.md, case 1).
TEST_CASE("the paper's certificates on small integer scenes over whole spans", "[segments][aeg][slow]") {
  Compared c;
  for (const std::uint64_t seed : {207, 967, 1591, 3649, 4828, 3929, 7469, 11662, 9511})
    if (const auto s = kvd::test::small_integer_scene(seed)) side_by_side("seed " + std::to_string(seed), *s, false, c);
  for (std::uint64_t seed = 51; seed <= 1050; ++seed)
    if (const auto s = kvd::test::small_integer_scene(seed)) side_by_side("seed " + std::to_string(seed), *s, false, c);
  CHECK(c.batches > 5000);
  CHECK(c.frontier > 0);
}

// Events of two segments at one instant, one inside the other's region, on
// the paper's set (proofs/segment-local-update.md, "Rerouting on the
// paper's set"). In seed 9277 of the small-integer scenes at t = 1/3 (order
// s0 s3 s2 s4 s5 s1 s6), s5.1 reaches its crossing with s4 (s5's steps
// decide it, at s4's edge cut) while the crossing of s5 and s6 passes
// s0.0's wall (s6's steps, at the root). Both segments' steps are decided
// again down to s5's frontier, whose nodes are replayed whole: every replay
// of the batch is a frontier node's (before, the subtrees the certificates
// name were replayed), and the tree and its log are a fresh construction's.
// The first attempt replayed only the frontier nodes above the tops and the
// certificates, and missed one: s6's part beside s0.0's wall changes its
// side of s5 at s5's edge cut, below the shared frontier.
TEST_CASE("two segments' events at one instant, one inside the other's region, are rerouted together",
          "[segments][aeg]") {
  small_integer_batch(9277, mpq_class(33, 100), mpq_class(1, 3), [](const Segment_scene&, const auto& b) {
    CHECK(b.changed);
    CHECK(b.replays > 0);
    CHECK(b.frontier_replays == b.replays);
  });
}

// Small-integer seed 1138 at t = 2: walls cross in three places at once
// (s3.0 and s1.0, s3.1 and s6.1, s5.0 and s2.0), and a failing certificate's
// changed signs are decided by two segments' steps. It starts both
// segments' reroutes (proofs/segment-local-update.md, "Rerouting on the
// paper's set"); the batch used to replay a whole subtree (116 nodes made,
// against 106 now).
TEST_CASE("a certificate whose changed signs are two segments' starts both reroutes", "[segments][aeg]") {
  small_integer_batch(
      1138, mpq_class(199, 100), mpq_class(2),
      [](const Segment_scene&, const auto& b) {
        CHECK(b.failing.size() == 7);
        CHECK(b.replays > 0);
        CHECK(b.frontier_replays == b.replays);
      },
      false);
}

// Small-integer seed 203 at t = 3/2: two transient cells collapse at once,
// between s3.0 and s2.1 below s4, and between s4.1 and s5.1 below s6. The
// subtree they name is that of s5.1's vertex cut, the second cut of s5
// (rank 0) on its path. It used to be replayed whole (138 nodes made); it is
// now made again from s5's first cut, the root, with only s5's cuts decided
// again, and the old subtrees beside keep their nodes (60 made).
TEST_CASE("a named subtree below its segment's first cut is made again from that cut", "[segments][aeg]") {
  small_integer_batch(203, mpq_class(149, 100), mpq_class(3, 2), [](const Segment_scene& s, const auto& b) {
    REQUIRE(s.rank[5] == 0);
    CHECK(b.failing.size() == 2);
    CHECK(b.replays == 1);
    CHECK(b.frontier_replays == 0);
    CHECK(b.nodes_rebuilt == 60);
  });
}

// Small-integer seed 10 at t = 1/2 (order s5 s4 s6 s0 s3 s2 s1): three
// certificates fail at once, the transient cells between s0.1 and s2.0 and
// between s4.0 and s0.0, and s1.0's. The guards refuse the batch as a
// whole. The cell between s4.0 and s0.0 passes them alone: it is rerouted
// (two frontier nodes made again); the other two name one subtree, apart
// from those, which is made again (proofs/segment-local-update.md,
// "Certificates apart"). Before, the batch was replayed as a whole:
// 78 nodes made, 56 now.
TEST_CASE("a batch refused whole reroutes the certificates that pass alone, the others' subtrees made again",
          "[segments][aeg]") {
  small_integer_batch(10, mpq_class(49, 100), mpq_class(1, 2), [](const Segment_scene&, const auto& b) {
    CHECK(b.failing.size() == 3);
    CHECK(b.replays == 3);
    CHECK(b.frontier_replays == 2);
    CHECK(b.nodes_rebuilt == 56);
  });
}

// A vertex event (seed 003, Figure 2, a case of disjoint segments) updated
// by the frontier replay. s2.1 moves right through s1.0's wall at t = 1,
// under s1 and above s0; the later s3 crosses every cell between them. Only
// the transient cell between the two walls fails (s2.1's neighbours change
// too, which that cell's collapse says). The x order of s2.1 and s1.0 is
// decided only by s2's steps, at s1.0's cut: they are decided again from
// there, and exactly the two leaves of B_1 whose arrivals of s2 changed are
// made again, the one s2.1 leaves (left of s1.0) and the one it enters
// (below s1), with s3's cuts. Both trees derived by hand.
TEST_CASE("walls crossing: a vertex event remakes the two leaves of B_{i-1} it moves between", "[segments][aeg]") {
  const auto s = scene_of({fixed(0, 0, 20, 0), fixed(8, 5, 10, 5), moving(linear(3, 0), linear(2, 0), linear(7, 1), linear(2, 0)),
                           fixed(1, 1, 15, 1)},
                          {0, 1, 2, 3}, 0, 2);
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, s, true);
  const Segment_predicates<Exact_kernel> pred(kernel, s);
  CHECK(run.tree().text() == "(V s0.0 . (V s0.1 (E s0 . (V s1.0 (V s2.0 (V s3.0 . (E s3 . .)) (V s2.1 (E s2 (E s3 . .) .) "
                             "(E s3 . .))) (V s1.1 (E s1 (E s3 . .) .) (V s3.1 (E s3 . .) .)))) .))");
  REQUIRE(run.next_event_time());
  const auto b = run.advance();
  CHECK(b.time.to_string() == "1");
  CHECK(b.failing == std::vector<Aeg_certificate_id>{transient(Site_point::endpoint(5), Site_point::endpoint(2), 0, {})});
  CHECK(b.replays == 2);
  CHECK(b.frontier_replays == 2);
  // The guard over other segments' steps at s1.0's cut, the one node
  // deciding the changed key, searches down s1.0's abscissa (x = 8): the x
  // orders with s1.0 of its cell's walls, s0.0 and s0.1, and of the point
  // cuts below whose cells hold x = 8 now, s1.1 (x = 10: only its left
  // side is searched), s2.0 (x = 3: its right side) and s2.1 (the changed
  // key: both sides). Only s1.1's was not asked before in the batch; s3's
  // cuts (x = 1 and 15) lie in cells it does not search. Reading the log
  // decided three: s1.1's, s3.0's and s3.1's.
  CHECK(b.phases.other_guard == 1);
  // Both leaves keep an old edge cut of s3 with a wall renamed (Lemma 5′),
  // 10 nodes made where making them again made 16. Left of s1.0, s3's cut
  // below s2 lay between s2.0 and the wall s2.1, and lies between s2.0 and
  // s1.0 now, both at x = 8. That check decided three signs: s2.1's x
  // order with the other wall s2.0, and the floor against the roof of the
  // two leaves along the wall at x = 8 (s0 and s3, s3 and s2); the x
  // orders of s2.1 and s1.0 and of s1.0 and s2.0 were decided before in
  // the batch. Below s1, s3's cut lay between s1.0 and s1.1, and lies
  // right of s2.1 now: the cells are fitted taking old subtrees whole
  // first, so this one goes there renamed rather than to the cell left of
  // s2.1, which has the same cut on top and is made again. That check
  // decided two more: s2.1's x order with s1.1, and s0 against s3 at s1.0
  // (s3 against s1 there was decided before, s1.0 lying on s1).
  CHECK(b.phases.walls == 5);
  CHECK(b.nodes_rebuilt == 10);
  CHECK(run.tree().text() == "(V s0.0 . (V s0.1 (E s0 . (V s1.0 (V s2.0 (V s3.0 . (E s3 . .)) (E s2 (E s3 . .) .)) "
                             "(V s1.1 (E s1 (V s2.1 (E s2 (E s3 . .) .) (E s3 . .)) .) (V s3.1 (E s3 . .) .)))) .))");
  CHECK(same_log(run, pred, b.time));
  for (std::size_t e = 0; e < 8; ++e) CHECK(run.leaf_beside(e) == aeg_leaf(run.edited_tree(), pred, b.time, e));
  CHECK_FALSE(run.next_event_time());
  CHECK(run.validation_failures().empty());
}

// Two cells failing for one wall crossing: s0.1 moves right through the
// abscissa of the crossing of the later s1 and s2 at t = 4. s0.1's cut,
// made before s1, runs across s1, so the crossing's two cuts, above and
// below s1, each bound a cell whose other wall is s0.1's, and both
// collapse; the sign that changed is still one, decided by s2's steps at
// s0.1's cut, and the batch is remade at the frontier too.
TEST_CASE("walls crossing: the two cells above and below a segment remake at the frontier", "[segments][aeg]") {
  const auto s = scene_of({moving(linear(0, 0), linear(10, 0), linear(7, 1), linear(10, 0)), fixed(6, 0, 12, 0),
                           fixed(5, -30, 13, 10)},
                          {0, 1, 2}, 0, 9);
  const auto scene = [&] {
    auto t = s;
    t.end = mpq_class(9, 2);
    return t;
  }();
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, scene, true);
  const Segment_predicates<Exact_kernel> pred(kernel, scene);
  REQUIRE(run.next_event_time());
  const auto b = run.advance();
  const Site_point s01 = Site_point::endpoint(1), y = Site_point::crossing(1, 2);
  CHECK(b.time.to_string() == "4");
  CHECK(b.failing == std::vector<Aeg_certificate_id>{transient(s01, y, {}, 1), transient(s01, y, 1, {})});
  CHECK(b.replays > 0);
  CHECK(b.frontier_replays == b.replays);
  CHECK(run.tree().text() == build_cylindrical_bsp(pred, Exact_time(mpq_class(17, 4))).text());
  CHECK(same_log(run, pred, b.time));
  CHECK_FALSE(run.next_event_time());
  CHECK(run.validation_failures().empty());
}

// An endpoint's neighbour ends before it: s2.0 moves right under s1.1 at
// t = 1, so s1.1 loses s2 as its segment below and s2.0 loses s1 as its
// segment above, and the cell between s2.0's wall and s1.1's collapses.
// The three certificates changed one sign, the x order of s2.0 and s1.1,
// which only s2's steps decide: the batch is remade at the frontier, the
// two endpoints' certificates made again from their new leaves.
TEST_CASE("walls crossing: an endpoint whose neighbour ends before it remakes at the frontier", "[segments][aeg]") {
  const auto s = scene_of({fixed(0, 0, 20, 0), fixed(5, 5, 10, 5), moving(linear(9, 1), linear(2, 0), linear(20, 0), linear(2, 0))},
                          {0, 1, 2}, 0, 2);
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, s, true);
  const Segment_predicates<Exact_kernel> pred(kernel, s);
  REQUIRE(run.next_event_time());
  const auto b = run.advance();
  CHECK(b.time.to_string() == "1");
  CHECK(b.failing ==
        std::vector<Aeg_certificate_id>{transient(Site_point::endpoint(4), Site_point::endpoint(3), 0, 1), endpoint(3),
                                        endpoint(4)});
  CHECK(b.replays > 0);
  CHECK(b.frontier_replays == b.replays);
  ends_as_fresh(run, pred, b, mpq_class(3, 2));
}

// The scene of the first test, validated: at t = 1 s1 passes over s0.1 (an
// edge event: the side of s0.1 to s1 changes), at t = 2 s1.0 passes down
// through s0 (an intersection event: the side of s1.0 to s0 and the x order
// of s1.0 and the crossing s0xs1 change). Every changed key names s1, the
// later segment, whose steps alone decide it (at s0.1's cut, at s0's edge
// cut): both batches reroute s1 and remake only leaves of B_0, to the trees
// derived by hand and a fresh construction's log.
TEST_CASE("rerouting: an edge and an intersection event remake at the frontier", "[segments][aeg]") {
  const auto s = scene_of({fixed(0, 0, 4, 0), moving(linear(2, 0), linear(2, -1), linear(6, 0), linear(0, -1))},
                          {0, 1}, 0, 3);
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, s, true);
  const Segment_predicates<Exact_kernel> pred(kernel, s);
  const std::vector<std::string> trees{
      "(V s0.0 . (V s0.1 (E s0 (I s0xs1 . (E s1 . .)) (V s1.0 . (I s0xs1 (E s1 . .) .))) (V s1.1 (E s1 . .) .)))",
      "(V s0.0 . (V s0.1 (E s0 (V s1.0 . (E s1 . .)) .) (V s1.1 (E s1 . .) .)))"};
  for (const std::string& tree : trees) {
    REQUIRE(run.next_event_time());
    const auto b = run.advance();
    INFO("t = " << b.time.to_string());
    CHECK(b.replays > 0);
    CHECK(b.frontier_replays == b.replays);
    CHECK(run.tree().text() == tree);
    CHECK(same_log(run, pred, b.time));
    for (std::size_t e = 0; e < 4; ++e) CHECK(run.leaf_beside(e) == aeg_leaf(run.edited_tree(), pred, b.time, e));
  }
  CHECK_FALSE(run.next_event_time());
  CHECK(run.validation_failures().empty());
}

// Two vertex events at one instant, apart: the scene of "a vertex event
// remakes the two leaves" twice, the copy 100 to the right (s4 to s7), so
// that s2.1 passes s1.0's wall and s6.1 passes s5.0's at t = 1. The changed
// keys are two segments' (s2's, s6's), decided at cuts neither of which lies
// below the other: each segment is rerouted, and the four leaves of B_{i-1}
// they move between are remade, to a fresh construction's tree and log.
TEST_CASE("rerouting: two events at one instant in disjoint subtrees remake at the frontier", "[segments][aeg]") {
  const auto copy = [](long dx) {
    return std::vector{fixed(0 + dx, 0, 20 + dx, 0), fixed(8 + dx, 5, 10 + dx, 5),
                       moving(linear(3 + dx, 0), linear(2, 0), linear(7 + dx, 1), linear(2, 0)), fixed(1 + dx, 1, 15 + dx, 1)};
  };
  auto segments = copy(0);
  for (auto& g : copy(100)) segments.push_back(g);
  const auto s = scene_of(segments, {0, 1, 2, 3, 4, 5, 6, 7}, 0, 2);
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, s, true);
  const Segment_predicates<Exact_kernel> pred(kernel, s);
  REQUIRE(run.next_event_time());
  const auto b = run.advance();
  CHECK(b.time.to_string() == "1");
  CHECK(b.failing.size() == 2);
  CHECK(b.replays == 4);
  CHECK(b.frontier_replays == 4);
  ends_as_fresh(run, pred, b, mpq_class(3, 2));
}

// Two events at one instant, one inside the other's subtree: the scene of
// "a vertex event remakes the two leaves" with a later s4 above s3 whose
// right endpoint passes s3.1's wall at t = 1, as s2.1 passes s1.0's. s3.1's
// cut lies below s1.0's, where s2's steps are decided again, and inside a
// leaf of B_1 that s2's reroute remakes: the two reroutes are not done one
// after the other with their own frontiers (s3's would run through the
// cells s2's remakes), but both down to s2's frontier, the leaves of B_1,
// which are then replayed whole: every replay is a frontier node's, and the
// batch ends in a fresh construction's tree and log (before, the subtrees
// the certificates name were replayed).
TEST_CASE("rerouting: two events at one instant, one below the other, go down to the earlier one's frontier",
          "[segments][aeg]") {
  const auto s = scene_of({fixed(0, 0, 20, 0), fixed(8, 5, 10, 5), moving(linear(3, 0), linear(2, 0), linear(7, 1), linear(2, 0)),
                           fixed(1, 1, 15, 1), moving(linear(12, 0), linear(3, 0), linear(14, 1), linear(3, 0))},
                          {0, 1, 2, 3, 4}, 0, 2);
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, s, true);
  const Segment_predicates<Exact_kernel> pred(kernel, s);
  REQUIRE(run.next_event_time());
  const auto b = run.advance();
  CHECK(b.time.to_string() == "1");
  // The two collapsing cells, and s4.1's endpoint: s3 ends before it.
  CHECK(b.failing == std::vector<Aeg_certificate_id>{transient(Site_point::endpoint(5), Site_point::endpoint(2), 0, {}),
                                                     transient(Site_point::endpoint(9), Site_point::endpoint(7), 3, {}),
                                                     endpoint(9)});
  CHECK(b.replays > 0);
  CHECK(b.frontier_replays == b.replays);
  ends_as_fresh(run, pred, b, mpq_class(3, 2));
}

// The same event with a point beside it: s1.1 has s2.1's abscissa for good
// (the degenerate family's shared x-coordinates), so both pass s0.0's wall
// at t = 1. s2 is inserted before s1, and only the cell between s2.1 and
// s0.0 fails; s1.1's cut lies left of s2.1's (by the perturbation),
// not on that cell's path. Rerouting s2 alone would leave s1.1 where it
// was (mutation: a wrong tree and log): the batch is replayed instead, to
// a fresh build's tree and log.
TEST_CASE("walls crossing with another point at the same abscissa is replayed", "[segments][aeg]") {
  const auto s = scene_of({fixed(8, 5, 10, 5), moving(linear(3, 0), linear(2, 0), linear(7, 1), linear(2, 0)),
                           moving(linear(4, 0), linear(1, 0), linear(7, 1), linear(1, 0))},
                          {0, 2, 1}, 0, 2);
  Aeg_kinetic_bsp<Exact_kernel> run(kernel, s, true);
  const Segment_predicates<Exact_kernel> pred(kernel, s);
  REQUIRE(run.next_event_time());
  const auto b = run.advance();
  CHECK(b.time.to_string() == "1");
  CHECK(b.failing == std::vector<Aeg_certificate_id>{transient(Site_point::endpoint(5), Site_point::endpoint(0), {}, {})});
  CHECK(b.frontier_replays == 0);
  CHECK(run.tree().text() == build_cylindrical_bsp(pred, Exact_time(mpq_class(3, 2))).text());
  CHECK(same_log(run, pred, b.time));
  CHECK_FALSE(run.next_event_time());
  CHECK(run.validation_failures().empty());
}

// Two parallel segments passing through each other's line: s2 comes down
// onto s1's line at t = 1 (s2.0 onto s1, s1.1 onto s2 at once) and goes on
// below, so the two swap their order at every wall across both, among them
// the walls of the first segment, s0, far above. Only the two endpoint
// certificates fail: between s0's walls the cell under s2 is no transient
// node (its parent is s1's edge cut). Replaying what they name on their
// paths (left of s0.0's wall and right of s0.1's) left that cell as it was,
// with s2 above s1 (as on `kvd generate segments-random --n 150 --moving
// 150 --seed 7`, whose generator makes parallel segments). Every sign that
// changes names both segments, so it is decided at a cut of s1 or later:
// the three leaves of B_0 (s0's cuts) that s1 or s2 reaches are made again
// whole, each one's old cells kept where no cut of either segment lies, and
// s0's cuts above them stay. With s2 first, the tree before it is one leaf,
// and the tree is made again from the root. So it is when s2 starts at
// x = 6 and moves right too: at t = 1, s2.0 also reaches s0.0's abscissa,
// a sign of s2's steps above the leaves of B_0 vanishes, and the instant
// is another event's too.
TEST_CASE("parallel segments swapping through each other's line are made again below the earlier one's frontier",
          "[segments][aeg]") {
  const auto run = [](long x0, long vx, std::vector<std::size_t> order) {
    Compared c;
    side_by_side("collinear", scene_of({fixed(7, 10, 9, 10), fixed(0, 0, 10, 0),
                                        moving(linear(x0, vx), linear(1, -1), linear(x0 + 10, vx), linear(1, -1))},
                                       std::move(order), 0, 2),
                 false, c);
    CHECK(c.batches == 1);
    CHECK(c.caught[static_cast<std::size_t>(Aeg_certificate_kind::endpoint)] == 1);
    return c.replays;
  };
  CHECK(run(5, 0, {0, 1, 2}) == 3);
  CHECK(run(5, 0, {2, 0, 1}) == 1);
  CHECK(run(6, 1, {0, 1, 2}) == 1);
}

// Section 3.1.4's flip, done in place. s0 turns through vertical at t = 1
// about (10, 0), under s3 and crossed by the later s1 and s2; s4 lies beside
// it. Alone, the flip is done in place: the same tree and log as the run
// keeping every sign and a fresh build; so are two flips at one instant
// whose leaves of B_{i-1} lie apart, not when one lies below the other. Four flips that meet another event
// at their instant are replayed instead; done in place, each would leave a
// wrong tree:
// - s2's crossing with s1 comes up to s0.0's abscissa at t = 1, on s0, and
//   turns back (x(s1 x s2) - x(s0.0) = -(t - 1)^2): three segments
//   concurrent, and the crossing lies between s0's cuts just after;
// - so does an endpoint of a later segment below s0; no certificate fails
//   for either;
// - far away, the crossing of s7 and s8 passes s5.1's wall: only transient
//   certificates outside the flip's subtrees fail with it;
// - s6 passes over s5.1, as in the first test: only an endpoint certificate
//   fails with it.
TEST_CASE("a lone flip is done in place, and a flip meeting another event is replayed", "[segments][aeg]") {
  const auto s0 = moving(linear(9, 1), linear(-2, 0), linear(11, -1), linear(2, 0));
  const auto s1 = fixed(5, 1, 15, 1), s2 = fixed(5, -1, 15, -1);
  const auto s3 = fixed(0, 5, 20, 5), s4 = fixed(12, -3, 14, 3);
  const auto flips = [&](const std::string& name, std::vector<Segment> segs, std::vector<std::size_t> order) {
    Compared c;
    side_by_side(name, scene_of(std::move(segs), std::move(order), 0, 2), false, c);
    CHECK(c.kept_batches == c.batches);
    // Every scene has its flip batch.
    CHECK(c.caught[static_cast<std::size_t>(Aeg_certificate_kind::flip)] == 1);
    return c.flipped;
  };
  CHECK(flips("lone", {s0, s1, s2, s3, s4}, {3, 0, 1, 2, 4}) == 1);
  // A second segment turning at t = 1 about (50, 0), right of s3.1's wall:
  // the leaves of B_{i-1} of the two flips lie apart, and both are done in
  // place in one batch. With s0 first, s0's leaf is the whole plane, the
  // other's lies below its cut, and the batch is replayed.
  const auto t0 = moving(linear(49, 1), linear(-2, 0), linear(51, -1), linear(2, 0));
  CHECK(flips("two apart", {s0, s1, s2, s3, s4, t0}, {3, 0, 1, 2, 4, 5}) == 1);
  CHECK(flips("two, one below the other", {s0, s1, s2, s3, s4, t0}, {0, 3, 1, 2, 4, 5}) == 0);
  const QPoly x0({mpq_class(7), mpq_class(3), mpq_class(-1)}), x1({mpq_class(9), mpq_class(3), mpq_class(-1)});
  CHECK(flips("tangent", {s0, fixed(5, 0, 15, 0), moving(x0, linear(-3, 0), x1, linear(3, 0)), s3}, {3, 0, 1, 2}) == 0);
  // s5.1 comes up to s0.0's abscissa at t = 1 from the left without
  // crossing it (x(s5.1) - x(s0.0) = -(t - 1)^2), below s0: it lies in the
  // strip between s0's cuts just after, and no certificate fails for it.
  const QPoly q0({mpq_class(6), mpq_class(3), mpq_class(-1)}), q1({mpq_class(8), mpq_class(3), mpq_class(-1)});
  CHECK(flips("touching beside", {s0, s1, s2, s3, s4, moving(q0, linear(-3, 0), q1, linear(-3, 0))}, {3, 0, 1, 2, 4, 5}) == 0);
  const auto s5 = fixed(27, 4, 34, 4);
  CHECK(flips("crossing", {s0, s1, s2, s3, s4, s5, fixed(29, 3, 39, 3), fixed(28, -3, 40, 1),
                           moving(linear(30, 1), linear(-10, 0), linear(35, 1), linear(5, 0))},
              {3, 0, 1, 2, 4, 5, 6, 7, 8}) == 0);
  CHECK(flips("endpoint", {s0, s1, s2, s3, s4, fixed(30, 0, 34, 0), moving(linear(32, 0), linear(2, -1), linear(36, 0), linear(0, -1))},
              {3, 0, 1, 2, 4, 5, 6}) == 0);
}

// A run made afresh at an instant between two batches numbers its nodes
// otherwise than the run that got there by events. From there on both
// decide the same signs, in the same parts of each update, and make the
// same nodes: what an update does to several nodes in turn (the roots it
// makes again, the cells that pick old subtrees, the nodes a flip turned in
// place edits, the nodes a guard asks until a sign vanishes) goes in the
// tree's order, and what it does to endpoints by their number, not by slot
// (sort_in_preorder). Taken by slot, 12 of these batches differed on the
// paper's set, 4 of them in the signs decided.
TEST_CASE("a run made afresh at an instant goes on as the run that got there", "[segments][aeg]") {
  // Both runs have their next batch at the same exact instant.
  const auto next_together = [](auto& run, auto& afresh) {
    const auto t = run.next_event_time(), u = afresh.next_event_time();
    REQUIRE(u);
    REQUIRE(kernel.compare(*t, *u) == 0);
  };
  std::size_t compared = 0;
  for (const auto& [name, s] : kvd::test::generated_and_small(40, 10, 6)) {
    std::vector<Exact_time> times;
    {
      Aeg_kinetic_bsp<Exact_kernel> probe(kernel, s);
      while (probe.next_event_time() && times.size() <= 60) times.push_back(probe.advance().time);
    }
    for (std::size_t i = 3; i + 1 < times.size() && i < 60; i += 7) {
      const mpq_class at = kinetic::rational_between(times[i], times[i + 1]);
      INFO(name << ", made afresh at t = " << at.get_str());
      Segment_scene from = s;
      from.start = at;
      Aeg_kinetic_bsp<Exact_kernel> paper(kernel, s), paper_afresh(kernel, from);
      Kinetic_segment_bsp<Exact_kernel> kept(kernel, s, false), kept_afresh(kernel, from, false);
      paper.advance_to(Exact_time(at));
      kept.advance_to(Exact_time(at));
      for (int k = 0; k < 6 && paper.next_event_time(); ++k) {
        next_together(paper, paper_afresh);
        const auto x = paper.advance(), y = paper_afresh.advance();
        INFO("the paper's set's batch at t = " << x.time.to_string());
        CHECK(x.failing == y.failing);
        CHECK(x.signs == y.signs);
        CHECK(x.phases.named() == y.phases.named());
        CHECK(x.nodes_rebuilt == y.nodes_rebuilt);
        CHECK(x.certificates_made == y.certificates_made);
        CHECK(paper.tree().text() == paper_afresh.tree().text());
        ++compared;
      }
      for (int k = 0; k < 6 && kept.next_event_time(); ++k) {
        next_together(kept, kept_afresh);
        const auto x = kept.advance(), y = kept_afresh.advance();
        INFO("the kept run's batch at t = " << x.time.to_string());
        CHECK(x.failing == y.failing);
        CHECK(x.signs == y.signs);
        CHECK(x.held == y.held);
        CHECK(x.nodes_rebuilt == y.nodes_rebuilt);
      }
    }
  }
  // The paper's set's batches; the kept run's are as many again.
  CHECK(compared > 500);
}
