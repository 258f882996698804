// The frontier replay of the kinetic segment BSP (the local update,
// proofs/segment-local-update.md): after every batch it holds the tree and
// the certificates, node for node, that the subtree replay and a fresh
// construction at the batch's time hold, and the construction's logs, on
// generated scenes of every family; and it is the replay that ran for most
// failures, not the fallback.
#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>
#include <string>

#include "segment_scenes.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "kvd/segments/segment_generators.hpp"

using namespace kvd;
using namespace kvd::segments;

namespace {

using Listed = std::vector<std::pair<Segment_certificate_key, std::vector<std::int32_t>>>;

// The entries of one certificate list missing from the other, named (empty
// when the lists are equal).
std::string difference(const Listed& a, const Listed& b) {
  std::ostringstream out;
  const auto missing = [&](const Listed& x, const Listed& y, const char* tag) {
    for (const auto& e : x)
      if (!std::binary_search(y.begin(), y.end(), e)) {
        out << tag << " " << kind_name(e.first.kind) << " " << features(e.first) << " at";
        for (const std::int32_t n : e.second) out << " " << n;
        out << "\n";
      }
  };
  missing(a, b, "only in the first:");
  missing(b, a, "only in the second:");
  return out.str();
}

// The cells of a tree's nodes, in pre-order (tree() numbers nodes so):
// text() does not show them, and a subtree taken whole keeps its own.
std::vector<Cell> cells(const Cylindrical_bsp& t) {
  std::vector<Cell> out;
  for (const Bsp_node& n : t.nodes) out.push_back(n.cell);
  return out;
}

struct Tally {
  std::size_t batches = 0, frontier = 0, subtree = 0, made_local = 0, made_subtree = 0;
};

// Runs the scene with the local and the subtree update side by side, up to
// `limit` batches, comparing them after every batch (and with a fresh
// construction after every `fresh_every`-th).
void side_by_side(const Segment_scene& s, std::size_t limit, std::size_t fresh_every, Tally& tally) {
  const Exact_kernel k;
  Kinetic_segment_bsp<Exact_kernel> local(k, s, false, Segment_update::local),
      subtree(k, s, false, Segment_update::subtree);
  for (std::size_t n = 0; n < limit && local.next_event_time(); ++n) {
    REQUIRE(subtree.next_event_time());
    const auto a = local.advance(), b = subtree.advance();
    INFO("batch " << n << " at t = " << a.time.to_string());
    REQUIRE(k.compare(a.time, b.time) == 0);
    CHECK(a.failing == b.failing);
    CHECK(a.changed == b.changed);
    CHECK(local.tree().text() == subtree.tree().text());
    CHECK(cells(local.tree()) == cells(subtree.tree()));
    const std::string against_subtree = difference(local.certificate_list(), subtree.certificate_list());
    CHECK(against_subtree == "");
    if (n % fresh_every == 0) {
      const Kinetic_segment_bsp<Exact_kernel> fresh(k, s, false, Segment_update::subtree, a.time);
      const std::string against_fresh = difference(local.certificate_list(), fresh.certificate_list());
      CHECK(against_fresh == "");
      // The logs too, which the frontier replay reads above the frontier.
      CHECK(local.arrivals() == fresh.arrivals());
      CHECK(cells(local.tree()) == cells(fresh.tree()));
      CHECK(subtree.arrivals() == fresh.arrivals());
    }
    ++tally.batches;
    tally.frontier += a.frontier_replays;
    tally.subtree += a.subtree_replays;
    tally.made_local += a.nodes_rebuilt;
    tally.made_subtree += b.nodes_rebuilt;
    CHECK(b.frontier_replays == 0);
  }
  CHECK(!subtree.next_event_time() == !local.next_event_time());
}

Segment_scene with_motion(Segment_family family, std::size_t n, std::uint64_t seed, std::optional<std::size_t> moving,
                          std::optional<Segment_motion_kind> motion, Crossings crossings) {
  Segment_generator_options o;
  o.family = family;
  o.n = n;
  o.seed = seed;
  o.moving = moving;
  o.motion = motion;
  o.crossings = crossings;
  return generate_segments(o);
}

// The batch at t of small-integer scene `seed` on the local update (the run
// taken first to `before`, just earlier): its failing keys by name and its
// replays. Checks that the tree, cells, certificates and logs after it are
// a fresh construction's at t.
struct Local_batch {
  std::vector<std::string> failing;
  std::size_t frontier = 0, subtree = 0;
};

Local_batch local_batch_at(std::uint64_t seed, const mpq_class& before, const mpq_class& t) {
  const auto s = kvd::test::small_integer_scene(seed);
  REQUIRE(s);
  const Exact_kernel k;
  Kinetic_segment_bsp<Exact_kernel> local(k, *s, false, Segment_update::local);
  local.advance_to(Exact_time(before));
  REQUIRE(k.compare(*local.next_event_time(), Exact_time(t)) == 0);
  const auto b = local.advance();
  Local_batch out{{}, b.frontier_replays, b.subtree_replays};
  for (const auto& key : b.failing) out.failing.push_back(std::string(kind_name(key.kind)) + " " + features(key));
  const Kinetic_segment_bsp<Exact_kernel> fresh(k, *s, false, Segment_update::subtree, Exact_time(t));
  CHECK(local.tree().text() == fresh.tree().text());
  CHECK(cells(local.tree()) == cells(fresh.tree()));
  CHECK(difference(local.certificate_list(), fresh.certificate_list()) == "");
  CHECK(local.arrivals() == fresh.arrivals());
  return out;
}

}  // namespace

