#include "kvd/detail/kinetic/local_update.hpp"

#include <algorithm>
#include <tuple>

#include "kvd/tree/compare.hpp"

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/detail/tree/operations.hpp"

namespace kvd::kinetic {

namespace {

using SP = symbolic::Symbolic_plane;
using SV = symbolic::Symbolic_vertex;
using Sites = std::set<SP>;

void edge_sites(const scene::Scene& s, std::size_t e, Sites& out) {
  out.insert({SP::Kind::E, e});
  for (std::size_t t : s.edge_triangles[e]) out.insert({SP::Kind::T, t});
}

void vertex_sites(const scene::Scene& s, std::size_t v, Sites& out) {
  out.insert({SP::Kind::P, v});
  for (std::size_t e : s.vertex_edges[v]) edge_sites(s, e, out);
}

// The sites through a symbolic vertex: those of every feature defining it.
void sites_of(const scene::Scene& s, const SV& v, Sites& out) {
  const auto& id = v.ids;
  switch (v.kind) {
    case SV::Kind::endpoint: vertex_sites(s, id[0], out); break;
    case SV::Kind::intersection: edge_sites(s, id[0], out), edge_sites(s, id[1], out); break;
    case SV::Kind::thread: edge_sites(s, id[0], out), vertex_sites(s, id[1], out); break;
    case SV::Kind::internal_intersection:
      edge_sites(s, id[0], out), edge_sites(s, id[1], out), out.insert({SP::Kind::T, id[2]});
      break;
    case SV::Kind::internal_thread:
      vertex_sites(s, id[0], out), edge_sites(s, id[1], out), out.insert({SP::Kind::T, id[2]});
      break;
    case SV::Kind::axis: out.insert({SP::Kind::T, id[0]}); break;
    case SV::Kind::plumb: vertex_sites(s, id[0], out), out.insert({SP::Kind::T, id[1]}); break;
  }
}

// The sites through a certificate's plane: its own site, and for an E-plane
// the edge's triangles too, whose T-cuts are valid only inside its wall
// (proofs/local_update.md, section 4).
void sites_of(const scene::Scene& s, const SP& p, Sites& out) {
  switch (p.kind) {
    case SP::Kind::P: out.insert(p); break;
    case SP::Kind::E: edge_sites(s, p.id, out); break;
    case SP::Kind::T: out.insert(p); break;
  }
}

// The nodes_changed of Update_cost, from the journal's saved nodes (those
// that held a node before) and the live changed nodes after, by content (as
// canonical_text would write it): the slots whose content after is new or
// whose content before is gone. Contents are distinct within a tree (pieces
// of one site are disjoint).
std::size_t nodes_changed(const tree::Kvd_tree& t, const tree::Tree_journal& journal, std::vector<int> changed) {
  using Held = std::pair<tree::Node_content, int>;
  const auto sorted = [](std::vector<int> v) {
    std::ranges::sort(v);
    return v;
  };
  const std::vector<int> free_before = sorted(journal.free_at_start()), free_after = sorted(t.free_nodes);
  std::vector<Held> before, after;
  for (const auto& [n, node] : journal.saved())
    if (!std::ranges::binary_search(free_before, n)) before.emplace_back(tree::content(node), n);
  std::ranges::sort(changed);
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  for (int n : changed)  // a changed slot past the end was released and dropped
    if (static_cast<std::size_t>(n) < t.nodes.size() && !std::ranges::binary_search(free_after, n))
      after.emplace_back(tree::content(t.nodes[static_cast<std::size_t>(n)]), n);
  std::ranges::sort(before);
  std::ranges::sort(after);
  const auto holds = [](const std::vector<Held>& in, const tree::Node_content& c) {
    const auto it = std::ranges::lower_bound(in, c, {}, &Held::first);
    return it != in.end() && it->first == c;
  };
  std::vector<int> slots;
  for (const auto& [c, n] : after)
    if (!holds(before, c)) slots.push_back(n);
  for (const auto& [c, n] : before)
    if (!holds(after, c)) slots.push_back(n);
  std::ranges::sort(slots);
  return static_cast<std::size_t>(std::unique(slots.begin(), slots.end()) - slots.begin());
}

}  // namespace

std::set<SP> sites_with(const scene::Scene& s, const SP& site) {
  Sites out;
  if (site.kind == SP::Kind::P) vertex_sites(s, site.id, out);
  else if (site.kind == SP::Kind::E) edge_sites(s, site.id, out);
  else out.insert(site);
  return out;
}

template <class Poly>
std::set<SP> moving_sites(const scene::Scene& s, const Certificate<Poly>& failing) {
  Sites out;
  for (const SV& v : failing.vertices) sites_of(s, v, out);
  for (const SP& p : failing.planes) sites_of(s, p, out);
  return out;
}

template <class K>
Update_cost local_update(tree::Kvd_tree& t, const tree::Tree_links& links, const tree::Fragment_splitter<K>& split,
                         const std::set<SP>& moving, tree::Tree_journal* journal) {
  const scene::Scene& s = split.classifier().motion().scene();
  // The nodes of moving sites, with where each hangs.
  struct Held {
    std::size_t priority;
    int node, parent;
    bool right;
  };
  std::vector<Held> held;
  for (const SP& site : moving) {
    const std::size_t priority = tree::cut_priority(s, site);
    for (int n : links.holding(site)) {
      const int parent = links.parent(n);
      held.push_back({priority, n, parent, parent >= 0 && t.nodes[static_cast<std::size_t>(parent)].right == n});
    }
  }
  // Lowest priority first: a node's parent is never dragged before it.
  // Pieces of one site lie in disjoint subtrees; slots order them.
  std::sort(held.begin(), held.end(),
            [](const Held& a, const Held& b) { return std::tie(b.priority, a.node) < std::tie(a.priority, b.node); });
  tree::Tree_editor<K> editor(t, split, journal);
  std::vector<int> changed;
  for (const Held& h : held) {
    const int replacement = editor.drag(h.node);
    if (h.parent >= 0 && journal) journal->save(h.parent);
    if (h.parent < 0) t.root = replacement;
    else if (h.right) t.nodes[static_cast<std::size_t>(h.parent)].right = replacement;
    else t.nodes[static_cast<std::size_t>(h.parent)].left = replacement;
    if (h.parent >= 0) changed.push_back(h.parent);
  }
  std::vector<SP> order(moving.begin(), moving.end());
  tree::sort_by_priority(s, order);
  for (const SP& site : order) t.root = editor.insert(t.root, site, tree::site_fragment(s, site));
  const std::vector<int> touched = editor.touched_nodes();
  changed.insert(changed.end(), touched.begin(), touched.end());
  const std::size_t differ = journal ? nodes_changed(t, *journal, changed) : 0;
  return {moving.size(), touched.size(), differ, std::move(changed)};
}

#define KVD_INSTANTIATE_LOCAL_UPDATE(K)                                                                      \
  template std::set<SP> moving_sites<K::Poly>(const scene::Scene&, const Certificate<K::Poly>&);            \
  template Update_cost local_update<K>(tree::Kvd_tree&, const tree::Tree_links&,                          \
                                       const tree::Fragment_splitter<K>&, const std::set<SP>&, tree::Tree_journal*);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_LOCAL_UPDATE)

}  // namespace kvd::kinetic
