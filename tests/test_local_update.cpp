// The local update (thesis 7.2-7.3): the tree operations give back the
// canonical tree, a local update gives the tree a build gives, and a
// simulation with --update local is the simulation with --update rebuild,
// batch for batch.
#include <catch2/catch.hpp>
#include <algorithm>
#include <map>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>


#include "kernels.hpp"
#include "kvd/kvd.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/detail/kinetic/local_update.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"
#include "kvd/detail/tree/journal.hpp"
#include "kvd/detail/tree/operations.hpp"
#include "kvd/detail/tree/subtree_hashes.hpp"
#include "kvd/detail/tree/tree_links.hpp"

using namespace kvd;
using SP = symbolic::Symbolic_plane;

namespace {
scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }

// The tree after `moving` is dragged out of `t` and inserted again at time
// `at`, and the nodes it touched.
template <class K>
std::pair<tree::Kvd_tree, std::size_t> moved(const predicates::Classifier<K>& c, tree::Kvd_tree t,
                                             const typename K::Time& at, const std::set<SP>& moving) {
  const auto cost = kinetic::local_update(t, tree::Tree_links(t), tree::Fragment_splitter<K>(c, at), moving);
  return {std::move(t), cost.nodes_touched};
}

// Whether a and b are the same node array, root and free slots, node for
// node.
bool identical(const tree::Kvd_tree& a, const tree::Kvd_tree& b) {
  if (a.nodes.size() != b.nodes.size() || a.root != b.root || a.free_nodes != b.free_nodes) return false;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    const tree::Node &x = a.nodes[i], &y = b.nodes[i];
    if (!(x.cut == y.cut && x.fragment == y.fragment && x.left == y.left && x.right == y.right)) return false;
  }
  return true;
}

// Links and per-subtree hashes of t before an edit, updated from the nodes
// it changed: they must equal those made afresh from t after it.
void keep_up(const tree::Kvd_tree& t, tree::Tree_links& links, tree::Subtree_hashes& hashes,
             const std::vector<int>& changed, const std::vector<SP>& sites) {
  links.update(t, changed);
  hashes.update(t, links, changed);
  const tree::Tree_links fresh(t);
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const int n = static_cast<int>(i);
    REQUIRE(links.live(n) == fresh.live(n));
    if (fresh.live(n)) CHECK(links.parent(n) == fresh.parent(n));
  }
  for (const SP& site : sites) CHECK(links.holding(site) == fresh.holding(site));
  CHECK(hashes.root() == tree::structure_hash(t));
}

// A thesis figure on a hand-built scene: the tree at `from`, and the local
// update of the batch failing at `at` (the certificates in force at `from`
// failing then), confined as a run confines it, which must give the tree a
// build gives just after `at`: a different one, unless `changes` is false.
// With the nodes it changed and touched, and the nodes touched sorted by
// what happened to them: a node made whose cut and fragment no node had
// before, a node whose cut and fragment another slot held before (moved), a
// node that kept its cut and fragment (relinked), a node removed.
struct Touched {
  std::size_t changed = 0, touched = 0, made = 0, moved = 0, relinked = 0, removed = 0;
  friend bool operator==(const Touched&, const Touched&) = default;
  friend std::ostream& operator<<(std::ostream& out, const Touched& t) {
    return out << "changed " << t.changed << ", touched " << t.touched << ": made " << t.made << ", moved " << t.moved
               << ", relinked " << t.relinked << ", removed " << t.removed;
  }
};
struct Figure {
  tree::Kvd_tree before, after;
  Touched nodes{};
  int scope = -1;
  bool widened = false;
};
// `scope`: the subtree to confine the update to, in place of the one the
// failing certificates give (a node's cut: the first node in pre-order cut
// by it).
Figure figure(const scene::Scene& s, const mpq_class& from, const mpq_class& at, bool changes = true,
              std::optional<SP> scope = std::nullopt) {
  const Exact_kernel k;
  const predicates::Classifier<Exact_kernel> c(k, s);
  Figure f{tree::build(c, Exact_time(from)), {}};
  const auto in_force = kinetic::reduced_certificates(c, f.before, Exact_time(from));
  f.after = f.before;
  const tree::Tree_links links(f.after);
  std::set<SP> moving;
  std::vector<const kinetic::Certificate<Exact_kernel::Poly>*> failing;
  for (const auto& cert : in_force)
    for (const auto& q : cert.polys)
      if (auto r = k.next_root(q, Exact_time(from)); r && k.compare(*r, Exact_time(at)) == 0) {
        moving.merge(kinetic::moving_sites(s, links, f.after, cert));
        failing.push_back(&cert);
        break;
      }
  REQUIRE(!moving.empty());
  f.scope = scope ? *links.holding(*scope).begin() : kinetic::update_scope(s, links, f.after, failing);
  const Exact_time now(at);  // the splitter holds a reference to it
  const tree::Fragment_splitter<Exact_kernel> split(c, now);
  // The reference edit on a copy: the same tree.
  tree::Kvd_tree reinserted = f.after;
  kinetic::local_update(reinserted, links, split, moving, f.scope, nullptr, kinetic::Edit::reinsert);
  {  // The journal undoes the walk's edits, node for node.
    tree::Kvd_tree trial = f.after;
    tree::Tree_journal journal(trial);
    kinetic::local_update(trial, links, split, moving, f.scope, &journal, kinetic::Edit::recut);
    journal.undo();
    CHECK(identical(trial, f.before));
  }
  tree::Tree_journal journal(f.after);
  const auto cost = kinetic::local_update(f.after, links, split, moving, f.scope, &journal, kinetic::Edit::recut);
  {  // The links and per-subtree hashes kept from its changed nodes are the tree's.
    tree::Tree_links kept = links;
    tree::Subtree_hashes hashes(f.before);
    keep_up(f.after, kept, hashes, cost.changed, tree::sites_in_priority_order(s));
  }
  const auto live = [](const tree::Kvd_tree& t, int n) {
    return static_cast<std::size_t>(n) < t.nodes.size() && std::ranges::find(t.free_nodes, n) == t.free_nodes.end();
  };
  std::map<tree::Node_content, int> held;  // content -> slot, before
  for (std::size_t n = 0; n < f.before.nodes.size(); ++n)
    if (live(f.before, static_cast<int>(n))) held.emplace(tree::content(f.before.nodes[n]), static_cast<int>(n));
  for (int n : cost.changed) {
    if (!live(f.after, n)) {
      ++f.nodes.removed;
      continue;
    }
    const auto it = held.find(tree::content(f.after.nodes[static_cast<std::size_t>(n)]));
    ++(it == held.end() ? f.nodes.made : it->second == n ? f.nodes.relinked : f.nodes.moved);
  }
  f.nodes.touched = cost.nodes_touched;
  f.nodes.changed = cost.nodes_changed;
  f.widened = cost.widened;
  CHECK(f.widened == scope.has_value());
  CHECK(!tree::first_difference(f.after, tree::build(c, Exact_time(at))));
  CHECK(!tree::first_difference(reinserted, f.after));
  CHECK(tree::first_difference(f.after, f.before).has_value() == changes);
  return f;
}