TEST_CASE("the frontier replay makes the subtree replay's trees and certificates", "[segments][kinetic]") {
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    INFO("seed " << seed);
    const auto motion = seed % 2 ? Segment_motion_kind::linear : Segment_motion_kind::quadratic;
    side_by_side(with_motion(Segment_family::random, 60, seed, std::nullopt, motion, Crossings::linear), 60, 10,
                 tally);
    side_by_side(with_motion(Segment_family::random, 30, seed, 15, motion, Crossings::quadratic), 40, 10, tally);
    side_by_side(kvd::test::generated(Segment_family::rotating, 12, seed, 10), 60, 10, tally);
    side_by_side(kvd::test::generated(Segment_family::degenerate, 24, seed, 10), 60, 5, tally);
  }
  INFO("batches " << tally.batches << ", frontier " << tally.frontier << ", subtree " << tally.subtree);
  CHECK(tally.batches > 500);
  // The frontier replay is what ran for most failures, and it made fewer nodes.
  CHECK(tally.frontier > tally.subtree);
  CHECK(tally.made_local * 2 < tally.made_subtree);
}

// Changes of several segments at one instant, one's failing nodes in the
// crown of another's topmost one: all their steps are decided again down to
// the frontier of the earliest of them before any frontier node is replayed
// (proofs/segment-local-update.md, "Several segments at one instant"). In
// seed 188 of the small-integer scenes, at t = 1/2 (order s1 s2 s0 s6 s3 s5
// s4), s3.0 passes s1.1's wall, s5.0 passes s0.1's and s3.1's, and s4.0
// reaches s2's line, all under s1.1's cut: one frontier replay, at s3's
// frontier, where the whole subtree of s1.1's cut was replayed before.
TEST_CASE("changes of several segments under one node are decided again down to the earliest one's frontier",
          "[segments][kinetic]") {
  const Local_batch b = local_batch_at(188, mpq_class(49, 100), mpq_class(1, 2));
  CHECK(b.failing == std::vector<std::string>{"x_order s0.1 s5.0", "x_order s0.1 s3xs5", "x_order s1.1 s3.0",
                                              "x_order s3.1 s5.0", "side s3.1 s5", "side s4.0 s2",
                                              "order_at s0.1 s5 s3"});
  CHECK(b.frontier == 1);
  CHECK(b.subtree == 0);

  // The same, side by side with the subtree replay and a fresh construction
  // after every batch, over whole spans of the first hundred seeds, where
  // such batches are common.
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 100; ++seed)
    if (const auto scene = kvd::test::small_integer_scene(seed)) {
      INFO("seed " << seed);
      side_by_side(*scene, 1000, 1, tally);
    }
  CHECK(tally.batches > 500);
}

