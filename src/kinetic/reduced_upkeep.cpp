#include "kvd/detail/kinetic/reduced_upkeep.hpp"

#include <algorithm>

#include "kvd/detail/tree/slot_room.hpp"
#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/tree/compare.hpp"

namespace kvd::kinetic {

namespace {

// Slot sets as increasing vectors.
void add(std::vector<int>& slots, int s) {
  const auto it = std::ranges::lower_bound(slots, s);
  if (it == slots.end() || *it != s) slots.insert(it, s);
}
void remove(std::vector<int>& slots, int s) {
  const auto it = std::ranges::lower_bound(slots, s);
  if (it != slots.end() && *it == s) slots.erase(it);
}

}  // namespace

template <class K>
typename Reduced_upkeep<K>::Changes Reduced_upkeep<K>::update(const predicates::Classifier<K>& c,
                                                              const tree::Kvd_tree& t, const tree::Tree_links& links,
                                                              const std::vector<int>* edited,
                                                              const typename K::Time& now,
                                                              const std::set<Certificate_key>& failed, Work& work) {
  // Marks left by an update that threw are not this update's.
  for (tree::Slot_marks* m : {&failed_, &marked_, &not_kept_, &given_, &rewritten_, &fresh_}) m->clear();
  tree::room_for(records_, t.nodes.size());
  records_.resize(std::max(records_.size(), t.nodes.size()));
  const bool whole = !edited || remake_;
  // The slots whose record holds a failed certificate, from the holders of
  // the failed keys (records are read below only as they were on entry).
  for (const Certificate_key& key : failed)
    if (const std::vector<int>* h = holders_.find(key))
      for (int slot : *h) failed_.set(static_cast<std::size_t>(slot));
  const auto holds_failed = [&](std::size_t slot) { return failed_[slot]; };
  // What the walk must look at: the nodes the edit changed, those holding a
  // failed certificate, and their ancestors. An unmarked node below the
  // same ancestors as before roots a subtree the batch left alone, every
  // record of which is kept in place (its keys cannot have changed).
  if (!whole) {
    for (int n : *edited)
      if (links.live(n)) links.mark_path(n, marked_);
    for (std::size_t slot : failed_.marked())
      if (links.live(static_cast<int>(slot))) links.mark_path(static_cast<int>(slot), marked_);
  }
  // The slots whose records are not kept in place: released ones, and
  // pending nodes (below); listed when they held a record.
  std::vector<int> not_kept_slots;
  const auto drop = [&](std::size_t slot) {
    if (not_kept_.set(slot) && records_[slot].used) not_kept_slots.push_back(static_cast<int>(slot));
  };
  if (whole) {
    for (std::size_t slot = 0; slot < records_.size(); ++slot)
      if (!links.live(static_cast<int>(slot))) drop(slot);
  } else {
    for (int n : *edited)
      if (!links.live(n) && static_cast<std::size_t>(n) < records_.size()) drop(static_cast<std::size_t>(n));
    for (std::size_t slot = t.nodes.size(); slot < records_.size(); ++slot) drop(slot);
  }
  // 1. Pre-order: the nodes whose slot holds their key keep their record;
  // the others are pending, with their key and ancestors.
  struct Pending {
    int node;
    Key key;
    std::vector<int> ancestors;
    int path, children_path;
  };
  std::vector<Pending> pending;
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
    const auto slot = static_cast<std::size_t>(v.node);
    const tree::Node& n = t.nodes[slot];
    Record& r = records_[slot];
    if (!whole && !marked_[slot] && r.used && r.path == v.path) continue;
    ancestors.resize(v.depth);
    const auto children_of = [&] {
      const auto [id, fresh] = paths_.try_emplace(Path{v.path, n.cut, intersection_walls(n)});
      if (fresh) *id = next_path_++;
      return *id;
    };
    const int key_path = names_walls(n) ? v.path : unwalled;
    int children;
    if (!remake_ && r.used && r.key.path == key_path && r.key.cut == n.cut &&
        (r.fragment == n.fragment || r.key.fragment == tree::canonical(n.fragment)) && !holds_failed(slot)) {
      // Kept; under other ancestors (an unwalled node) it gives its children another path.
      if (r.path != v.path) {
        r.path = v.path;
        r.children_path = children_of();
      }
      children = r.children_path;
    } else {
      children = children_of();
      pending.push_back({v.node, Key{key_path, n.cut, tree::canonical(n.fragment)}, ancestors, v.path, children});
      drop(slot);
    }
    ancestors.push_back(v.node);
    for (int child : {n.right, n.left})  // left first off the stack
      if (child >= 0) stack.push_back({child, children, v.depth + 1});
  }
  // The holders of the keys that records not kept in place lose (with
  // each touched key's holder before).
  kvd::detail::Flat_map<Certificate_key, int, Certificate_key_hash> before;
  const auto touch = [&](const Certificate_key& key) -> std::vector<int>& {
    auto& h = holders_[key];
    if (const auto [old, fresh] = before.try_emplace(key); fresh) *old = h.empty() ? -1 : h.front();
    return h;
  };
  for (int slot : not_kept_slots)
    for (const auto& cert : records_[static_cast<std::size_t>(slot)].certificates) remove(touch(cert.key), slot);
  // 2. A pending key held before by another slot that is not kept in place
  // (the rebuild renumbers every node) keeps that slot's certificates;
  // the other pending nodes make theirs. Records are written afterwards:
  // a slot may give its certificates to a node of another slot.
  std::vector<std::vector<Certificate<Poly>>> certs(pending.size());
  std::vector<bool> made(pending.size());
  for (std::size_t p = 0; p < pending.size(); ++p) {
    const int* old = where_.find(pending[p].key);
    const auto from = old ? static_cast<std::size_t>(*old) : records_.size();
    if (!remake_ && from < records_.size() && not_kept_[from] && !holds_failed(from) && given_.set(from))
      certs[p] = std::move(records_[from].certificates);
    else
      made[p] = true;
  }
  // A node that makes its certificates takes, from the record its slot held
  // and did not give, those under a key that did not fail: a certificate's
  // polynomials are its key's, and positive just after now unless it
  // failed. (Not in the reference, which makes everything again.)
  Reduced_maker<K> maker(c, t, now);
  for (std::size_t p = 0; p < pending.size(); ++p) {
    if (!made[p]) continue;
    const auto slot = static_cast<std::size_t>(pending[p].node);
    std::vector<Certificate<Poly>>* held =
        !remake_ && slot < records_.size() && !given_[slot] ? &records_[slot].certificates : nullptr;
    certs[p] = maker.of_node(pending[p].node, pending[p].ancestors, held, failed);
    ++work.nodes;
    work.certificates += certs[p].size();
  }
  // 3. The records of the tree just after.
  for (int slot : not_kept_slots) {
    Record& r = records_[static_cast<std::size_t>(slot)];
    if (const int* w = where_.find(r.key); w && *w == slot) where_.erase(r.key);
    r = Record{};
  }
  for (std::size_t p = 0; p < pending.size(); ++p) {
    const auto slot = static_cast<std::size_t>(pending[p].node);
    const tree::Node& n = t.nodes[slot];
    Record& r = records_[slot];
    r.used = true;
    r.fragment = n.fragment;
    r.path = pending[p].path;
    r.children_path = pending[p].children_path;
    r.certificates = std::move(certs[p]);
    for (auto& cert : r.certificates) {
      cert.node = pending[p].node;
      add(touch(cert.key), pending[p].node);
    }
    // A key met twice stays with its first node.
    if (const auto [w, fresh] = where_.try_emplace(pending[p].key); fresh) *w = pending[p].node;
    r.key = std::move(pending[p].key);
    rewritten_.set(slot);
    if (made[p]) fresh_.set(slot);
  }
  records_.resize(t.nodes.size());
  remake_ = false;
  // 4. What changed in force: a key whose holder is new or rewritten; by key.
  std::vector<std::pair<Certificate_key, int>> touched;
  touched.reserve(before.size());
  before.for_each([&](const Certificate_key& key, int old) { touched.emplace_back(key, old); });
  std::ranges::sort(touched);
  Changes out;
  for (const auto& [key, old] : touched) {
    const std::vector<int>& h = *holders_.find(key);
    if (h.empty()) {
      if (old >= 0) out.gone.push_back(key);
      holders_.erase(key);
      continue;
    }
    const int holder = h.front();
    const auto slot = static_cast<std::size_t>(holder);
    if (holder == old && !rewritten_[slot]) continue;
    for (const auto& cert : records_[slot].certificates)
      if (cert.key == key) out.changed.push_back({&cert, fresh_[slot]});
  }
  return out;
}

template <class K>
void Reduced_upkeep<K>::clear() {
  records_.clear();
  where_.clear();
  holders_.clear();
  paths_.clear();
}

template <class K>
std::vector<Certificate<typename K::Poly>> reduced_certificates(const predicates::Classifier<K>& c,
                                                                const tree::Kvd_tree& t,
                                                                const typename K::Time& now) {
  Reduced_upkeep<K> upkeep;
  typename Reduced_upkeep<K>::Work work;
  std::vector<Certificate<typename K::Poly>> out;
  for (const auto& held : upkeep.update(c, t, tree::Tree_links(t), nullptr, now, {}, work).changed)
    out.push_back(*held.certificate);
  return out;
}

#define KVD_INSTANTIATE_REDUCED_UPKEEP(K)                                                               \
  template class Reduced_upkeep<K>;                                                                     \
  template std::vector<Certificate<K::Poly>> reduced_certificates<K>(const predicates::Classifier<K>&, \
                                                                     const tree::Kvd_tree&, const K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_REDUCED_UPKEEP)

}  // namespace kvd::kinetic