// The subtree of t below the first node in pre-order cut by `cut`, written
// out as Kvd_tree::describe writes a tree.
std::string below(tree::Kvd_tree t, const SP& cut) {
  std::vector<int> stack{t.root};
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    const tree::Node& nd = t.nodes[static_cast<std::size_t>(n)];
    if (nd.cut == cut) {
      t.root = n;
      return t.describe();
    }
    for (int c : {nd.right, nd.left})
      if (c >= 0) stack.push_back(c);
  }
  return "";
}

// f(s, c, at, t) for random-20, uniform-scale-25 and boxes, each built
// in kernel K just after t = 1: scenes whose local updates merge, split,
// join, release and recycle slots.
template <class K, class F>
void on_built_scenes(F f) {
  for (const char* name : {"random-20.json", "uniform-scale-25.json", "boxes.json"}) {
    CAPTURE(name);
    const scene::Scene s = load(name);
    const K k;
    const predicates::Classifier<K> c(k, s);
    const auto at = k.time(typename K::FT(1));
    f(s, c, at, tree::build(c, at));
  }
}

// A small generated scene: `uniform-density` with n triangles (the same
// bytes on every platform for a seed), `moving` of them moving by
// translations of degree `degree`.
scene::Scene generated(std::size_t n, std::uint64_t seed, int degree = 1, const mpq_class& moving = 1) {
  scene::Uniform_params p;
  p.triangles = n;
  p.seed = seed;
  p.degree = degree;
  p.moving = moving;
  return scene::read_scene(scene::write_scene(scene::uniform_density(p)), "generated");
}

kinetic::Simulation<Exact_time> run(const scene::Scene& s, kinetic::Update u, std::size_t events) {
  kinetic::Options o;
  o.update = u;
  o.max_events = events;
  return kinetic::simulate(Exact_kernel(), s, o);
}

// A batch's failing certificates as traces print them.
using Printed = std::vector<std::pair<kinetic::Certificate_type, std::string>>;
Printed printed(const std::vector<kinetic::Failure>& failing) {
  Printed out;
  for (const auto& f : failing) out.emplace_back(f.type, kinetic::features(f));
  return out;
}
}  // namespace

TEMPLATE_TEST_CASE("dragging a site out and inserting it again gives the same tree", "[local]", KVD_ALL_KERNELS) {
  // Every site of a scene with the sites it bounds, one at a time: drag
  // (priority merging of the subtrees of each of their nodes, with fragment
  // joins) followed by out-of-order insertion from the root must restore the
  // canonical tree.
  const scene::Scene s = load("random-20.json");
  const TestType k;
  const predicates::Classifier<TestType> c(k, s);
  const auto at = k.time(typename TestType::FT(1));
  const tree::Kvd_tree t = tree::build(c, at);
  for (const SP& site : tree::sites_in_priority_order(s)) {
    const auto [after, touched] = moved(c, t, at, kinetic::sites_with(s, site));
    const auto diff = tree::first_difference(after, t);
    INFO(symbolic::to_string(site) << ": " << diff.value_or(""));
    CHECK(!diff);
    CHECK(touched > 0);
  }
  // All at once: the whole tree taken apart and put together again.
  const auto all = tree::sites_in_priority_order(s);
  CHECK(!tree::first_difference(moved(c, t, at, std::set<SP>(all.begin(), all.end())).first, t));
}

TEMPLATE_TEST_CASE("the journal undoes a local update exactly, node for node", "[local]", KVD_ALL_KERNELS) {
  // Each site of a scene with the sites it bounds dragged out and inserted
  // again (merges, splits, joins, recycled slots: the same tree, in other
  // slots), then the journal undone: the same node array, root and free
  // slots as before.
  on_built_scenes<TestType>([](const scene::Scene& s, const auto& c, const auto& at, tree::Kvd_tree t) {
    const tree::Kvd_tree before = t;
    const auto same = [&] { return identical(t, before); };
    std::size_t edited = 0;
    for (const SP& site : tree::sites_in_priority_order(s)) {
      CAPTURE(symbolic::to_string(site));
      tree::Tree_journal journal(t);
      kinetic::local_update(t, tree::Tree_links(t), tree::Fragment_splitter<TestType>(c, at), kinetic::sites_with(s, site),
                            -1, &journal);
      CHECK(!tree::first_difference(t, before));
      edited += !same();
      journal.undo();
      CHECK(same());
    }
    CHECK(edited > 0);  // the updates did move nodes between slots
  });
}

TEMPLATE_TEST_CASE("links and hashes kept from the changed nodes are the tree's after every local update", "[local]",
                   KVD_ALL_KERNELS) {
  // Every site of a scene with the sites it bounds dragged out and inserted
  // again, one after the other (nodes move between slots, slots are
  // released and recycled): the links and the per-subtree hashes updated
  // from each update's changed nodes equal those made afresh from the tree.
  std::size_t released = 0;
  on_built_scenes<TestType>([&](const scene::Scene& s, const auto& c, const auto& at, tree::Kvd_tree t) {
    tree::Tree_links links(t);
    tree::Subtree_hashes hashes(t);
    const auto sites = tree::sites_in_priority_order(s);
    for (const SP& site : sites) {
      CAPTURE(symbolic::to_string(site));
      const auto cost = kinetic::local_update(t, links, tree::Fragment_splitter<TestType>(c, at), kinetic::sites_with(s, site));
      keep_up(t, links, hashes, cost.changed, sites);
      released += t.free_nodes.size();
    }
  });
  CHECK(released > 0);  // slots were released (and the index had to drop them)
}

