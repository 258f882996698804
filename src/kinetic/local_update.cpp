#include "kvd/detail/kinetic/local_update.hpp"

#include <algorithm>
#include <optional>

#include "kvd/tree/compare.hpp"

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/detail/kinetic/site_edit.hpp"
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

// Which sites of a feature's definition: those a failure moves, or all it names.
enum class Reach { moved, named };

// The sites through a symbolic vertex: those of every feature defining it,
// except that an intersection point (edge e meeting the E-plane of e') moves
// e's sites alone (thesis 7.3.2, E-update: the nodes of the edge whose
// intersection moved); e' is only named.
void sites_of(const scene::Scene& s, const SV& v, Reach reach, Sites& out) {
  const auto& id = v.ids;
  switch (v.kind) {
    case SV::Kind::endpoint: vertex_sites(s, id[0], out); break;
    case SV::Kind::intersection:
      edge_sites(s, id[0], out);
      if (reach == Reach::named) edge_sites(s, id[1], out);
      break;
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
// canonical_text would write it): the larger of the number of contents
// after that no node had before and the number of contents before that no
// node has after. Each node an update writes can take one content away and
// bring one, so no update of the same trees writes fewer nodes; and the
// count depends on the two trees alone (untouched nodes are the same in
// both; contents are distinct within a tree, pieces of one site being
// disjoint), not on how the update reused slots.
std::size_t nodes_changed(const tree::Kvd_tree& t, const tree::Tree_journal& journal, const std::vector<int>& changed) {
  const auto sorted = [](std::vector<int> v) {
    std::ranges::sort(v);
    return v;
  };
  const std::vector<int> free_before = sorted(journal.free_at_start()), free_after = sorted(t.free_nodes);
  std::vector<tree::Node_content> before, after;
  for (const auto& [n, node] : journal.saved())
    if (!std::ranges::binary_search(free_before, n)) before.push_back(tree::content(node));
  for (int n : changed)  // distinct; a changed slot past the end was released and dropped
    if (static_cast<std::size_t>(n) < t.nodes.size() && !std::ranges::binary_search(free_after, n))
      after.push_back(tree::content(t.nodes[static_cast<std::size_t>(n)]));
  std::ranges::sort(before);
  std::ranges::sort(after);
  const auto only_in = [](const std::vector<tree::Node_content>& a, const std::vector<tree::Node_content>& b) {
    std::size_t k = 0;
    for (const auto& c : a) k += !std::ranges::binary_search(b, c);
    return k;
  };
  return std::max(only_in(after, before), only_in(before, after));
}

// How a failure's changed signs are confined (proofs/local_update.md,
// section 5). `named`: all lie in the subtree of the highest node above its
// own that is cut by a site it names: a point crossing a P-plane of the
// pencil (VV, IV, II), or a vertex crossing the E-plane of an edge of
// another triangle. `turning`: a vertex crossing the E-plane of an edge of
// its own triangle T, which is T turning through z: T's plane and the
// E-planes of its three edges coincide at the event, and the signs that
// change are decided at nodes cut by those four sites, wherever they are,
// so in the subtree of their lowest common ancestor. The other failures are
// collisions or take the whole tree.
enum class Confinement { named, turning, none };

template <class Poly>
Confinement confinement(const scene::Scene& s, const Certificate<Poly>& c) {
  switch (c.key.type) {
    case Certificate_type::VV:
    case Certificate_type::IV:
    case Certificate_type::II: return Confinement::named;
    case Certificate_type::VE: {
      const SV& v = c.key.vertex;
      const SP* e = std::get_if<SP>(&c.key.against);
      if (v.kind != SV::Kind::endpoint || !e || e->kind != SP::Kind::E) return Confinement::none;
      const bool own = std::ranges::any_of(s.edge_triangles[e->id], [&](std::size_t t) {
        return std::ranges::find(s.triangles[t], v.ids[0]) != s.triangles[t].end();
      });
      return own ? Confinement::turning : Confinement::named;
    }
    default: return Confinement::none;
  }
}

// The sites of a turning triangle: the triangles of the crossed edge that
// hold the vertex (their planes turn through z), and their edges' E-planes.
template <class Poly>
Sites turning_sites(const scene::Scene& s, const Certificate<Poly>& c) {
  Sites out;
  const std::size_t v = c.key.vertex.ids[0];
  for (std::size_t t : s.edge_triangles[std::get<SP>(c.key.against).id]) {
    if (std::ranges::find(s.triangles[t], v) == s.triangles[t].end()) continue;
    out.insert({SP::Kind::T, t});
    for (std::size_t e : s.triangle_edges[t]) out.insert({SP::Kind::E, e});
  }
  return out;
}

// Whether a is n or one of n's ancestors.
bool ancestor_or_self(const tree::Tree_links& links, int a, int n) {
  for (; n >= 0; n = links.parent(n))
    if (n == a) return true;
  return false;
}

// The piece of `site` inside the cell of `scope`, cut down the scope's
// proper ancestors (`path`, root first): empty when the site misses the
// cell, and no answer when it meets the cell of an ancestor of lower or
// equal priority (its own node), where the tree in force would have it cut
// already: a sign above the scope changed. (A site the batch names cuts no
// node above the scope, by the scope's choice.)
template <class K>
std::optional<tree::Piece> piece_in_cell(const tree::Kvd_tree& t, const tree::Fragment_splitter<K>& split, const SP& site,
                                         const std::vector<int>& path, int scope) {
  const scene::Scene& s = split.classifier().motion().scene();
  const std::size_t priority = tree::cut_priority(s, site);
  tree::Piece piece = tree::site_fragment(s, site);
  for (std::size_t i = 0; i < path.size(); ++i) {
    const tree::Node& b = t.nodes[static_cast<std::size_t>(path[i])];
    if (tree::cut_priority(s, b.cut) >= priority) return std::nullopt;
    const int child = i + 1 < path.size() ? path[i + 1] : scope;
    auto [neg, pos] = split.split(*piece, b.cut, site);
    piece = b.right == child ? std::move(pos) : std::move(neg);
    if (!piece) return piece;
  }
  return piece;
}

}  // namespace

std::set<SP> sites_with(const scene::Scene& s, const SP& site) {
  Sites out;
  if (site.kind == SP::Kind::P) vertex_sites(s, site.id, out);
  else if (site.kind == SP::Kind::E) edge_sites(s, site.id, out);
  else out.insert(site);
  return out;
}

namespace {

// The sites a failure moves (reach moved) or names (reach named). A VV
// failure moves the vertex's sites, not the P-cut it crosses (thesis Fig. 7.8,
// V-update: only the point node moves; proofs/local_update.md, section 4).
template <class Poly>
Sites sites_of(const scene::Scene& s, const Certificate<Poly>& c, Reach reach) {
  Sites out;
  for (const SV& v : c.vertices) sites_of(s, v, reach, out);
  if (reach == Reach::moved && c.key.type == Certificate_type::VV) return out;
  for (const SP& p : c.planes) sites_of(s, p, out);
  return out;
}

// Whether a node of one of `sites` is a proper ancestor of n.
bool below_any(const tree::Kvd_tree& t, const tree::Tree_links& links, int n, const Sites& sites) {
  for (int a = links.parent(n); a >= 0; a = links.parent(a))
    if (sites.contains(t.nodes[static_cast<std::size_t>(a)].cut)) return true;
  return false;
}

}  // namespace

template <class Poly>
std::set<SP> moving_sites(const scene::Scene& s, const tree::Tree_links& links, const tree::Kvd_tree& t,
                          const Certificate<Poly>& failing) {
  if (failing.key.type != Certificate_type::IV) return sites_of(s, failing, Reach::moved);
  // An IV failure's P-plane moves only when its node hangs below a node of
  // the edge's sites: there it classifies corners those sites' planes make,
  // which reach the P-plane with the point (proofs/local_update.md, section 4).
  Sites out;
  for (const SV& v : failing.vertices) sites_of(s, v, Reach::moved, out);
  for (const SP& p : failing.planes)
    if (std::ranges::any_of(links.holding(p), [&](int n) { return below_any(t, links, n, out); })) sites_of(s, p, out);
  return out;
}

template <class Poly>
int update_scope(const scene::Scene& s, const tree::Tree_links& links, const tree::Kvd_tree& t,
                 const std::vector<const Certificate<Poly>*>& failing) {
  // Each certificate's highest node: its own, or an ancestor cut by a site
  // it names (named, not only moved: a VV vertex's crossed P-cut is above).
  std::vector<int> tops;
  for (const Certificate<Poly>* c : failing) {
    const Confinement how = confinement(s, *c);
    if (how == Confinement::none) return -1;
    if (how == Confinement::turning) {
      tops.push_back(c->node);
      for (const SP& site : turning_sites(s, *c))
        for (int n : links.holding(site)) tops.push_back(n);
      continue;
    }
    const Sites named = sites_of(s, *c, Reach::named);
    int top = c->node;
    for (int n = c->node; n >= 0; n = links.parent(n))
      if (named.contains(t.nodes[static_cast<std::size_t>(n)].cut)) top = n;
    tops.push_back(top);
  }
  if (tops.empty()) return -1;
  int scope = tops.front();
  for (int n : tops)
    while (scope >= 0 && !ancestor_or_self(links, scope, n)) scope = links.parent(scope);
  return scope;
}

template <class K>
Update_cost local_update(tree::Kvd_tree& t, const tree::Tree_links& links, const tree::Fragment_splitter<K>& split,
                         const std::set<SP>& moving, int scope, tree::Tree_journal* journal, Edit way) {
  const scene::Scene& s = split.classifier().motion().scene();
  const bool asked = scope >= 0;
  // Each moving site's piece inside the scope's cell, before any edit (the
  // ancestors' cuts are not edited); a sign above the scope found changed
  // widens the scope to the whole tree, where the pieces are the sites'
  // whole fragments.
  Site_pieces pieces;
  if (asked) {
    std::vector<int> path;  // the scope's proper ancestors, root first
    for (int n = links.parent(scope); n >= 0; n = links.parent(n)) path.push_back(n);
    std::ranges::reverse(path);
    for (const SP& site : moving) {
      const auto piece = piece_in_cell(t, split, site, path, scope);
      // With the signs above unchanged, a site meets the scope's cell just
      // when the tree in force holds a piece of it there.
      const bool was_in =
          std::ranges::any_of(links.holding(site), [&](int n) { return ancestor_or_self(links, scope, n); });
      if (!piece || piece->has_value() != was_in) {
        scope = -1;
        pieces.clear();
        break;
      }
      if (*piece) pieces.emplace_back(site, std::move(**piece));
    }
  }
  if (scope < 0)
    for (const SP& site : moving) pieces.emplace_back(site, tree::site_fragment(s, site));
  std::ranges::sort(pieces, {}, [&](const auto& p) { return tree::cut_priority(s, p.first); });
  // The scope's place (the root for the whole tree); its parent is outside
  // the scope and keeps its cut.
  const int above = scope >= 0 ? links.parent(scope) : -1;
  const typename Site_edit<K>::Place at{above, above >= 0 && t.nodes[static_cast<std::size_t>(above)].right == scope};
  Site_edit<K> edit(t, links, split, moving, journal);
  if (way == Edit::recut) edit.recut(at, std::move(pieces));
  else edit.reinsert(at, std::move(pieces));
  std::vector<int> changed = edit.changed();
  const std::size_t differ = journal ? nodes_changed(t, *journal, changed) : 0;
  const std::size_t touched = changed.size();
  return {moving.size(), touched, differ, std::move(changed), asked && scope < 0};
}

#define KVD_INSTANTIATE_LOCAL_UPDATE(K)                                                                      \
  template std::set<SP> moving_sites<K::Poly>(const scene::Scene&, const tree::Tree_links&,                  \
                                              const tree::Kvd_tree&, const Certificate<K::Poly>&);        \
  template int update_scope<K::Poly>(const scene::Scene&, const tree::Tree_links&, const tree::Kvd_tree&,    \
                                     const std::vector<const Certificate<K::Poly>*>&);                     \
  template Update_cost local_update<K>(tree::Kvd_tree&, const tree::Tree_links&,                          \
                                       const tree::Fragment_splitter<K>&, const std::set<SP>&, int,        \
                                       tree::Tree_journal*, Edit);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_LOCAL_UPDATE)

}  // namespace kvd::kinetic
