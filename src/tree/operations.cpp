#include "kvd/detail/tree/operations.hpp"

#include <algorithm>
#include <stdexcept>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::tree {

using SE = symbolic::Symbolic_edge;
using SP = Symbolic_plane;
using SV = Symbolic_vertex;

std::size_t cut_priority(const scene::Scene& s, const SP& cut) {
  switch (cut.kind) {
    case SP::Kind::P: return s.vertex_cut_priority[cut.id];
    case SP::Kind::E: return s.edge_cut_priority[cut.id];
    case SP::Kind::T: break;
  }
  return s.triangle_cut_priority[cut.id];
}

Fragment site_fragment(const scene::Scene& s, const SP& cut) {
  switch (cut.kind) {
    case SP::Kind::P: return SV::endpoint(cut.id);
    case SP::Kind::E: {
      const auto& e = s.edges[cut.id];
      return Edge_fragment{SV::endpoint(e[0]), SV::endpoint(e[1]), SE{SE::Kind::edge, cut.id, 0}};
    }
    case SP::Kind::T: break;
  }
  Triangle_fragment f;
  for (std::size_t k = 0; k < 3; ++k) {
    f.corners.push_back(SV::endpoint(s.triangles[cut.id][k]));
    f.sides.push_back(SE{SE::Kind::edge, s.triangle_edges[cut.id][k], 0});
  }
  return f;
}

void sort_by_priority(const scene::Scene& s, std::vector<SP>& sites) {
  std::sort(sites.begin(), sites.end(), [&](const SP& a, const SP& b) { return cut_priority(s, a) < cut_priority(s, b); });
}

std::vector<SP> sites_in_priority_order(const scene::Scene& s) {
  std::vector<SP> out;
  // A vertex of no triangle is no feature of the decomposition: it has no cut.
  for (std::size_t v = 0; v < s.rest.size(); ++v)
    if (!s.vertex_edges[v].empty()) out.push_back({SP::Kind::P, v});
  for (std::size_t e = 0; e < s.edges.size(); ++e) out.push_back({SP::Kind::E, e});
  for (std::size_t t = 0; t < s.triangles.size(); ++t) out.push_back({SP::Kind::T, t});
  sort_by_priority(s, out);
  return out;
}

template <class K>
Tree_editor<K>::Tree_editor(Kvd_tree& t, const Fragment_splitter<K>& split, Tree_journal* journal)
    : t_(t), split_(split), s_(split.classifier().motion().scene()), journal_(journal) {}

template <class K>
Node& Tree_editor<K>::edit(int i) {
  if (journal_) journal_->save(i);
  return node(i);
}

template <class K>
std::size_t Tree_editor<K>::priority(int n) const {
  return cut_priority(s_, t_.nodes[static_cast<std::size_t>(n)].cut);
}

template <class K>
int Tree_editor<K>::make(Node n) {
  int i;
  if (t_.free_nodes.empty()) {
    t_.nodes.push_back(std::move(n));
    i = static_cast<int>(t_.nodes.size()) - 1;
  } else {
    i = t_.free_nodes.back();
    t_.free_nodes.pop_back();
    edit(i) = std::move(n);
  }
  touched_.push_back(i);
  return i;
}

template <class K>
void Tree_editor<K>::relink(int n, int left, int right) {
  if (node(n).left == left && node(n).right == right) return;
  Node& x = edit(n);
  x.left = left, x.right = right;
  touched_.push_back(n);
}

template <class K>
void Tree_editor<K>::release(int n) {
  Node& x = edit(n);
  x.left = x.right = -1;
  t_.free_nodes.push_back(n);
  touched_.push_back(n);
}