TEST_CASE("split_tree and merge are inverse on a subtree", "[local]") {
  // Splitting the subtrees below a P-node by that node's own plane leaves
  // them whole; splitting the tree of a cell by a plane of higher priority
  // and merging the halves back gives the tree of the cell.
  const scene::Scene s = load("uniform-scale-25.json");
  const Exact_kernel k;
  const predicates::Classifier<Exact_kernel> c(k, s);
  const Exact_time at(mpq_class(1, 3));
  const tree::Kvd_tree t = tree::build(c, at);
  const tree::Fragment_splitter<Exact_kernel> split(c, at);
  std::size_t tried = 0;
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const tree::Node& n = t.nodes[i];
    if (n.left < 0 || n.right < 0) continue;
    tree::Kvd_tree u = t;
    tree::Kvd_tree whole = t;
    tree::Tree_editor<Exact_kernel> editor(u, split);
    // The two subtrees of n are the halves of n's cell: merged without n's
    // cut, they are n's cell without n's site; inserting n's piece again
    // restores the subtree.
    const int merged = editor.merge(n.left, n.right, n.cut);
    const int back = editor.insert(merged, n.cut, n.fragment);
    const tree::Node& r = u.nodes[static_cast<std::size_t>(back)];
    tree::Kvd_tree sub_u, sub_t;
    sub_u.nodes = u.nodes, sub_u.root = back;
    sub_t.nodes = whole.nodes, sub_t.root = static_cast<int>(i);
    INFO("node " << i << " " << symbolic::to_string(r.cut));
    CHECK(!tree::first_difference(sub_u, sub_t));
    ++tried;
  }
  CHECK(tried > 20);
}

TEST_CASE("VE update of thesis Fig. 7.7: a vertex crossing the E-plane of an ancestor edge", "[local]") {
  // two-triangles: the mover's vertex v4 crosses the E-plane of the static
  // floor's edge e1 at t = 2 (test_simulation derives the times). The local
  // update moves v4's sites (its P-cut, its two edges, the mover) and the
  // crossed edge's sites; the result is written out here and equals a build.
  const Figure f = figure(load("two-triangles.json"), 1, 2);
  // v4 is not a vertex of e1's triangle, so the update is confined to
  // E(1)'s subtree (proofs/local_update.md, section 5). E(1) keeps its
  // place: v4 now lies on its negative side, where the walk makes P(4)'s
  // node and the new pieces of e3, e4 and the mover; on the positive side
  // P(4)'s old subtree, under T(0), is made again without it. The update
  // touches only what the figure changes (so does dragging and inserting
  // again every moving node in E(1)'s subtree, E(1) being one): eight nodes made (the two new
  // pieces of e3, of e4 and of the mover beside P(4), and the joined pieces
  // of e3 with e5 and of the mover under P(5)), P(4)'s node moved, three
  // pieces removed (e4 and the mover's two under P(4)), and three nodes
  // given new children (E(1), P(3), P(5)).
  REQUIRE(f.scope >= 0);
  CHECK(f.before.nodes[static_cast<std::size_t>(f.scope)].cut == SP{SP::Kind::E, 1});
  CHECK(f.nodes == Touched{.changed = 8, .touched = 15, .made = 8, .moved = 1, .relinked = 3, .removed = 3});
  // v4 on the positive side of E(1), below the floor T(0).
  CHECK(f.before.describe() == R"(P(0) [SV(v0)]
  + P(1) [SV(v1)]
    - E(0) [SV(v0) SV(v1) SE(e0)]
      + E(2) [SV(e2,P1) SV(v0) SE(e2)]
        + T(0) [SV(v0) SE(e0), SV(v1) SE(P1,T0), SV(e2,P1) SE(e2)]
    + P(2) [SV(v2)]
      - E(1) [SV(v1) SV(v2) SE(e1)]
        + E(2) [SV(v2) SV(e2,P1) SE(e2)]
          + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]
            - P(3) [SV(v3)]
              + P(4) [SV(v4)]
                - E(3) [SV(v3) SV(v4) SE(e3)]
                  + E(5) [SV(e5,P4) SV(v3) SE(e5)]
                    + T(1) [SV(v3) SE(e3), SV(v4) SE(P4,T1), SV(e5,P4) SE(e5)]
                + P(5) [SV(v5)]
                  - E(4) [SV(v4) SV(v5) SE(e4)]
                    + E(5) [SV(v5) SV(e5,P4) SE(e5)]
                      + T(1) [SV(v4) SE(e4), SV(v5) SE(e5), SV(e5,P4) SE(P4,T1)]
)");
  // v4 has crossed to the negative side of E(1): its P-cut is inserted out
  // of order under E(1)'s left subtree, and its edges e3, e4 are split by
  // E(1) (the SPLIT effect), the pieces beyond E(1) staying under T(0).
  CHECK(f.after.describe() == R"(P(0) [SV(v0)]
  + P(1) [SV(v1)]
    - E(0) [SV(v0) SV(v1) SE(e0)]
      + E(2) [SV(e2,P1) SV(v0) SE(e2)]
        + T(0) [SV(v0) SE(e0), SV(v1) SE(P1,T0), SV(e2,P1) SE(e2)]
    + P(2) [SV(v2)]
      - E(1) [SV(v1) SV(v2) SE(e1)]
        - P(4) [SV(v4)]
          - E(3) [SV(e3,E1) SV(v4) SE(e3)]
            + T(1) [SV(e3,E1) SE(e3), SV(v4) SE(P4,T1), SV(P4,E1,T1) SE(E1,T1)]
          + E(4) [SV(v4) SV(e4,E1) SE(e4)]
            + T(1) [SV(v4) SE(e4), SV(e4,E1) SE(E1,T1), SV(P4,E1,T1) SE(P4,T1)]
        + E(2) [SV(v2) SV(e2,P1) SE(e2)]
          + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]
            - P(3) [SV(v3)]
              + P(5) [SV(v5)]
                - E(3) [SV(v3) SV(e3,E1) SE(e3)]
                  + E(4) [SV(e4,E1) SV(v5) SE(e4)]
                    + E(5) [SV(v5) SV(v3) SE(e5)]
                      + T(1) [SV(v3) SE(e3), SV(e3,E1) SE(E1,T1), SV(e4,E1) SE(e4), SV(v5) SE(e5)]
)");
}

