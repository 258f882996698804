// What a local update replaced (kvd/detail/segments/replay_ledger.hpp).
#include "kvd/detail/segments/replay_ledger.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace kvd::segments {

std::size_t Replay_ledger::identity(std::size_t slot) const {
  const auto it = identity_.find(slot);
  return it == identity_.end() ? slot : it->second;
}

void Replay_ledger::forgot(std::size_t slot) { forgotten_.emplace(identity(slot), tree_.nodes[slot]); }

void Replay_ledger::moved(std::size_t from, std::size_t to) {
  const std::size_t id = identity(from);
  identity_.erase(from);
  identity_[to] = id;
  location_[id] = to;
}

const Bsp_node& Replay_ledger::old_node(std::size_t id) const {
  if (const auto f = forgotten_.find(id); f != forgotten_.end()) return f->second;
  if (const auto l = location_.find(id); l != location_.end()) return tree_.nodes[l->second];
  return tree_.nodes[id];
}

bool Replay_ledger::same(std::size_t id, std::size_t slot) const {
  // A subtree kept whole, in the place it had or moved there.
  if (kept_.count(slot) && identity(slot) == id) return true;
  // A slot never forgotten, moved or kept holds its old content: nothing
  // makes a node in a slot that was not freed.
  if (id == slot && !forgotten_.count(id) && !location_.count(id) && !identity_.count(slot)) return true;
  const Bsp_node& was = old_node(id);
  const Bsp_node& now = tree_.nodes[slot];
  if (!same_cut(was, now)) return false;
  if (now.kind == Cut_kind::leaf) return true;
  return same(child(was, 0), child(now, 0)) && same(child(was, 1), child(now, 1));
}

void Replay_ledger::audit(std::size_t v) { audited_[v] = {tree_.text(v), crossings_below(tree_, v)}; }

bool Replay_ledger::changed(std::size_t v) const {
  const auto it = audited_.find(v);
  if (trust_reading_) return it->second.text != tree_.text(v);
  const bool out = !same(v, v);
  if (it != audited_.end() && out != (it->second.text != tree_.text(v)))
    throw std::logic_error("replay ledger: node " + std::to_string(v) + "'s subtree is said " +
                           (out ? "changed" : "unchanged") + " against its text before");
  return out;
}

std::vector<Site_point> Replay_ledger::gone(const std::vector<std::size_t>& roots, const Build_log& log,
                                            const std::vector<std::size_t>& rank) const {
  if (trust_reading_) return read_gone(roots);
  std::vector<Site_point> lost;
  for (const auto& [id, n] : forgotten_)
    if (n.kind == Cut_kind::intersection) lost.push_back(n.point);
  std::sort(lost.begin(), lost.end());
  lost.erase(std::unique(lost.begin(), lost.end()), lost.end());
  if (!lost.empty()) {
    // The crossings cut by nodes made: below the roots, above the tops kept.
    std::vector<Site_point> made;
    std::vector<std::size_t> stack(roots.begin(), roots.end());
    while (!stack.empty()) {
      const Bsp_node& n = tree_.nodes[stack.back()];
      const bool top = kept_.count(stack.back()) > 0;
      stack.pop_back();
      if (n.kind == Cut_kind::intersection) made.push_back(n.point);
      if (!top && n.kind != Cut_kind::leaf) stack.insert(stack.end(), {child(n, 0), child(n, 1)});
    }
    std::sort(made.begin(), made.end());
    const auto located = [&](const Site_point& x) {
      for (const std::size_t t : kept_) {
        const auto& at = log.at[t];
        const auto [from, to] = rank_block(at, rank, point_rank(x, rank));
        for (std::size_t i = from; i < to; ++i)
          if (at[i].kind == Arrival::Kind::intersection && at[i].a == x) return true;
      }
      return false;
    };
    std::erase_if(lost, [&](const Site_point& x) { return std::binary_search(made.begin(), made.end(), x) || located(x); });
  }
  if (!audited_.empty())
    if (const std::vector<Site_point> read = read_gone(roots); read != lost)
      throw std::logic_error("replay ledger: " + std::to_string(lost.size()) + " crossings said gone, " +
                             std::to_string(read.size()) + " read gone from the subtrees");
  return lost;
}

std::vector<Site_point> Replay_ledger::read_gone(const std::vector<std::size_t>& roots) const {
  std::vector<Site_point> was, is;
  for (const auto& [v, reading] : audited_) was.insert(was.end(), reading.crossings.begin(), reading.crossings.end());
  for (const std::size_t v : roots) {
    const std::vector<Site_point> x = crossings_below(tree_, v);
    is.insert(is.end(), x.begin(), x.end());
  }
  std::sort(was.begin(), was.end());
  std::sort(is.begin(), is.end());
  std::vector<Site_point> read;
  std::set_difference(was.begin(), was.end(), is.begin(), is.end(), std::back_inserter(read));
  read.erase(std::unique(read.begin(), read.end()), read.end());
  return read;
}

}  // namespace kvd::segments
