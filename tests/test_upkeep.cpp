// Certificate upkeep after a batch (detail/kinetic/reduced_upkeep.hpp,
// detail/kinetic/in_force.hpp, Event_queue::reshape): which nodes make their
// certificates again, checked against keys written out here independently
// of the upkeep's interned ones; the tree queue after reshapes against a
// queue filled afresh and against the heap; a run keeping certificates
// against a run making them all after every batch.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <optional>
#include <random>
#include <set>

#include "kernels.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/detail/kinetic/event_queue.hpp"
#include "kvd/detail/kinetic/in_force.hpp"
#include "kvd/detail/kinetic/reduced_upkeep.hpp"
#include "kvd/detail/tree/journal.hpp"
#include "kvd/detail/kinetic/local_update.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/generators.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"

using namespace kvd;
using SV = symbolic::Symbolic_vertex;

namespace {
scene::Scene load(const char* name) { return scene::load_scene(std::string(KVD_SOURCE_DIR) + "/data/" + name); }

// What a node's certificates are made from, written out in full: for a
// point node and an edge node with an intersection endpoint (whose
// certificates name walls of the ancestors), every ancestor, root first,
// with its cut and (for an E-node) its fragment's intersection endpoints;
// then the node's cut and fragment (canonical: the local update and a build
// may start a piece at different corners).
using Wall_list = std::vector<std::pair<symbolic::Symbolic_plane, std::vector<SV>>>;
using Explicit_key = std::tuple<Wall_list, symbolic::Symbolic_plane, tree::Fragment>;

struct Node_view {
  int node;
  std::vector<int> ancestors;
  Explicit_key key;
};

std::vector<Node_view> nodes_of(const tree::Kvd_tree& t) {
  std::vector<Node_view> out;
  std::vector<int> ancestors;
  Wall_list walls;
  auto walk = [&](auto& self, int n) -> void {
    const tree::Node& nd = t.nodes[static_cast<std::size_t>(n)];
    std::vector<SV> ends;
    if (const auto* e = std::get_if<tree::Edge_fragment>(&nd.fragment))
      for (const SV& v : {e->a, e->b})
        if (v.kind == SV::Kind::intersection) ends.push_back(v);
    std::ranges::sort(ends);
    const bool walled = std::holds_alternative<SV>(nd.fragment) || !ends.empty();
    out.push_back({n, ancestors, {walled ? walls : Wall_list{}, nd.cut, tree::canonical(nd.fragment)}});
    ancestors.push_back(n);
    walls.emplace_back(nd.cut, ends);
    for (int c : {nd.left, nd.right})
      if (c >= 0) self(self, c);
    ancestors.pop_back();
    walls.pop_back();
  };
  if (t.root >= 0) walk(walk, t.root);
  return out;
}

template <class K>
std::set<kinetic::Certificate_key> keys(const std::vector<typename kinetic::Reduced_upkeep<K>::Held>& held) {
  std::set<kinetic::Certificate_key> out;
  for (const auto& h : held) out.insert(h.certificate->key);
  return out;
}
}  // namespace