namespace {
// The mover, beside the floor, translates along y; its top vertex v5
// crosses P(2), the plane y = 4 of the floor's vertex v2, at t = 3.
scene::Scene vv_scene() {
  return scene::read_scene(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 10}, "objects": [
    {"vertices": [[-4,-4,0],[4,-4,0],[0,4,0]], "triangles": [[0,1,2]]},
    {"vertices": [[5,0,1],[6,0,1],[5,1,2]], "triangles": [[0,1,2]], "motion": {"translation": [0,[0,1],0]}}]})",
                           "vv.json");
}
}  // namespace

TEST_CASE("a confined update that finds a sign above its subtree changed takes the whole tree", "[local]") {
  // Confined to P(5)'s own subtree, below the P(2) it crosses: P(5)'s piece
  // (its vertex) no longer meets that cell, so the update widens, and still
  // gives the build's tree (checked in figure()).
  const Figure f = figure(vv_scene(), 1, 3, true, SP{SP::Kind::P, 5});
  CHECK(f.widened);
}

TEST_CASE("VV update of thesis Figs. 7.1 and 7.6: a vertex crossing the P-plane of an ancestor vertex", "[local]") {
  const Figure f = figure(vv_scene(), 1, 3);
  // Before: the mover's nodes on P(2)'s negative side, under E(1).
  CHECK(f.before.describe() == R"(P(0) [SV(v0)]
  + P(1) [SV(v1)]
    - E(0) [SV(v0) SV(v1) SE(e0)]
      + E(2) [SV(e2,P1) SV(v0) SE(e2)]
        + T(0) [SV(v0) SE(e0), SV(v1) SE(P1,T0), SV(e2,P1) SE(e2)]
    + P(2) [SV(v2)]
      - E(1) [SV(v1) SV(v2) SE(e1)]
        - P(3) [SV(v3)]
          + P(4) [SV(v4)]
            - E(3) [SV(v3) SV(v4) SE(e3)]
              + E(5) [SV(e5,P4) SV(v3) SE(e5)]
                + T(1) [SV(v3) SE(e3), SV(v4) SE(P4,T1), SV(e5,P4) SE(e5)]
            + P(5) [SV(v5)]
              - E(4) [SV(v4) SV(v5) SE(e4)]
                + E(5) [SV(v5) SV(e5,P4) SE(e5)]
                  + T(1) [SV(v4) SE(e4), SV(v5) SE(e5), SV(e5,P4) SE(P4,T1)]
        + E(2) [SV(v2) SV(e2,P1) SE(e2)]
          + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]
)");
  // The update is confined to P(2)'s subtree (the P-cut crossed), and P(2)
  // stays. It changes six nodes: the three pieces of e4, e5 and the mover
  // under P(5) give way to three pieces on each side of P(2). The walk
  // down from P(2) leaves the mover's pieces under P(4)'s left child as
  // they are (their planes moved, but no piece below them changed sides)
  // and re-cuts only P(5)'s subtree: it touches nine nodes, the six made,
  // P(5)'s node moved to P(2)'s positive side, and the two nodes given a
  // new child (P(2), P(4)). Dragging and inserting again every piece of the
  // moving sites in P(2)'s subtree (`--update reinsert`) touches twelve.
  REQUIRE(f.scope >= 0);
  CHECK(f.before.nodes[static_cast<std::size_t>(f.scope)].cut == SP{SP::Kind::P, 2});
  CHECK(f.nodes == Touched{.changed = 6, .touched = 9, .made = 6, .moved = 1, .relinked = 2, .removed = 0});
  // After: P(5) has moved to P(2)'s positive side (Fig. 7.1(c)); its edges
  // e4 and e5 moved with it and were split by P(2) (Fig. 7.1(d)): their
  // pieces on the negative side stay under P(4), ending at the threads
  // SV(e4,P2) and SV(e5,P2).
  CHECK(f.after.describe() == R"(P(0) [SV(v0)]
  + P(1) [SV(v1)]
    - E(0) [SV(v0) SV(v1) SE(e0)]
      + E(2) [SV(e2,P1) SV(v0) SE(e2)]
        + T(0) [SV(v0) SE(e0), SV(v1) SE(P1,T0), SV(e2,P1) SE(e2)]
    + P(2) [SV(v2)]
      - E(1) [SV(v1) SV(v2) SE(e1)]
        - P(3) [SV(v3)]
          + P(4) [SV(v4)]
            - E(3) [SV(v3) SV(v4) SE(e3)]
              + E(5) [SV(e5,P4) SV(v3) SE(e5)]
                + T(1) [SV(v3) SE(e3), SV(v4) SE(P4,T1), SV(e5,P4) SE(e5)]
            + E(4) [SV(v4) SV(e4,P2) SE(e4)]
              + E(5) [SV(e5,P2) SV(e5,P4) SE(e5)]
                + T(1) [SV(v4) SE(e4), SV(e4,P2) SE(P2,T1), SV(e5,P2) SE(e5), SV(e5,P4) SE(P4,T1)]
        + E(2) [SV(v2) SV(e2,P1) SE(e2)]
          + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]
      + P(5) [SV(v5)]
        - E(4) [SV(e4,P2) SV(v5) SE(e4)]
          + E(5) [SV(v5) SV(e5,P2) SE(e5)]
            + T(1) [SV(e4,P2) SE(e4), SV(v5) SE(e5), SV(e5,P2) SE(P2,T1)]
)");
}