// A failing node whose key two segments decide: the x order of its point cut
// with its cell's wall, which every walk cut above by that wall compares
// with the cut. Every segment deciding a failing key there sets the
// frontier, and the cut's own segment puts the node on it (proofs/
// segment-local-update.md, "Several segments at one instant"). In seed 4
// of the small-integer scenes at t = 1/3 (order s0 s3 s1 s5 s2 s4 s6), s4.1
// passes the root's abscissa s0.0 while s2.0, a cut below the root, passes
// its cell's wall s1.1: s2's and s4's parts ending at that wall both decide
// their x order there. The update gave up there and replayed the root's
// subtree, the whole tree; it makes one frontier replay at s2's frontier.
// At 12,800 segments the same gave batches that made 328,470 nodes again.
TEST_CASE("a failing node whose key two segments decide falls to the earlier one's frontier", "[segments][kinetic]") {
  const Local_batch b = local_batch_at(4, mpq_class(33, 100), mpq_class(1, 3));
  CHECK(b.failing == std::vector<std::string>{"x_order s0.0 s4.1", "x_order s1.1 s2.0"});
  CHECK(b.frontier == 1);
  CHECK(b.subtree == 0);
}

// A topmost failing node that is itself on the frontier (a leaf of the tree
// before the segment whose steps changed there) is made again as a frontier
// node is, not replayed whole. In seed 6 of the small-integer scenes at
// t = 3/2 (order s4 s2 s6 s0 s1 s5 s3), s2 turns through vertical while
// s0.0 reaches s3's line: the flip's topmost nodes have another failure
// below them, so they are not a lone flip's (flip_frontiers), and they are
// s2's first cuts on their paths.
TEST_CASE("a topmost failing node on the frontier is made again as a frontier node", "[segments][kinetic]") {
  const Local_batch b = local_batch_at(6, mpq_class(149, 100), mpq_class(3, 2));
  CHECK(b.failing == std::vector<std::string>{"x_order s2.0 s2.1", "x_order s2.0 s2xs4", "x_order s2.1 s2xs4",
                                              "side s0.0 s3"});
  CHECK(b.frontier == 2);
  CHECK(b.subtree == 0);
}

// Several segments deciding the failing keys of one node above the
// frontier, each not the node's own cut's: their steps are all decided
// again from it, down to the frontier of the earliest (proofs/
// segment-local-update.md, "Several segments at one instant"). In seed 45
// of the small-integer scenes at t = 1/2 (order s3 s5 s4 s0 s1 s6 s2), s6.0
// reaches the root's abscissa s3.0 while s6.1 and s2.0 both reach that of
// s5.0, a cut below the root: s6's and s2's steps decide the failing keys
// at s5.0's cut. The update replayed the root's subtree, the whole tree; it
// makes one frontier replay at s6's frontier.
TEST_CASE("a failing node whose keys two later segments decide is rerouted from for both", "[segments][kinetic]") {
  const Local_batch b = local_batch_at(45, mpq_class(49, 100), mpq_class(1, 2));
  CHECK(b.failing == std::vector<std::string>{"x_order s2.0 s5.0", "x_order s3.0 s6.0", "x_order s5.0 s6.1"});
  CHECK(b.frontier == 1);
  CHECK(b.subtree == 0);
}

// The same at the topmost failing node itself, with a crossing that goes at
// that instant between two of the rerouted segments. In seed 220 at t = 2
// (order s0 s1 s6 s2 s3 s5 s4), s1.0, s5.1, s6.0 and the crossing of s5 and
// s6 all reach the root's abscissa s0.0, where s6.0 meets s5's line: s1's,
// s5's and s6's steps decide the root's failing keys, and s5 and s6 no
// longer cross after. Their steps are decided again from the root down to
// s1's frontier. The reroutes locate the crossing as logged, since neither
// segment's cuts lie above that frontier; a cell of a frontier node's remake
// then got its location without s5's crossing walk, and cut it twice ("a
// point is cut twice in one region") until the fit dropped such arrivals as
// the frontier nodes' logs do (drop_unwalked_crossings).
TEST_CASE("several segments at the topmost failing node are rerouted from it", "[segments][kinetic]") {
  const Local_batch b = local_batch_at(220, mpq_class(19, 10), mpq_class(2));
  CHECK(b.failing == std::vector<std::string>{"x_order s0.0 s1.0", "x_order s0.0 s5.1", "x_order s0.0 s6.0",
                                              "x_order s0.0 s5xs6", "x_order s1.0 s5.1", "x_order s1.0 s6.0",
                                              "x_order s1.0 s5xs6", "x_order s1.1 s6.1", "x_order s6.0 s5xs6",
                                              "side s6.0 s5"});
  CHECK(b.frontier == 1);
  CHECK(b.subtree == 0);
}
