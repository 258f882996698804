// Seed 003's augmented BSP (kvd/segments/augmented_bsp.hpp): a whole tree
// derived by hand across a flip, the tree read back from it on every kernel,
// and flips turned in place by the run on the paper's certificates leaving
// it as it was.
#include <catch2/catch.hpp>

#include "kernels.hpp"
#include "segment_scenes.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"
#include "kvd/segments/augmented_bsp.hpp"

using namespace kvd;
using namespace kvd::segments;
using kvd::test::fixed;
using kvd::test::linear;
using kvd::test::moving;
using kvd::test::scene_of;

namespace {

// The tree at t, its augmented form, and the tree read back from that form,
// which must be the tree, cells included.
template <class K>
Augmented_bsp round_trip(const Segment_scene& s, const mpq_class& at) {
  const K k;
  const Segment_predicates<K> pred(k, s);
  const auto t = k.time(from_rational<typename K::FT>(at));
  const Cylindrical_bsp b = build_cylindrical_bsp(pred, t);
  const Augmented_bsp a = augment(b, pred, t);
  const Cylindrical_bsp back = expand(a, pred, t);
  INFO("at t = " << at << ": " << b.text());
  CHECK(back.text() == b.text());
  const Cylindrical_bsp c = b.compacted();
  REQUIRE(back.nodes.size() == c.nodes.size());
  for (std::size_t n = 0; n < c.nodes.size(); ++n) {
    INFO("node " << n);
    CHECK(back.nodes[n].cell == c.nodes[n].cell);
    CHECK(back.nodes[n].parent == c.nodes[n].parent);
  }
  return a;
}

}  // namespace

// Section 3.1.4, Figure 5: s0 runs from (-t, -2) to (t, 2) and turns through
// vertical at t = 0; s1 (y = 1, from x = -3 to 3) comes first in priority,
// s2 (y = 0, from x = -2 to 2) last. s1's two vertex cuts are a ternary
// node. Below s1, s0 puts its vertex cut at s0.0 and its intersection cut at
// s0xs1 (x = t/2): a ternary node whose middle child is s0's edge cut;
// above s1, s0.1 and s0xs1 likewise. s2 ends left and right of s0's strip
// below s1, and crosses s0 at the origin inside it: in the cell above s0
// and in the one below, an intersection cut s0xs2, whose children are the
// side of s0's marked endpoint s0.0 and the other. At t = 1 s0.0 is left of
// the origin: s2 runs above s0 on that side (the cell above s0) and below s0
// on the other. At t = -1 s0.0 is right of the origin, s0 leans the other
// way, and s2 still runs above s0 on s0.0's side: the same augmented tree,
// where the tree B changes (the second cut of each ternary node changes
// sides, and the children of the cuts s0xs2 swap).
TEMPLATE_TEST_CASE("a flip leaves the augmented BSP as it was (seed 003, Figure 5)", "[segments][bsp][augmented]",
                   KVD_ALL_KERNELS) {
  const auto s = scene_of({moving(linear(0, -1), linear(-2, 0), linear(0, 1), linear(2, 0)), fixed(-3, 1, 3, 1),
                           fixed(-2, 0, 2, 0)},
                          {1, 0, 2}, -1, 1);
  const std::string below = "(T s0.0 s0xs1 (V s2.0 . (E s2 . .)) (E s0 (I s0xs2 . (E s2 . .)) (I s0xs2 (E s2 . .) .)) "
                            "(V s2.1 (E s2 . .) .))";
  const std::string expected = "(T s1.0 s1.1 . (E s1 " + below + " (T s0.1 s0xs1 . (E s0 . .) .)) .)";
  const Augmented_bsp before = round_trip<TestType>(s, -1), after = round_trip<TestType>(s, 1);
  CHECK(before.text() == expected);
  CHECK(after.text() == expected);
  const auto c = after.counts();
  CHECK(c.ternary == 3);
  CHECK(c.binary_point_cuts == 4);
  CHECK(c.edge_cuts == 7);
  // B itself changes.
  const TestType k;
  const Segment_predicates<TestType> pred(k, s);
  CHECK(build_cylindrical_bsp(pred, k.time(-1)).text() != build_cylindrical_bsp(pred, k.time(1)).text());
}

// The augmented tree encodes B: read back at the same instant it gives B,
// on the small-integer scenes (every kernel computes them exactly) and, in
// the exact kernel, on the bundled and generated scenes of the certificate
// tests (degenerate ones among them) at several instants.
TEMPLATE_TEST_CASE("the augmented BSP reads back as the tree", "[segments][bsp][augmented]", KVD_ALL_KERNELS) {
  Augmented_counts total;
  for (std::uint64_t seed = 1; seed <= 30; ++seed)
    if (const auto s = kvd::test::small_integer_scene(seed))
      for (const mpq_class& t : {mpq_class(0), mpq_class(1, 2), mpq_class(3, 2)}) {
        INFO("seed " << seed);
        const auto c = round_trip<TestType>(*s, t).counts();
        total.ternary += c.ternary;
        total.binary_point_cuts += c.binary_point_cuts;
      }
  CHECK(total.ternary > 100);
  CHECK(total.binary_point_cuts > 100);
}

TEST_CASE("the augmented BSP reads back as the tree on the certificate scenes", "[segments][bsp][augmented]") {
  for (const auto& [name, s] : kvd::test::certificate_scenes())
    for (const mpq_class& t : {mpq_class(0), mpq_class(1, 3), mpq_class(7, 4)}) {
      INFO(name);
      round_trip<Exact_kernel>(s, t);
    }
}

// The run on the paper's certificates turns lone flips in place, editing B
// (the strips' subtrees and the cells along their walls). Before and after
// each such batch the augmented tree is the same: the paper's "flip events
// do not change B̃ at all", on rotating scenes of short and long segments
// (the long ones cross many others, so the strips hold intersection cuts
// the marked endpoint orients). The run checks it too when it validates.
TEST_CASE("flips turned in place leave the augmented BSP as it was", "[segments][aeg][augmented]") {
  const Exact_kernel k;
  std::size_t flips = 0, oriented = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed)
    for (const auto crossings : {Crossings::linear, Crossings::quadratic}) {
      const Segment_scene s = kvd::test::generated(Segment_family::rotating, 16, seed, 4, crossings);
      Aeg_kinetic_bsp<Exact_kernel> run(k, s, true);
      const Segment_predicates<Exact_kernel> pred(k, s);
      while (run.next_event_time()) {
        const Exact_time was = run.now();
        const Cylindrical_bsp tree = run.tree();
        const Augmented_bsp before = augment(tree, pred, was);
        const auto b = run.advance();
        if (b.flipped_in_place == 0 || b.replays > 0) continue;
        INFO("seed " << seed << ", flips at t = " << b.time.to_string());
        ++flips;
        CHECK(run.tree().text() != tree.text());
        CHECK(augment(run.tree(), pred, b.time).text() == before.text());
        for (const auto& id : b.failing)
          if (id.kind == Aeg_certificate_kind::flip)
            for (const Augmented_node& n : before.nodes)
              if (n.kind == Augmented_kind::intersection && n.segment == id.index) {
                ++oriented;
                break;
              }
      }
      INFO("seed " << seed);
      CHECK(run.validation_failures().empty());
    }
  CHECK(flips > 30);
  CHECK(oriented > 10);
}