TEST_CASE("E-update of thesis Fig. 7.10: an edge event detected with IV and II certificates", "[local]") {
  // The mover straddles the floor edge e1's E-plane and translates along y;
  // at t = 8 its vertex v3 crosses E(1), and with it the intersection
  // points of its edges e3 and e5 with E(1) cross P-planes and each other.
  const Figure f = figure(scene::read_scene(R"({"format": "kvd-scene/1", "time": {"start": 0, "end": 10}, "objects": [
    {"vertices": [[-4,-4,0],[4,-4,0],[0,4,0]], "triangles": [[0,1,2]]},
    {"vertices": [[1,-2,1],[4,-2,1],[2,-1,2]], "triangles": [[0,1,2]], "motion": {"translation": [0,[0,"1/2"],0]}}]})",
                                                  "iv.json"),
                          4, 8);
  // The IV and II failures confine the update to E(1)'s subtree.
  REQUIRE(f.scope >= 0);
  CHECK(f.before.nodes[static_cast<std::size_t>(f.scope)].cut == SP{SP::Kind::E, 1});
  // Before: v3 is beyond E(1), under the floor's T(0); e3 and e5 are split
  // by E(1) at the intersection points SV(e3,E1) and SV(e5,E1).
  CHECK(f.before.describe() == R"(P(0) [SV(v0)]
  + P(1) [SV(v1)]
    - E(0) [SV(v0) SV(v1) SE(e0)]
      + E(2) [SV(e2,P1) SV(v0) SE(e2)]
        + T(0) [SV(v0) SE(e0), SV(v1) SE(P1,T0), SV(e2,P1) SE(e2)]
    + P(2) [SV(v2)]
      - E(1) [SV(v1) SV(v2) SE(e1)]
        - P(4) [SV(v4)]
          - E(3) [SV(e3,E1) SV(v4) SE(e3)]
            + T(1) [SV(e3,E1) SE(e3), SV(v4) SE(P4,T1), SV(P4,E1,T1) SE(E1,T1)]
          + P(5) [SV(v5)]
            - E(4) [SV(v4) SV(v5) SE(e4)]
              + E(5) [SV(v5) SV(e5,E1) SE(e5)]
                + T(1) [SV(v4) SE(e4), SV(v5) SE(e5), SV(e5,E1) SE(E1,T1), SV(P4,E1,T1) SE(P4,T1)]
        + E(2) [SV(v2) SV(e2,P1) SE(e2)]
          + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]
            - P(3) [SV(v3)]
              + E(3) [SV(v3) SV(e3,E1) SE(e3)]
                + E(5) [SV(e5,E1) SV(v3) SE(e5)]
                  + T(1) [SV(v3) SE(e3), SV(e3,E1) SE(E1,T1), SV(e5,E1) SE(e5)]
)");
  // After: the whole mover is on E(1)'s negative side; the pieces of e3 and
  // e5 on either side are merged into one fragment each (the merging set),
  // and the intersection points are gone.
  CHECK(f.after.describe() == R"(P(0) [SV(v0)]
  + P(1) [SV(v1)]
    - E(0) [SV(v0) SV(v1) SE(e0)]
      + E(2) [SV(e2,P1) SV(v0) SE(e2)]
        + T(0) [SV(v0) SE(e0), SV(v1) SE(P1,T0), SV(e2,P1) SE(e2)]
    + P(2) [SV(v2)]
      - E(1) [SV(v1) SV(v2) SE(e1)]
        - P(3) [SV(v3)]
          + P(4) [SV(v4)]
            - E(3) [SV(v3) SV(v4) SE(e3)]
              + E(5) [SV(e5,P4) SV(v3) SE(e5)]
                + T(1) [SV(v3) SE(e3), SV(v4) SE(P4,T1), SV(e5,P4) SE(e5)]
            + P(5) [SV(v5)]
              - E(4) [SV(v4) SV(v5) SE(e4)]
                + E(5) [SV(v5) SV(e5,P4) SE(e5)]
                  + T(1) [SV(v4) SE(e4), SV(v5) SE(e5), SV(e5,P4) SE(P4,T1)]
        + E(2) [SV(v2) SV(e2,P1) SE(e2)]
          + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]
)");
}

namespace {
// The local and reinsert updates' simulations of s are the rebuild's, batch
// for batch: the same batches at the same exact times with the same failures
// and the same structure hash after each, every interval validated against a
// fresh build. Returns the number of batches that changed the tree.
std::size_t same_simulation(const scene::Scene& s, std::size_t events) {
  const auto rebuild = run(s, kinetic::Update::rebuild, events);
  for (const kinetic::Update update : {kinetic::Update::local, kinetic::Update::reinsert}) {
    const auto local = run(s, update, events);
    INFO((update == kinetic::Update::local ? "local" : "reinsert"));
    CHECK(local.valid());
    INFO(local.failure);
    REQUIRE(local.batches.size() == rebuild.batches.size());
    for (std::size_t i = 0; i < local.batches.size(); ++i) {
      CHECK(Exact_kernel().compare(local.batches[i].time, rebuild.batches[i].time) == 0);
      CHECK(local.batches[i].failing == rebuild.batches[i].failing);
      CHECK(local.batches[i].structure == rebuild.batches[i].structure);
      // Both keep the certificates of the nodes the batch left alone.
      CHECK(local.batches[i].certificates == rebuild.batches[i].certificates);
      CHECK(local.batches[i].certificates_recomputed == rebuild.batches[i].certificates_recomputed);
    }
    CHECK(local.structure_hash == rebuild.structure_hash);
    CHECK(local.collision == rebuild.collision);
  }
  return static_cast<std::size_t>(std::ranges::count_if(rebuild.batches, [](const auto& b) { return b.changed; }));
}
}  // namespace