TEMPLATE_TEST_CASE("a tree left alone keeps its certificates; a failed one is made again at every node holding it",
                   "[upkeep]", KVD_ALL_KERNELS) {
  const TestType k;
  const scene::Scene s = load("random-20.json");
  const predicates::Classifier<TestType> c(k, s);
  const auto now = k.time(typename TestType::FT(0));
  const tree::Kvd_tree t = tree::build(c, now);
  const std::size_t n = t.statistics().nodes;

  kinetic::Reduced_upkeep<TestType> upkeep;
  typename kinetic::Reduced_upkeep<TestType>::Work first, again, refail;
  const tree::Tree_links links(t);
  const std::vector<int> untouched;  // no node edited: only failed ones are looked at
  const auto made = upkeep.update(c, t, links, nullptr, now, {}, first);
  CHECK(first.nodes == n);
  CHECK(made.gone.empty());
  REQUIRE(made.changed.size() >= 20);
  for (const auto& h : made.changed) CHECK(h.made);
  const std::set<kinetic::Certificate_key> all = keys<TestType>(made.changed);
  std::set<kinetic::Certificate_key> scratch;
  for (const auto& cert : kinetic::reduced_certificates(c, t, now)) scratch.insert(cert.key);
  CHECK(all == scratch);

  const auto kept = upkeep.update(c, t, links, &untouched, now, {}, again);
  CHECK(again.nodes == 0);
  CHECK(again.certificates == 0);
  CHECK(kept.gone.empty());
  CHECK(kept.changed.empty());

  // Every node whose own certificates include the failed one makes them
  // again, and no other node; what they make is what changes in force.
  const kinetic::Certificate_key failed = *std::next(all.begin(), static_cast<std::ptrdiff_t>(all.size() / 2));
  kinetic::Reduced_maker<TestType> maker(c, t, now);
  std::size_t holders = 0, certificates = 0;
  for (const auto& v : nodes_of(t)) {
    const auto certs = maker.of_node(v.node, v.ancestors);
    if (std::ranges::any_of(certs, [&](const auto& cert) { return cert.key == failed; })) {
      ++holders;
      certificates += certs.size();
    }
  }
  const auto after = upkeep.update(c, t, links, &untouched, now, {failed}, refail);
  CHECK(holders >= 1);
  CHECK(refail.nodes == holders);
  CHECK(refail.certificates == certificates);
  CHECK(after.gone.empty());
  const std::set<kinetic::Certificate_key> changed = keys<TestType>(after.changed);
  CHECK(changed.contains(failed));
  CHECK(std::ranges::includes(all, changed));
  CHECK(changed.size() <= refail.certificates);
  for (const auto& h : after.changed) CHECK(h.made);
}

