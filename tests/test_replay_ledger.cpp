// What a local update of the segment BSP replaced, told without reading the
// old subtrees it kept whole (kvd/detail/segments/replay_ledger.hpp): every
// batch says it changed the tree exactly when the tree's text before and
// after differ, in both kinetic runs and on every kernel; and with
// validation on, the runs' own audits (the ledger against each root's
// subtree read before and after, the paper's run's transient certificates
// and point flags against those made afresh) find nothing, and the
// validations pass.
#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "kernels.hpp"
#include "segment_scenes.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/segment_generators.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"
#include "kvd/detail/segments/subtree_fit.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"

using namespace kvd;
using namespace kvd::segments;

namespace {

// The small-integer scenes of seeds 1 to 150 (simultaneous events and
// shared coordinates are common) and the generated ones of every family.
std::vector<std::pair<std::string, Segment_scene>> scenes() {
  std::vector<std::pair<std::string, Segment_scene>> out;
  for (std::uint64_t seed = 1; seed <= 150; ++seed)
    if (auto s = test::small_integer_scene(seed)) out.emplace_back("small " + std::to_string(seed), *s);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    out.emplace_back("random " + std::to_string(seed), test::generated(Segment_family::random, 40, seed, 2));
    out.emplace_back("rotating " + std::to_string(seed), test::generated(Segment_family::rotating, 12, seed, 2));
    out.emplace_back("degenerate " + std::to_string(seed), test::generated(Segment_family::degenerate, 24, seed, 2));
  }
  return out;
}

}  // namespace

namespace {

// Runs to the end, requiring of every batch that it says it changed the tree
// exactly when the tree's text changed; the batches that did. A batch with
// a floating-point repair (which builds the whole tree again) is skipped.
template <class K, class Run>
std::size_t changes_told(const K& k, Run& run, const kinetic::Recovery* recovery) {
  std::size_t changed = 0;
  while (run.next_event_time()) {
    const std::string before = run.tree().text();
    const std::size_t rebuilds = recovery ? recovery->rebuilds : 0;
    const auto b = run.advance();
    if (recovery && recovery->rebuilds != rebuilds) continue;
    INFO("t = " << k.to_string(b.time));
    REQUIRE(b.changed == (run.tree().text() != before));
    changed += b.changed;
  }
  return changed;
}

}  // namespace

// (Every batch of these scenes changes the tree: the ledger's other verdict
// is tested on remakes that change nothing, below.)
TEMPLATE_TEST_CASE("the kept run's batches say they changed the tree exactly when its text changed",
                   "[segments][kinetic][ledger]", KVD_ALL_KERNELS) {
  const TestType k;
  std::size_t changed = 0;
  for (const auto& [name, scene] : scenes()) {
    INFO(name);
    Kinetic_segment_bsp<TestType> run(k, scene, false);
    changed += changes_told(k, run, &run.recovery());
  }
  CHECK(changed > 1000);
}

TEST_CASE("the paper's run's batches say they changed the tree exactly when its text changed",
          "[segments][kinetic][ledger]") {
  const Exact_kernel k;
  std::size_t changed = 0;
  for (const auto& [name, scene] : scenes()) {
    INFO(name);
    Aeg_kinetic_bsp<Exact_kernel> run(k, scene, false);
    changed += changes_told(k, run, nullptr);
  }
  CHECK(changed > 1000);
}

TEST_CASE("validated, both runs' audits of what an update replaced find nothing", "[segments][kinetic][ledger]") {
  const Exact_kernel k;
  for (const auto& [name, scene] : scenes()) {
    INFO(name);
    Aeg_kinetic_bsp<Exact_kernel> paper(k, scene, true);
    while (paper.next_event_time()) paper.advance();
    CHECK(paper.validation_failures().empty());
    Kinetic_segment_bsp<Exact_kernel> kept(k, scene, true);
    while (kept.next_event_time()) kept.advance();
    CHECK(kept.validation_failures().empty());
  }
}

TEST_CASE("the ledger says a remake that keeps everything changed nothing, and one that drops a segment what it lost",
          "[segments][ledger]") {
  const Exact_kernel k;
  std::size_t remade = 0, dropped = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    // (Quadratic crossings: the last segment crosses others.)
    const Segment_scene scene = test::generated(Segment_family::random, 30, seed, 2, Crossings::quadratic);
    const Segment_predicates<Exact_kernel> pred(k, scene);
    const Exact_time t(mpq_class(1, 3));
    Cylindrical_bsp tree;
    Build_log log;
    Bsp_builder<Exact_kernel> builder(pred, t, tree, &log);
    builder.start();
    for (const std::size_t s : scene.priority_order) builder.insert(static_cast<std::uint32_t>(s));
    const std::string whole = tree.text();
    std::set<std::size_t> dirty;
    const Subtree_fit_hooks hooks{[](std::size_t) {}, [](std::size_t, std::size_t) {}, {}, {}};
    // Every node that is its segment's first cut on its path, made again at
    // the same instant, keeping its old cells (Subtree_fit::remake): the
    // same subtree, so nothing changed and no crossing went.
    // (A remake moves old contents to other slots: the order is read again.)
    for (std::size_t i = 0; i < tree.preorder().size(); ++i) {
      const std::size_t v = tree.preorder()[i];
      const Bsp_node& n = tree.nodes[v];
      const std::size_t r = cut_rank(n, scene.rank);
      if (n.kind == Cut_kind::leaf || (n.parent >= 0 && cut_rank(tree.nodes[static_cast<std::size_t>(n.parent)], scene.rank) == r))
        continue;
      Subtree_fit<Exact_kernel> fit(tree, log, scene, builder, dirty, hooks);
      fit.ledger().audit(v);
      const std::vector<Arrival> arrivals = log.at[v];
      fit.remake(v, r, arrivals, fit.set_aside(v, r));
      INFO("seed " << seed << ", node " << cut_name(tree.nodes[v]));
      CHECK_FALSE(fit.ledger().changed(v));
      CHECK(fit.ledger().gone({v}, log, scene.rank).empty());
      REQUIRE(tree.text() == whole);
      ++remade;
    }
    // The root's subtree replayed without the last segment's steps: the
    // tree that segment was inserted into, and its crossings gone.
    const std::size_t last = scene.priority_order.back();
    const std::vector<Site_point> before = crossings_below(tree, 0);
    std::vector<Arrival> arrivals = log.at[0];
    std::erase_if(arrivals, [&](const Arrival& a) { return a.segment == last; });
    Subtree_fit<Exact_kernel> fit(tree, log, scene, builder, dirty, hooks);
    fit.ledger().audit(0);
    fit.discard(0, false);
    builder.replay(0, arrivals);
    CHECK(fit.ledger().changed(0) == (tree.text() != whole));
    const std::vector<Site_point> gone = fit.ledger().gone({0}, log, scene.rank);
    for (const Site_point& x : before) CHECK(std::binary_search(gone.begin(), gone.end(), x) == x.on(last));
    dropped += gone.size();
  }
  CHECK(remade > 30);
  CHECK(dropped > 0);
}
