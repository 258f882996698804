#include "kvd/detail/kinetic/local_update.hpp"

#include <algorithm>
#include <map>
#include <string>
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
// that held a node before) and the live changed nodes after, by canonical
// text: the slots whose text after is new or whose text before is gone.
// Texts are distinct within a tree (pieces of one site are disjoint).
std::size_t nodes_changed(const tree::Kvd_tree& t, const tree::Tree_journal& journal, std::vector<int> changed) {
  std::map<int, std::string> before, after;
  const std::set<int> free_before(journal.free_at_start().begin(), journal.free_at_start().end());
  for (const auto& [n, node] : journal.saved())
    if (!free_before.contains(n)) before.emplace(n, tree::canonical_text(node));
  const std::set<int> free_after(t.free_nodes.begin(), t.free_nodes.end());
  for (int n : changed)  // a changed slot past the end was released and dropped
    if (static_cast<std::size_t>(n) < t.nodes.size() && !free_after.contains(n))
      after.emplace(n, tree::canonical_text(t.nodes[static_cast<std::size_t>(n)]));
  std::set<std::string> texts_before, texts_after;
  for (const auto& [n, text] : before) texts_before.insert(text);
  for (const auto& [n, text] : after) texts_after.insert(text);
  std::set<int> slots;
  for (const auto& [n, text] : after)
    if (!texts_before.contains(text)) slots.insert(n);
  for (const auto& [n, text] : before)
    if (!texts_after.contains(text)) slots.insert(n);
  return slots.size();
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
