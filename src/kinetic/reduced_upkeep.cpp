#include "kvd/kinetic/reduced_upkeep.hpp"

#include <algorithm>
#include <string_view>
#include <unordered_set>

#include "kvd/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/tree/compare.hpp"

namespace kvd::kinetic {

namespace {

// The intersection endpoints of an E-node's fragment: the P-walls it offers
// its subtree besides its cut.
std::vector<symbolic::Symbolic_vertex> intersections(const tree::Node& n) {
  std::vector<symbolic::Symbolic_vertex> out;
  if (const auto* e = std::get_if<tree::Edge_fragment>(&n.fragment))
    for (const auto& end : {e->a, e->b})
      if (end.kind == symbolic::Symbolic_vertex::Kind::intersection) out.push_back(end);
  std::ranges::sort(out);  // the fragment's ends in either order
  return out;
}

}  // namespace

template <class K>
std::vector<typename Reduced_upkeep<K>::Held> Reduced_upkeep<K>::update(const predicates::Classifier<K>& c,
                                                                        const tree::Kvd_tree& t,
                                                                        const typename K::Time& now,
                                                                        const std::set<std::string>& failed, Work& work) {
  Reduced_maker<K> maker(c, t, now);
  std::map<Key, std::vector<Certificate<Poly>>> nodes;
  std::map<Path, int> paths;
  std::vector<Held> out;
  std::unordered_set<std::string_view> named;
  const auto holds_failed = [&](const std::vector<Certificate<Poly>>& certs) {
    return std::ranges::any_of(certs, [&](const auto& cert) { return failed.contains(cert.nodes); });
  };
  // Pre-order, with the ancestors of each node and the id of their path.
  struct Visit {
    int node, path;
    std::size_t depth;
  };
  std::vector<Visit> stack;
  std::vector<int> ancestors;
  if (t.root >= 0) stack.push_back({t.root, -1, 0});
  while (!stack.empty()) {
    const Visit v = stack.back();
    stack.pop_back();
    ancestors.resize(v.depth);
    const tree::Node& n = t.nodes[static_cast<std::size_t>(v.node)];
    Key key{v.path, n.cut, tree::canonical(n.fragment)};
    auto kept = nodes_.extract(key);
    const auto [at, first] = nodes.try_emplace(std::move(key));
    // A key met twice has the certificates of its first node, already named.
    if (first) {
      const bool made = kept.empty() || holds_failed(kept.mapped());
      at->second = made ? maker.of_node(v.node, ancestors) : std::move(kept.mapped());
      if (made) {
        ++work.nodes;
        work.certificates += at->second.size();
      }
      for (auto& cert : at->second) {
        cert.node = v.node;
        if (named.insert(cert.nodes).second) out.push_back({&cert, made});
      }
    }
    // The path id of the children: the id it had before when it was there
    // before (another node with the same cut under the same path may have
    // met it already).
    Path path{v.path, n.cut, intersections(n)};
    auto [known, fresh_path] = paths.try_emplace(std::move(path), 0);
    if (fresh_path) {
      const auto old = paths_.find(known->first);
      known->second = old != paths_.end() ? old->second : next_path_++;
    }
    const int id = known->second;
    ancestors.push_back(v.node);
    for (int child : {n.right, n.left})  // left first off the stack
      if (child >= 0) stack.push_back({child, id, v.depth + 1});
  }
  nodes_ = std::move(nodes);
  paths_ = std::move(paths);
  return out;
}

template <class K>
void Reduced_upkeep<K>::clear() {
  nodes_.clear();
  paths_.clear();
}

template <class K>
std::vector<Certificate<typename K::Poly>> reduced_certificates(const predicates::Classifier<K>& c,
                                                                const tree::Kvd_tree& t,
                                                                const typename K::Time& now) {
  Reduced_upkeep<K> upkeep;
  typename Reduced_upkeep<K>::Work work;
  std::vector<Certificate<typename K::Poly>> out;
  for (const auto& held : upkeep.update(c, t, now, {}, work)) out.push_back(*held.certificate);
  return out;
}

#define KVD_INSTANTIATE_REDUCED_UPKEEP(K)                                                               \
  template class Reduced_upkeep<K>;                                                                     \
  template std::vector<Certificate<K::Poly>> reduced_certificates<K>(const predicates::Classifier<K>&, \
                                                                     const tree::Kvd_tree&, const K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_REDUCED_UPKEEP)

}  // namespace kvd::kinetic