TEST_CASE("local, reinsert and rebuild updates give the same simulation", "[local][kinetic]") {
  // Random, generated and degenerate scenes (coplanar boxes moving along one
  // axis, lockstep motions, a shared y, a vertical edge, z on a plane).
  for (const char* name : {"random-20.json", "uniform-scale-25.json", "uniform-density-25.json", "boxes.json", "rotor.json",
                           "viewpoint.json", "two-triangles.json", "degenerate-shared-y.json",
                           "degenerate-vertical-edge.json", "degenerate-z-on-plane.json", "cycle3.json"}) {
    INFO(name);
    same_simulation(load(name), 300);
  }
}

TEST_CASE("local, reinsert and rebuild updates agree on the stiff scenes and twenty generated ones", "[local][kinetic][slow]") {
  // The stiff scenes (close, simultaneous and tangential events, high
  // degrees, rational rotations, wide ranges of scale and speed).
  for (const char* name : {"close-events", "high-degree", "near-degenerate", "rational-rotation", "simultaneous",
                           "slow-fast", "tangential", "wide-range", "z-near-plane"}) {
    INFO(name);
    same_simulation(load((std::string("stiff/") + name + ".json").c_str()), 150);
  }
  std::vector<std::pair<std::string, scene::Scene>> scenes;
  // Mixed degrees: translations of degree 1 to 3, all or half moving.
  for (std::uint64_t seed = 1; seed <= 8; ++seed)
    scenes.emplace_back("uniform-density, seed " + std::to_string(seed),
                        generated(10 + seed, seed, 1 + static_cast<int>(seed % 3), seed % 2 ? mpq_class(1) : mpq_class(1, 2)));
  // Rotations (degree 2), and boxes with coplanar faces and shared
  // coordinates, seen from a viewpoint (the default axis-aligned walls stay
  // parallel to the faces, and the tree never changes between collisions).
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    scenes.emplace_back("rotor, seed " + std::to_string(seed), scene::rotor(2 + seed, seed));
    scene::Scene boxes = scene::boxes(3 + seed, mpq_class(1, 2), seed);
    boxes.z = {scene::QPoly(mpq_class(7)), scene::QPoly(mpq_class(-5)), scene::QPoly(mpq_class(60)),
               scene::QPoly(mpq_class(1))};
    scenes.emplace_back("boxes, seed " + std::to_string(seed), scene::read_scene(scene::write_scene(boxes), "generated"));
  }
  // A moving viewpoint: z a Euclidean point above the box, sliding along y,
  // over static and over moving triangles.
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    scene::Scene s = generated(10, seed, 1, seed % 2 ? mpq_class(0) : mpq_class(1));
    s.z = {scene::QPoly(mpq_class(50)), scene::QPoly({mpq_class(50), mpq_class(40 * static_cast<long>(seed))}),
           scene::QPoly(mpq_class(300)), scene::QPoly(mpq_class(1))};
    scenes.emplace_back("moving viewpoint, seed " + std::to_string(seed),
                        scene::read_scene(scene::write_scene(s), "generated"));
  }
  REQUIRE(scenes.size() == 20);
  // Each family must change the tree: a scene whose run does nothing proves
  // nothing.
  std::map<std::string, std::size_t> changed;
  for (const auto& [name, s] : scenes) {
    INFO(name);
    changed[name.substr(0, name.find(','))] += same_simulation(s, 150);
  }
  for (const auto& [family, n] : changed) {
    INFO(family);
    WARN(family << ": " << n << " batches changed the tree");
    CHECK(n >= 10);
  }
}

TEMPLATE_TEST_CASE("a batch's nodes changed are the nodes the trees before and after do not share",
                   "[local]", KVD_ALL_KERNELS) {
  // Counted from the update's journal; here from the whole trees, by text
  // (cut and fragment): the larger of the number of nodes after that no
  // node before matches and the number before that no node after matches.
  // They are among the nodes touched.
  using Texts = std::map<int, std::string>;
  const auto texts = [](const tree::Kvd_tree& t) {
    Texts out;
    const std::set<int> free(t.free_nodes.begin(), t.free_nodes.end());
    for (std::size_t i = 0; i < t.nodes.size(); ++i)
      if (!free.contains(static_cast<int>(i))) out.emplace(static_cast<int>(i), tree::canonical_text(t.nodes[i]));
    return out;
  };
  const auto values = [](const Texts& m) {
    std::set<std::string> out;
    for (const auto& [n, text] : m) out.insert(text);
    return out;
  };
  std::size_t changed = 0, batches = 0;
  for (const char* name : {"random-20.json", "uniform-scale-25.json", "rotor.json"}) {
    CAPTURE(name);
    const scene::Scene s = load(name);
    kinetic::Options o;
    o.max_events = 60;
    o.validate = kinetic::Validation::none;
    const TestType k;
    Kinetic_kvd<TestType> kvd(k, s, o);
    Texts before = texts(kvd.tree());
    while (const auto* batch = kvd.advance()) {
      const Texts after = texts(kvd.tree());
      const auto texts_before = values(before), texts_after = values(after);
      std::size_t made = 0, gone = 0;
      for (const auto& text : texts_after) made += !texts_before.contains(text);
      for (const auto& text : texts_before) gone += !texts_after.contains(text);
      CHECK(batch->nodes_changed == std::max(made, gone));
      CHECK(batch->nodes_changed <= batch->nodes_touched);
      changed += batch->nodes_changed;
      ++batches;
      before = after;
    }
  }
  CHECK(batches > 0);
  CHECK(changed > 0);
}

TEST_CASE("an intersection event without an edge event (thesis Fig. 7.9): II fails, the tree stays", "[local]") {
  // Three triangles. In the cell of v3, e3 ends at its intersection with
  // E(7) and e5 at its intersection with E(8); the two points pass the same
  // height (an II certificate) while neither edge crosses a cut, so only
  // certificates change.
  const scene::Scene s = generated(3, 9);
  const auto sim = run(s, kinetic::Update::local, 8);
  REQUIRE(sim.batches.size() >= 5);
  const auto& b = sim.batches[4];
  CHECK(printed(b.failing) == Printed{{kinetic::Certificate_type::II, "SV(e5,E8) P(SV(e3,E7))"}});
  CHECK(!b.changed);
  REQUIRE(b.time.is_rational());
  CHECK(b.time.rational() == test::q(326398995532, 81551288405));
  const Figure f = figure(s, kinetic::rational_between(sim.batches[3].time, b.time), b.time.rational(), false);
  const std::string cell = R"(P(3) [SV(v3)]
  - E(3) [SV(v3) SV(e3,E7) SE(e3)]
    + E(5) [SV(e5,E8) SV(v3) SE(e5)]
      + T(1) [SV(v3) SE(e3), SV(e3,E7) SE(E7,T1), SV(v8,T1) SE(E8,T1), SV(e5,E8) SE(e5)]
)";
  CHECK(below(f.before, SP{SP::Kind::P, 3}) == cell);
  CHECK(below(f.after, SP{SP::Kind::P, 3}) == cell);
}

