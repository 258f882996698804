#include "kvd/detail/kinetic/site_edit.hpp"

#include <algorithm>
#include <tuple>

#include "kvd/tree/compare.hpp"

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::kinetic {

using SP = symbolic::Symbolic_plane;

template <class K>
Site_edit<K>::Site_edit(tree::Kvd_tree& t, const tree::Tree_links& links, const tree::Fragment_splitter<K>& split,
                        const std::set<SP>& moving, tree::Tree_journal* journal)
    : t_(t),
      split_(split),
      s_(split.classifier().motion().scene()),
      moving_(moving),
      editor_(t, split, journal),
      journal_(journal) {
  for (const SP& site : moving)
    for (int n : links.holding(site)) links.mark_path(n, holds_);
}

template <class K>
int Site_edit<K>::child(Place at) const {
  if (at.parent < 0) return t_.root;
  const tree::Node& p = t_.nodes[static_cast<std::size_t>(at.parent)];
  return at.right ? p.right : p.left;
}

template <class K>
void Site_edit<K>::hang(Place at, int sub) {
  if (at.parent < 0) {
    t_.root = sub;
    return;
  }
  tree::Node& p = t_.nodes[static_cast<std::size_t>(at.parent)];
  int& link = at.right ? p.right : p.left;
  if (link == sub) return;
  if (journal_) journal_->save(at.parent);
  link = sub;
  relinked_.push_back(at.parent);
}

template <class K>
bool Site_edit<K>::moves(int n) const {
  return moving_.contains(t_.nodes[static_cast<std::size_t>(n)].cut);
}

template <class K>
void Site_edit<K>::reinsert(Place at, Site_pieces pieces) {
  // The moving sites' nodes in the subtree, found down the marked paths,
  // with where each hangs.
  struct Held {
    std::size_t priority;
    int node;
    Place at;
  };
  std::vector<Held> held;
  const auto collect = [&](auto&& self, int n, Place from) -> void {
    if (n < 0 || !holds_[static_cast<std::size_t>(n)]) return;
    const tree::Node& x = t_.nodes[static_cast<std::size_t>(n)];
    if (moving_.contains(x.cut)) held.push_back({tree::cut_priority(s_, x.cut), n, from});
    self(self, x.left, {n, false});
    self(self, x.right, {n, true});
  };
  collect(collect, child(at), at);
  // Lowest priority first: a node's parent is never dragged before it
  // (descendants have lower priority). Pieces of one site lie in disjoint
  // subtrees; slots order them.
  std::ranges::sort(held, [](const Held& a, const Held& b) { return std::tie(b.priority, a.node) < std::tie(a.priority, b.node); });
  for (const Held& h : held) hang(h.at, editor_.drag(h.node));
  for (auto& [site, piece] : pieces) hang(at, editor_.insert(child(at), site, std::move(piece)));
}

template <class K>
void Site_edit<K>::recut(Place at, Site_pieces pieces) {
  const int n = child(at);
  if (n < 0) return reinsert(at, std::move(pieces));
  // Nothing moving was here, and nothing moving comes: the subtree stays.
  // (The marks are those of the tree before the update; the walk reads them
  // only in subtrees it has not edited yet, whose slots still hold the
  // nodes they held then.)
  if (!holds_[static_cast<std::size_t>(n)] && pieces.empty()) return;
  const SP cut = t_.nodes[static_cast<std::size_t>(n)].cut;
  // A moving site of higher priority now meets the cell: it goes above n.
  if (!pieces.empty() && tree::cut_priority(s_, pieces.front().first) < tree::cut_priority(s_, cut))
    return reinsert(at, std::move(pieces));
  if (moves(n)) {
    // n stays where its site still meets the cell and no piece below
    // changed sides of its moved plane; its subtrees do not depend on its
    // piece, only on its plane.
    if (pieces.empty() || pieces.front().first != cut || !sides_kept(n)) return reinsert(at, std::move(pieces));
    tree::Fragment& now = pieces.front().second;
    if (tree::canonical(now) != tree::canonical(t_.nodes[static_cast<std::size_t>(n)].fragment))
      editor_.refit(n, std::move(now));
    pieces.erase(pieces.begin());
  }
  Site_pieces neg, pos;
  for (auto& [site, piece] : pieces) {
    auto [a, b] = split_.split(piece, cut, site);
    if (a) neg.emplace_back(site, std::move(*a));
    if (b) pos.emplace_back(site, std::move(*b));
  }
  recut({n, false}, std::move(neg));
  recut({n, true}, std::move(pos));
}

template <class K>
bool Site_edit<K>::sides_kept(int n) const {
  const tree::Node& x = t_.nodes[static_cast<std::size_t>(n)];
  return sides_kept(x.left, x.cut, false) && sides_kept(x.right, x.cut, true);
}

// The moving sites' pieces below are made afresh by the walk; the others
// were cut by the plane before the batch and must still lie on their side.
template <class K>
bool Site_edit<K>::sides_kept(int n, const SP& plane, bool right) const {
  if (n < 0) return true;
  const tree::Node& y = t_.nodes[static_cast<std::size_t>(n)];
  if (!moving_.contains(y.cut)) {
    const auto [neg, pos] = split_.split(y.fragment, plane, y.cut);
    if (right ? neg.has_value() : pos.has_value()) return false;
  }
  return sides_kept(y.left, plane, right) && sides_kept(y.right, plane, right);
}

template <class K>
std::vector<int> Site_edit<K>::changed() const {
  std::vector<int> out = editor_.touched_nodes();
  out.insert(out.end(), relinked_.begin(), relinked_.end());
  std::ranges::sort(out);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

#define KVD_INSTANTIATE_SITE_EDIT(K) template class Site_edit<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SITE_EDIT)

}  // namespace kvd::kinetic