// The claim behind the short keys: a triangle node and an edge node without
// an intersection endpoint make the same certificates whatever their
// ancestors; the others do not.
TEMPLATE_TEST_CASE("only point nodes and edges ending at intersections make certificates from their ancestors",
                   "[upkeep]", KVD_ALL_KERNELS) {
  const TestType k;
  std::size_t unwalled = 0, others = 0, differ = 0;
  for (const char* name : {"random-20.json", "uniform-density-25.json", "rotor.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    const predicates::Classifier<TestType> c(k, s);
    const auto now = k.time(from_rational<typename TestType::FT>(s.start));
    const tree::Kvd_tree t = tree::build(c, now);
    kinetic::Reduced_maker<TestType> maker(c, t, now);
    const auto keys_of = [](const auto& certs) {
      std::set<kinetic::Certificate_key> out;
      for (const auto& cert : certs) out.insert(cert.key);
      return out;
    };
    for (const auto& v : nodes_of(t)) {
      const bool walled = kinetic::names_walls(t.nodes[static_cast<std::size_t>(v.node)]);
      const auto alone = keys_of(maker.of_node(v.node, {})), placed = keys_of(maker.of_node(v.node, v.ancestors));
      if (!walled) {
        ++unwalled;
        CHECK(alone == placed);
      } else {
        ++others;
        differ += alone != placed;
      }
      CHECK((walled == !std::get<0>(v.key).empty() || v.ancestors.empty()));
    }
  }
  WARN(unwalled << " nodes name no wall of an ancestor; of the other " << others << ", " << differ << " make other certificates alone");
  CHECK(unwalled >= 100);
  CHECK(differ >= 100);
}

TEST_CASE("after the tree changes, exactly the nodes with a new key make their certificates", "[upkeep]") {
  const Exact_kernel k;
  for (const char* name : {"random-20.json", "uniform-density-25.json", "boxes.json", "rotor.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    const predicates::Classifier<Exact_kernel> c(k, s);
    kinetic::Reduced_upkeep<Exact_kernel> upkeep;
    typename kinetic::Reduced_upkeep<Exact_kernel>::Work work;
    const Exact_time t0(s.start);
    const tree::Kvd_tree before = tree::build(c, t0);
    upkeep.update(c, before, tree::Tree_links(before), nullptr, t0, {}, work);
    std::set<Explicit_key> keys;
    for (const auto& v : nodes_of(before)) keys.insert(v.key);

    std::size_t changed_trees = 0;
    for (int step = 1; step <= 4; ++step) {
      const Exact_time t1(s.start + mpq_class(step, 2));
      const tree::Kvd_tree after = tree::build(c, t1);
      std::size_t fresh = 0;
      for (const auto& v : nodes_of(after)) fresh += !keys.contains(v.key);
      typename kinetic::Reduced_upkeep<Exact_kernel>::Work w;
      upkeep.update(c, after, tree::Tree_links(after), nullptr, t1, {}, w);
      CHECK(w.nodes == fresh);
      changed_trees += fresh > 0;
      // The next step compares with this tree.
      keys.clear();
      for (const auto& v : nodes_of(after)) keys.insert(v.key);
    }
    CHECK(changed_trees >= 1);
  }
}

// The run's path: the first batches of each scene through the confined
// local update, the upkeep told only the nodes the update changed. A node
// makes its certificates when its key is new, or when the node with its key
// before made a certificate that failed (nodes keyed without their
// ancestors kept under moved ones included).
TEST_CASE("after a local update, exactly the nodes with a new key or a failed certificate make theirs",
          "[upkeep][local]") {
  const Exact_kernel k;
  std::size_t batches = 0;
  for (const char* name : {"random-20.json", "uniform-density-25.json", "uniform-scale-25.json", "rotor.json"}) {
    INFO(name);
    const scene::Scene s = load(name);
    const predicates::Classifier<Exact_kernel> c(k, s);
    Exact_time now(s.start);
    tree::Kvd_tree t = tree::build(c, now);
    tree::Tree_links links(t);
    kinetic::Reduced_upkeep<Exact_kernel> upkeep;
    typename kinetic::Reduced_upkeep<Exact_kernel>::Work work;
    std::map<kinetic::Certificate_key, kinetic::Certificate<Exact_kernel::Poly>> in_force;
    const auto apply = [&](const auto& changes) {
      for (const auto& key : changes.gone) in_force.erase(key);
      for (const auto& held : changes.changed) in_force.insert_or_assign(held.certificate->key, *held.certificate);
    };
    apply(upkeep.update(c, t, links, nullptr, now, {}, work));
    for (int batch = 0; batch < 8; ++batch) {
      // The next failure, and the certificates failing then.
      std::optional<Exact_time> first;
      std::vector<const kinetic::Certificate<Exact_kernel::Poly>*> failing;
      for (const auto& [key, cert] : in_force)
        for (const auto& q : cert.polys) {
          const auto r = k.next_root(q, now);
          if (!r) continue;
          const int cmp = first ? k.compare(*r, *first) : -1;
          if (cmp < 0) first = r, failing.clear();
          if (cmp <= 0) {
            failing.push_back(&cert);
            break;
          }
        }
      if (!first) break;
      std::set<kinetic::Certificate_key> failed;
      for (const auto* cert : failing) failed.insert(cert->key);
      // What each key of the tree before made.
      std::map<Explicit_key, bool> made_failed;
      kinetic::Reduced_maker<Exact_kernel> before_maker(c, t, now);
      for (const auto& v : nodes_of(t))
        made_failed[v.key] = std::ranges::any_of(before_maker.of_node(v.node, v.ancestors),
                                                 [&](const auto& cert) { return failed.contains(cert.key); });
      std::set<symbolic::Symbolic_plane> moving;
      for (const auto* cert : failing) moving.merge(kinetic::moving_sites(s, links, t, *cert));
      const int scope = kinetic::update_scope(s, links, t, failing);
      tree::Tree_journal journal(t);
      kinetic::Update_cost cost;
      try {
        cost = kinetic::local_update(t, links, tree::Fragment_splitter<Exact_kernel>(c, *first), moving, scope,
                                     &journal);
      } catch (const tree::Build_error&) {
        break;  // triangles meet there: a collision, not this test's
      }
      links.update(t, cost.changed);
      now = *first;
      REQUIRE(!tree::first_difference(t, tree::build(c, now)));
      std::size_t expected = 0;
      for (const auto& v : nodes_of(t)) {
        const auto it = made_failed.find(v.key);
        expected += it == made_failed.end() || it->second;
      }
      typename kinetic::Reduced_upkeep<Exact_kernel>::Work w;
      apply(upkeep.update(c, t, links, &cost.changed, now, failed, w));
      CHECK(w.nodes == expected);
      ++batches;
    }
  }
  CHECK(batches >= 20);
}

TEST_CASE("the tree queue after reshapes holds what a queue filled afresh and the heap hold", "[upkeep][queue]") {
  const Exact_kernel k;
  const scene::Scene s = load("uniform-density-25.json");
  const predicates::Classifier<Exact_kernel> c(k, s);
  std::vector<tree::Kvd_tree> trees;
  for (int i = 0; i < 6; ++i) trees.push_back(tree::build(c, Exact_time(mpq_class(i, 3))));
  auto reshaped = kinetic::make_queue(k, kinetic::Queue_kind::tree);
  auto heap = kinetic::make_queue(k, kinetic::Queue_kind::heap);
  std::mt19937_64 rng(7);
  std::map<std::size_t, std::pair<int, mpq_class>> held;  // id -> node, time
  reshaped->reset(trees[0]);
  heap->reset(trees[0]);
  std::size_t checks = 0;
  for (int round = 0; round < 60; ++round) {
    const tree::Kvd_tree& t = trees[static_cast<std::size_t>(round) % trees.size()];
    const tree::Tree_links links(t);
    reshaped->reshape(t, links, nullptr);
    heap->reshape(t, links, nullptr);
    std::vector<int> live;
    for (const auto& v : nodes_of(t)) live.push_back(v.node);
    // Certificates at nodes no longer in the tree move; some others move,
    // change time or go; new ones come. Times collide on purpose.
    for (std::size_t id = 0; id < 80; ++id) {
      const int what = static_cast<int>(rng() % 6);
      const bool stale = held.contains(id) && std::ranges::find(live, held[id].first) == live.end();
      if (what == 0 && held.contains(id) && !stale) {
        held.erase(id);
        reshaped->set(id, -1, std::nullopt);
        heap->set(id, -1, std::nullopt);
      } else if (what <= 2 || stale || !held.contains(id)) {
        const int node = live[rng() % live.size()];
        const mpq_class time(static_cast<long>(rng() % 40), 7);
        held[id] = {node, time};
        reshaped->set(id, node, Exact_time(time));
        heap->set(id, node, Exact_time(time));
      }
    }
    auto fresh = kinetic::make_queue(k, kinetic::Queue_kind::tree);
    fresh->reset(t);
    for (const auto& [id, at] : held) fresh->set(id, at.first, Exact_time(at.second));
    auto sorted = [](std::vector<std::size_t> v) {
      std::ranges::sort(v);
      return v;
    };
    REQUIRE(fresh->first_time());
    CHECK(k.compare(*reshaped->first_time(), *fresh->first_time()) == 0);
    CHECK(k.compare(*heap->first_time(), *fresh->first_time()) == 0);
    CHECK(sorted(reshaped->first()) == sorted(fresh->first()));
    CHECK(sorted(heap->first()) == sorted(fresh->first()));
    ++checks;
  }
  CHECK(checks == 60);
}

TEST_CASE("keeping certificates over batches sees the structural changes of making them all again", "[upkeep][kinetic]") {
  // The kept certificates name the walls that were nearest when their nodes
  // made them; the run must still see every change of the tree, at the same
  // exact times, and recompute far fewer certificates.
  const Exact_kernel k;
  std::vector<scene::Scene> scenes;
  for (const char* name : {"random-20.json", "uniform-density-25.json", "uniform-scale-25.json", "boxes.json",
                           "rotor.json", "viewpoint.json", "collisions.json"})
    scenes.push_back(load(name));
  std::size_t compared = 0, kept_made = 0, all_made = 0;
  for (const auto& s : scenes) {
    INFO(s.name);
    kinetic::Options o;
    o.max_events = 250;
    const auto kept = kinetic::simulate(k, s, o);
    o.upkeep = kinetic::Upkeep::all;
    const auto all = kinetic::simulate(k, s, o);
    CHECK(kept.valid());
    INFO(kept.failure);
    std::vector<std::pair<std::size_t, std::string>> a, b;  // structural changes, and where
    for (std::size_t i = 0; i < kept.batches.size(); ++i)
      if (kept.batches[i].changed) a.emplace_back(i, kept.batches[i].structure);
    for (std::size_t i = 0; i < all.batches.size(); ++i)
      if (all.batches[i].changed) b.emplace_back(i, all.batches[i].structure);
    // The shorter run (max_events counts failures, which differ) is a prefix.
    const std::size_t common = std::min(a.size(), b.size());
    for (std::size_t i = 0; i < common; ++i) {
      CHECK(a[i].second == b[i].second);
      CHECK(k.compare(kept.batches[a[i].first].time, all.batches[b[i].first].time) == 0);
    }
    for (std::size_t i = 0; i < std::min(kept.motion_changes.size(), all.motion_changes.size()); ++i)
      CHECK(kept.motion_changes[i].time == all.motion_changes[i].time);
    compared += common;
    for (const auto& x : kept.batches) kept_made += x.certificates_recomputed;
    for (const auto& x : all.batches) all_made += x.certificates_recomputed;
  }
  WARN(compared << " structural changes compared; certificates made after batches: " << kept_made << " kept, "
                << all_made << " all");
  CHECK(compared >= 100);
  CHECK(2 * kept_made < all_made);
}

// The certificates in force are held in a hash table: what is read whole
// (traces, certificate files, the observer) must come in key order, and
// the queue must end the same, whatever order they were offered in.
TEST_CASE("the certificates in force are read in key order whatever order they came in", "[upkeep][queue]") {
  const Exact_kernel k;
  const scene::Scene s = load("uniform-density-25.json");
  const predicates::Classifier<Exact_kernel> c(k, s);
  const tree::Kvd_tree t = tree::build(c, Exact_time(mpq_class(0)));
  const auto certs = kinetic::reduced_certificates(c, t, Exact_time(mpq_class(0)));
  REQUIRE(certs.size() > 100);
  using Offer = kinetic::In_force<Exact_kernel>::Offer;
  // A failure time of each certificate's own, many of them equal.
  const auto fails = [&](const kinetic::Certificate<Exact_kernel::Poly>& cert) -> std::optional<Exact_time> {
    return Exact_time(mpq_class(static_cast<long>(kinetic::Certificate_key_hash{}(cert.key) % 13), 5));
  };
  const auto read = [](const kinetic::In_force<Exact_kernel>& f) {
    std::vector<kinetic::Certificate_key> out;
    f.for_each([&](const auto& cert) { out.push_back(cert.key); });
    return out;
  };
  std::vector<Offer> forward;
  for (const auto& cert : certs) forward.push_back({&cert, true});
  std::vector<Offer> shuffled = forward;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937_64(3));
  std::vector<kinetic::Certificate_key> keys;
  for (const auto& cert : certs) keys.push_back(cert.key);
  std::ranges::sort(keys);
  kinetic::In_force<Exact_kernel> a, b;
  auto qa = kinetic::make_queue(k, kinetic::Queue_kind::tree), qb = kinetic::make_queue(k, kinetic::Queue_kind::tree);
  qa->reset(t);
  qb->reset(t);
  a.apply({}, forward, *qa, fails);
  b.apply({}, shuffled, *qb, fails);
  CHECK(read(a) == keys);
  CHECK(read(b) == keys);
  // Every third key goes, taken out in opposite orders; the rest stay.
  std::vector<kinetic::Certificate_key> gone;
  for (std::size_t i = 0; i < keys.size(); i += 3) gone.push_back(keys[i]);
  std::vector<kinetic::Certificate_key> reversed(gone.rbegin(), gone.rend());
  a.apply(gone, {}, *qa, fails);
  b.apply(reversed, {}, *qb, fails);
  std::vector<kinetic::Certificate_key> kept;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (i % 3 != 0) kept.push_back(keys[i]);
  CHECK(read(a) == kept);
  CHECK(read(b) == kept);
  REQUIRE(qa->first_time());
  CHECK(k.compare(*qa->first_time(), *qb->first_time()) == 0);
  const auto sorted_keys = [&](const kinetic::In_force<Exact_kernel>& f, std::vector<std::size_t> ids) {
    std::vector<kinetic::Certificate_key> out;
    for (std::size_t id : ids) out.push_back(f[id].key);
    std::ranges::sort(out);
    return out;
  };
  CHECK(sorted_keys(a, qa->first()) == sorted_keys(b, qb->first()));
  CHECK(a.size() == kept.size());
}