TEST_CASE("edge events detected by II certificates (thesis Fig. 7.11): an edge passing an edge node", "[local]") {
  // Five triangles. Edge e11 passes the vertical line where the E-planes of
  // e3 and e12 meet: its intersections with E(3) and E(12) and e12's with
  // E(3) reach one height (four II certificates at once), and the piece of
  // e11 between E(12) and E(3) moves to E(3)'s other side.
  const scene::Scene s = generated(5, 43);
  const auto sim = run(s, kinetic::Update::local, 8);
  REQUIRE(sim.batches.size() >= 5);
  const auto& b = sim.batches[4];
  using T = kinetic::Certificate_type;
  CHECK(printed(b.failing) == Printed{{T::II, "SV(e11,E12) P(SV(e11,E3))"},
                                                   {T::II, "SV(e11,E12) P(SV(e12,E3))"},
                                                   {T::II, "SV(e11,E3) P(SV(e11,E12))"},
                                                   {T::II, "SV(e11,E3) P(SV(e12,E3))"}});
  CHECK(b.changed);
  REQUIRE(b.time.is_rational());
  CHECK(b.time.rational() == test::q(2224886, 11466781));
  const Figure f = figure(s, kinetic::rational_between(sim.batches[3].time, b.time), b.time.rational());
  // The II failures confine the update to E(3)'s subtree.
  REQUIRE(f.scope >= 0);
  CHECK(f.before.nodes[static_cast<std::size_t>(f.scope)].cut == SP{SP::Kind::E, 3});
  // Before: e11's piece from E(12) to E(3) is on E(3)'s negative side, in
  // the cell below e12's piece that ends at E(3).
  CHECK(below(f.before, SP{SP::Kind::E, 3}) == R"(E(3) [SV(v3) SV(v4) SE(e3)]
  - E(5) [SV(e5,P4) SV(v3) SE(e5)]
    - T(1) [SV(v3) SE(e3), SV(v4) SE(P4,T1), SV(e5,P4) SE(e5)]
      + E(12) [SV(e12,P4) SV(e12,E3) SE(e12)]
        - E(11) [SV(e11,E12) SV(e11,E3) SE(e11)]
          - T(3) [SV(v4,T3) SE(P4,T3), SV(P4,E12,T3) SE(E12,T3), SV(e11,E12) SE(e11), SV(e11,E3) SE(E3,T3)]
        + T(4) [SV(e12,P4) SE(e12), SV(e12,E3) SE(E3,T4), SV(v3,T4) SE(E5,T4), SV(P4,E5,T4) SE(P4,T4)]
          - E(11) [SV(e11,P4) SV(e11,E12) SE(e11)]
            - T(3) [SV(P4,E12,T3) SE(P4,T3), SV(e11,P4) SE(e11), SV(e11,E12) SE(E12,T3)]
    + E(14) [SV(e14,P3) SV(e14,P4) SE(e14)]
      + T(4) [SV(v3,T4) SE(P3,T4), SV(e14,P3) SE(e14), SV(e14,P4) SE(P4,T4), SV(P4,E5,T4) SE(E5,T4)]
  + E(12) [SV(e12,E3) SV(e12,P3) SE(e12)]
    - E(9) [SV(e9,P3) SV(e9,P4) SE(e9)]
      - E(11) [SV(e11,E3) SV(e11,P3) SE(e11)]
        - T(3) [SV(e9,P3) SE(e9), SV(e9,P4) SE(P4,T3), SV(v4,T3) SE(E3,T3), SV(e11,E3) SE(e11), SV(e11,P3) SE(P3,T3)]
    + T(4) [SV(e12,E3) SE(e12), SV(e12,P3) SE(P3,T4), SV(v3,T4) SE(E3,T4)]
)");
  // After: the piece of e11 from E(12) to E(3) is on E(3)'s other side,
  // below e12's piece there, ending at E(3) before E(12).
  CHECK(below(f.after, SP{SP::Kind::E, 3}) == R"(E(3) [SV(v3) SV(v4) SE(e3)]
  - E(5) [SV(e5,P4) SV(v3) SE(e5)]
    - T(1) [SV(v3) SE(e3), SV(v4) SE(P4,T1), SV(e5,P4) SE(e5)]
      + E(12) [SV(e12,P4) SV(e12,E3) SE(e12)]
        - T(3) [SV(v4,T3) SE(P4,T3), SV(P4,E12,T3) SE(E12,T3), SV(E3,E12,T3) SE(E3,T3)]
        + T(4) [SV(e12,P4) SE(e12), SV(e12,E3) SE(E3,T4), SV(v3,T4) SE(E5,T4), SV(P4,E5,T4) SE(P4,T4)]
          - E(11) [SV(e11,P4) SV(e11,E3) SE(e11)]
            - T(3) [SV(P4,E12,T3) SE(P4,T3), SV(e11,P4) SE(e11), SV(e11,E3) SE(E3,T3), SV(E3,E12,T3) SE(E12,T3)]
    + E(14) [SV(e14,P3) SV(e14,P4) SE(e14)]
      + T(4) [SV(v3,T4) SE(P3,T4), SV(e14,P3) SE(e14), SV(e14,P4) SE(P4,T4), SV(P4,E5,T4) SE(E5,T4)]
  + E(12) [SV(e12,E3) SV(e12,P3) SE(e12)]
    - E(9) [SV(e9,P3) SV(e9,P4) SE(e9)]
      - E(11) [SV(e11,E12) SV(e11,P3) SE(e11)]
        - T(3) [SV(e9,P3) SE(e9), SV(e9,P4) SE(P4,T3), SV(v4,T3) SE(E3,T3), SV(E3,E12,T3) SE(E12,T3), SV(e11,E12) SE(e11), SV(e11,P3) SE(P3,T3)]
    + T(4) [SV(e12,E3) SE(e12), SV(e12,P3) SE(P3,T4), SV(v3,T4) SE(E3,T4)]
      - E(11) [SV(e11,E3) SV(e11,E12) SE(e11)]
        - T(3) [SV(E3,E12,T3) SE(E3,T3), SV(e11,E3) SE(e11), SV(e11,E12) SE(E12,T3)]
)");
}

