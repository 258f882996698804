#include "kvd/tree/build.hpp"

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/detail/tree/operations.hpp"

namespace kvd::tree {

// Every site inserted in priority order: each insertion then only descends
// to the leaves (the out-of-order case of insert never arises).
template <class K>
Kvd_tree build(const predicates::Classifier<K>& classifier, const typename K::Time& t, Evaluated* evaluated) {
  const Fragment_splitter<K> split(classifier, t, evaluated);
  Kvd_tree tree;
  Tree_editor<K> editor(tree, split);
  const scene::Scene& s = classifier.motion().scene();
  for (const Symbolic_plane& site : sites_in_priority_order(s))
    tree.root = editor.insert(tree.root, site, site_fragment(s, site));
  return tree;
}

#define KVD_INSTANTIATE_BUILD(K) \
  template Kvd_tree build<K>(const predicates::Classifier<K>&, const typename K::Time&, Evaluated*);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_BUILD)

}  // namespace kvd::tree
