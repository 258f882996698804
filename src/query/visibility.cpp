#include "kvd/query/visibility.hpp"

#include <stdexcept>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::query {

namespace {

// The traversal behind both queries: far side, own fragment, near side; with
// `cull`, the far side of a T-node is skipped and counted instead.
template <class K>
Culling traverse(const predicates::Classifier<K>& classifier, const tree::Kvd_tree& tree,
                 const Point4<typename K::FT>& view, const typename K::FT& t, bool cull) {
  const K& kernel = classifier.kernel();
  Culling r;
  const tree::Tree_statistics all = tree.statistics();
  r.tree_nodes_total = all.nodes;
  r.triangle_nodes_total = all.t_nodes;
  // An explicit stack of (node, expanded?): an expanded node emits its own
  // fragment; an unexpanded one pushes near side, itself, far side.
  std::vector<std::pair<int, bool>> stack;
  if (tree.root >= 0) stack.emplace_back(tree.root, false);
  while (!stack.empty()) {
    const auto [i, expanded] = stack.back();
    stack.pop_back();
    const tree::Node& n = tree.nodes[static_cast<std::size_t>(i)];
    const bool triangle = n.cut.kind == symbolic::Symbolic_plane::Kind::T;
    if (expanded) {
      if (triangle) r.order.push_back(i);
      continue;
    }
    // The cut's plane as the tree at t keeps it: where it degenerates at t
    // (a P-plane through a vertex on the line x ∨ z) or for good (the E-plane
    // of an edge parallel to z), the plane its fragments lie on each side of.
    const int s = side(kernel, view, classifier.plane_after(n.cut, t));
    const int near = s > 0 ? n.right : n.left, far = s > 0 ? n.left : n.right;
    if (near >= 0) stack.emplace_back(near, false);
    stack.emplace_back(i, true);
    if (far < 0) continue;
    if (cull && triangle && s != 0) {
      const tree::Tree_statistics culled = tree.statistics(far);
      r.tree_nodes_culled += culled.nodes;
      r.triangle_nodes_culled += culled.t_nodes;
    } else {
      stack.emplace_back(far, false);
    }
  }
  return r;
}

}  // namespace

template <class K>
std::array<typename K::FT, 3> corner_at(const predicates::Classifier<K>& classifier, const symbolic::Symbolic_vertex& v,
                                        const typename K::FT& t) {
  const Point4<typename K::FT> p = classifier.position_after(v, t);
  if (classifier.kernel().sign(p[3]) == 0)
    throw std::logic_error("the fragment corner " + symbolic::to_string(v) + " is at infinity at the instant asked");
  return {p[0] / p[3], p[1] / p[3], p[2] / p[3]};
}

template <class K>
std::vector<int> back_to_front(const predicates::Classifier<K>& classifier, const tree::Kvd_tree& tree,
                               const Point4<typename K::FT>& view, const typename K::FT& t) {
  return traverse(classifier, tree, view, t, false).order;
}

template <class K>
Culling back_to_front_culled(const predicates::Classifier<K>& classifier, const tree::Kvd_tree& tree,
                             const typename K::FT& t) {
  const auto z = symbolic::at_instant(classifier.motion(), t).z();
  return traverse(classifier, tree, z, t, true);
}

#define KVD_INSTANTIATE_ORDER(K)                                                                                  \
  template std::array<typename K::FT, 3> corner_at<K>(const predicates::Classifier<K>&,                            \
                                                     const symbolic::Symbolic_vertex&, const typename K::FT&);  \
  template std::vector<int> back_to_front<K>(const predicates::Classifier<K>&, const tree::Kvd_tree&,           \
                                             const Point4<typename K::FT>&, const typename K::FT&);            \
  template Culling back_to_front_culled<K>(const predicates::Classifier<K>&, const tree::Kvd_tree&,             \
                                           const typename K::FT&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_ORDER)

}  // namespace kvd::query