template <class K>
std::vector<int> Tree_editor<K>::touched_nodes() const {
  std::vector<int> t = touched_;
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

// A node is split when its piece crosses the plane; otherwise it stays on
// its side, and on the other side its two subtrees lie in one cell, which
// its cut no longer divides: they are merged.
template <class K>
std::pair<int, int> Tree_editor<K>::split_tree(int t, SP plane) {
  if (t < 0) return {-1, -1};
  const SP cut = node(t).cut;
  auto [neg, pos] = split_.split(node(t).fragment, plane, cut);
  const auto [ln, lp] = split_tree(node(t).left, plane);
  const auto [rn, rp] = split_tree(node(t).right, plane);
  if (neg && pos) {
    edit(t).fragment = std::move(*neg);
    touched_.push_back(t);
    relink(t, ln, rn);
    return {t, make(Node{cut, std::move(*pos), lp, rp})};
  }
  if (neg) {
    relink(t, ln, rn);
    return {t, merge(lp, rp, cut)};
  }
  relink(t, lp, rp);
  return {merge(ln, rn, cut), t};
}

template <class K>
int Tree_editor<K>::merge(int t1, int t2, SP between) {
  if (t1 < 0) return t2;
  if (t2 < 0) return t1;
  if (priority(t1) == priority(t2)) {  // one site, its two pieces meeting across `between`
    Fragment joined = join(node(t1).fragment, node(t2).fragment, between, node(t1).cut);
    edit(t1).fragment = std::move(joined);
    touched_.push_back(t1);
    const int l2 = node(t2).left, r2 = node(t2).right;
    release(t2);
    const int l = merge(node(t1).left, l2, between);
    const int r = merge(node(t1).right, r2, between);
    relink(t1, l, r);
    return t1;
  }
  if (priority(t2) < priority(t1)) std::swap(t1, t2);
  const auto [neg, pos] = split_tree(t2, node(t1).cut);
  const int l = merge(node(t1).left, neg, between);
  const int r = merge(node(t1).right, pos, between);
  relink(t1, l, r);
  return t1;
}

template <class K>
int Tree_editor<K>::insert(int t, SP cut, Fragment f) {
  if (t < 0) return make(Node{cut, std::move(f)});
  if (priority(t) < cut_priority(s_, cut)) {
    auto [neg, pos] = split_.split(f, node(t).cut, cut);
    const int l = neg ? insert(node(t).left, cut, std::move(*neg)) : node(t).left;
    const int r = pos ? insert(node(t).right, cut, std::move(*pos)) : node(t).right;
    relink(t, l, r);
    return t;
  }
  const auto [l, r] = split_tree(t, cut);
  return make(Node{cut, std::move(f), l, r});
}

template <class K>
int Tree_editor<K>::drag(int n) {
  const int l = node(n).left, r = node(n).right;
  const SP cut = node(n).cut;
  release(n);
  return merge(l, r, cut);
}

template <class K>
void Tree_editor<K>::refit(int n, Fragment f) {
  edit(n).fragment = std::move(f);
  touched_.push_back(n);
}

// The union of two pieces of one site split by `between`. Edge pieces share
// the crossing vertex. Triangle pieces share their side on the cut line;
// the union walks a's corners from the end of that side round to its start,
// then b's likewise, and drops the shared corners that were crossings (where
// the side coming in is the side going out).
template <class K>
Fragment Tree_editor<K>::join(const Fragment& a, const Fragment& b, const SP& between, const SP& cut) const {
  if (const auto* ea = std::get_if<Edge_fragment>(&a)) {
    const auto& eb = std::get<Edge_fragment>(b);
    if (ea->b == eb.a) return Edge_fragment{ea->a, eb.b, ea->edge};
    if (eb.b == ea->a) return Edge_fragment{eb.a, ea->b, ea->edge};
    throw std::logic_error("join: edge pieces " + to_string(a) + " and " + to_string(b) + " do not meet");
  }
  const auto& ta = std::get<Triangle_fragment>(a);
  const auto& tb = std::get<Triangle_fragment>(b);
  if (between.kind == SP::Kind::T) throw std::logic_error("join: a triangle piece split by a triangle's plane");
  const SE line{between.kind == SP::Kind::P ? SE::Kind::pt : SE::Kind::et, between.id, cut.id};
  const auto at = [&](const Triangle_fragment& f) {
    for (std::size_t i = 0; i < f.sides.size(); ++i)
      if (f.sides[i] == line) return i;
    throw std::logic_error("join: triangle piece " + to_string(Fragment(f)) + " has no side on " + symbolic::to_string(line));
  };
  const std::size_t i = at(ta), j = at(tb), na = ta.corners.size(), nb = tb.corners.size();
  std::vector<std::pair<SV, SE>> ring;
  for (std::size_t k = 1; k < na; ++k) ring.emplace_back(ta.corners[(i + k) % na], ta.sides[(i + k) % na]);
  for (std::size_t k = 1; k < nb; ++k) ring.emplace_back(tb.corners[(j + k) % nb], tb.sides[(j + k) % nb]);
  Triangle_fragment out;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const SE& in = ring[(k + ring.size() - 1) % ring.size()].second;
    if (in == ring[k].second) continue;  // a crossing of the removed cut
    out.corners.push_back(ring[k].first);
    out.sides.push_back(ring[k].second);
  }
  return out;
}

#define KVD_INSTANTIATE_EDITOR(K) template class Tree_editor<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_EDITOR)

}  // namespace kvd::tree