TEST_CASE("dragging with merging and splitting effects (thesis Fig. 7.4): a vertex crossing the P-plane of an ancestor",
          "[local]") {
  // Three triangles. v5 crosses P(1) and its P-node moves from P(1)'s
  // negative subtree (below E(1)) to the positive one (below P(4)). On the
  // old side its node goes, the piece of e4 ending at v5 goes (a merging
  // effect) and the pieces of T(1) on either side of P(5) become one; e5's
  // piece is split at P(1) (a splitting effect), one part staying. On the
  // new side the two pieces of e4 meeting at P(1) become one fragment from
  // v4 to v5 (same-priority nodes joined, like e3 in the figure).
  const scene::Scene s = generated(3, 1);
  const auto sim = run(s, kinetic::Update::local, 4);
  REQUIRE(sim.batches.size() >= 2);
  const auto& b = sim.batches[1];
  CHECK(printed(b.failing) == Printed{{kinetic::Certificate_type::VV, "SV(v5) P(1)"}});
  REQUIRE(b.time.is_rational());
  CHECK(b.time.rational() == test::q(6516838, 2848615));
  const Figure f = figure(s, kinetic::rational_between(sim.batches[0].time, b.time), b.time.rational());
  // The update is confined to P(1)'s subtree, and touches only what the
  // figure changes: six nodes made (on the old side e5's piece now ending
  // at P(1) and the joined piece of T(1); on the new side e5's and T(1)'s
  // pieces beside v5, e4 from v4 to v5 and T(1) beyond it), P(5)'s node
  // moved, and four nodes given new children (E(1), whose left child is
  // E(3) once P(5) and e4's piece are gone; P(4), over P(5) now; and the
  // pieces of e3 on both sides).
  REQUIRE(f.scope >= 0);
  CHECK(f.before.nodes[static_cast<std::size_t>(f.scope)].cut == SP{SP::Kind::P, 1});
  CHECK(f.nodes == Touched{.changed = 6, .touched = 11, .made = 6, .moved = 1, .relinked = 4, .removed = 0});
  CHECK(below(f.before, SP{SP::Kind::E, 1}) == R"(E(1) [SV(v1) SV(v2) SE(e1)]
  - P(5) [SV(v5)]
    - E(3) [SV(e3,P2) SV(e3,E1) SE(e3)]
      + E(5) [SV(v5) SV(e5,P2) SE(e5)]
        + T(1) [SV(e3,P2) SE(e3), SV(e3,E1) SE(E1,T1), SV(P5,E1,T1) SE(P5,T1), SV(v5) SE(e5), SV(e5,P2) SE(P2,T1)]
    + E(4) [SV(e4,P1) SV(v5) SE(e4)]
      + T(1) [SV(P5,E1,T1) SE(E1,T1), SV(v1,T1) SE(P1,T1), SV(e4,P1) SE(e4), SV(v5) SE(P5,T1)]
  + E(2) [SV(v2) SV(e2,P1) SE(e2)]
    + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]
      - E(3) [SV(e3,E1) SV(e3,P1) SE(e3)]
        + T(1) [SV(e3,E1) SE(e3), SV(e3,P1) SE(P1,T1), SV(v1,T1) SE(E1,T1)]
)");
  CHECK(below(f.after, SP{SP::Kind::E, 1}) == R"(E(1) [SV(v1) SV(v2) SE(e1)]
  - E(3) [SV(e3,P2) SV(e3,E1) SE(e3)]
    + E(5) [SV(e5,P1) SV(e5,P2) SE(e5)]
      + T(1) [SV(e3,P2) SE(e3), SV(e3,E1) SE(E1,T1), SV(v1,T1) SE(P1,T1), SV(e5,P1) SE(e5), SV(e5,P2) SE(P2,T1)]
  + E(2) [SV(v2) SV(e2,P1) SE(e2)]
    + T(0) [SV(v1) SE(e1), SV(v2) SE(e2), SV(e2,P1) SE(P1,T0)]
      - E(3) [SV(e3,E1) SV(e3,P1) SE(e3)]
        + T(1) [SV(e3,E1) SE(e3), SV(e3,P1) SE(P1,T1), SV(v1,T1) SE(E1,T1)]
)");
  CHECK(below(f.before, SP{SP::Kind::P, 4}) == R"(P(4) [SV(v4)]
  - E(3) [SV(e3,E0) SV(v4) SE(e3)]
    + E(4) [SV(v4) SV(e4,P1) SE(e4)]
      + T(1) [SV(e3,E0) SE(e3), SV(v4) SE(e4), SV(e4,P1) SE(P1,T1), SV(v1,T1) SE(E0,T1)]
)");
  CHECK(below(f.after, SP{SP::Kind::P, 4}) == R"(P(4) [SV(v4)]
  - P(5) [SV(v5)]
    - E(5) [SV(v5) SV(e5,P1) SE(e5)]
      + T(1) [SV(v5) SE(e5), SV(e5,P1) SE(P1,T1), SV(v1,T1) SE(E0,T1), SV(P5,E0,T1) SE(P5,T1)]
    + E(3) [SV(e3,E0) SV(v4) SE(e3)]
      + E(4) [SV(v4) SV(v5) SE(e4)]
        + T(1) [SV(e3,E0) SE(e3), SV(v4) SE(e4), SV(v5) SE(P5,T1), SV(P5,E0,T1) SE(E0,T1)]
)");
}
