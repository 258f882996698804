// One segment's steps below a node decided again
// (kvd/detail/segments/reroute.hpp).
#include "kvd/detail/segments/reroute.hpp"

#include <map>
#include <set>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

template <class K>
std::vector<std::size_t> reroute_segment(Bsp_builder<K>& builder, const Cylindrical_bsp& tree, Build_log& log,
                                         const std::vector<std::size_t>& rank, std::size_t u, std::size_t r,
                                         std::size_t frontier_rank, const Reroute_above& above) {
  const auto frontier = [&](std::size_t n) { return cut_rank(tree.nodes[n], rank) >= frontier_rank; };
  const auto mine = [&](std::size_t n) {
    const auto& at = log.at[n];
    const auto [from, to] = rank_block(at, rank, r);
    return std::vector<Arrival>(at.begin() + static_cast<std::ptrdiff_t>(from), at.begin() + static_cast<std::ptrdiff_t>(to));
  };
  // The segment's steps below u before: its block in the logs of the nodes
  // its walks reach through the nodes above the frontier.
  std::map<std::size_t, std::vector<Arrival>> before, after;
  std::vector<std::size_t> stack;
  for (const std::int32_t c : tree.nodes[u].child) stack.push_back(static_cast<std::size_t>(c));
  while (!stack.empty()) {
    const std::size_t n = stack.back();
    stack.pop_back();
    std::vector<Arrival> steps = mine(n);
    if (steps.empty()) continue;
    before[n] = std::move(steps);
    if (!frontier(n))
      for (const std::int32_t c : tree.nodes[n].child) stack.push_back(static_cast<std::size_t>(c));
  }
  builder.reroute(u, mine(u), frontier_rank, after);
  std::set<std::size_t> reached;
  for (const auto& [n, steps] : before) reached.insert(n);
  for (const auto& [n, steps] : after) reached.insert(n);
  std::vector<std::size_t> changed;
  for (const std::size_t n : reached) {
    auto& at = log.at[n];
    const auto [from, to] = rank_block(at, rank, r);
    const std::vector<Arrival>&now = after[n], &was = before[n];
    at.erase(at.begin() + static_cast<std::ptrdiff_t>(from), at.begin() + static_cast<std::ptrdiff_t>(to));
    at.insert(at.begin() + static_cast<std::ptrdiff_t>(from), now.begin(), now.end());
    if (!frontier(n)) {
      if (above) above(n, was, now);
    }
    else if (was != now) changed.push_back(n);
  }
  return changed;
}

void drop_unwalked_crossings(std::vector<Arrival>& log) {
  std::set<std::uint32_t> walked;
  for (const Arrival& a : log)
    if (a.kind == Arrival::Kind::crossings) walked.insert(a.segment);
  std::erase_if(log, [&](const Arrival& a) { return a.kind == Arrival::Kind::intersection && !walked.count(a.segment); });
}

#define KVD_INSTANTIATE_REROUTE(K)                                                                              \
  template std::vector<std::size_t> reroute_segment<K>(Bsp_builder<K>&, const Cylindrical_bsp&, Build_log&,     \
                                                       const std::vector<std::size_t>&, std::size_t, std::size_t, \
                                                       std::size_t, const Reroute_above&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_REROUTE)

}  // namespace kvd::segments
