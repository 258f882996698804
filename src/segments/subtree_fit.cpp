// A node made again with its old subtrees kept where their arrivals did not
// change (kvd/detail/segments/subtree_fit.hpp; proofs/segment-local-update.md,
// "Cells kept").
#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/segments/reroute.hpp"
#include "kvd/detail/segments/subtree_fit.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

template <class K>
Subtree_fit<K>::Subtree_fit(Cylindrical_bsp& tree, Build_log& log, const Segment_scene& scene, Bsp_builder<K>& builder,
                            std::set<std::size_t>& dirty, Subtree_fit_hooks hooks)
    : tree_(tree),
      log_(log),
      scene_(scene),
      builder_(builder),
      dirty_(dirty),
      hooks_(std::move(hooks)),
      ledger_(tree) {}

template <class K>
std::vector<std::size_t> Subtree_fit<K>::set_aside(std::size_t v, std::size_t r, bool several) {
  if (several) dirty_.insert(v);
  const auto& rank = scene_.rank;
  std::vector<std::size_t> spare, stack{v};
  while (!stack.empty()) {
    const std::size_t n = stack.back();
    stack.pop_back();
    const Bsp_node& node = tree_.nodes[n];
    if (cut_rank(node, rank) > r) {
      spare.push_back(n);
      continue;
    }
    for (const std::int32_t c : node.child) stack.push_back(static_cast<std::size_t>(c));
    ledger_.forgot(n);
    hooks_.forget(n);
    if (n != v) log_.free.push_back(n);
  }
  if (!spare.empty() && spare.front() == v) {
    // v keeps its slot for the segment's cuts: what it held moves aside.
    Bsp_node aside;
    aside.cell = tree_.nodes[v].cell;
    const std::size_t m = place_node(tree_, &log_, aside);
    move_node(v, m);
    // m may be a slot freed earlier with a mark of its own: it takes v's.
    if (dirty_.count(v)) dirty_.insert(m);
    else dirty_.erase(m);
    // The segment had no step at v (it would have cut v): its new ones go.
    auto& log = log_.at[m];
    const auto [from, to] = rank_block(log, scene_.rank, r);
    log.erase(log.begin() + static_cast<std::ptrdiff_t>(from), log.begin() + static_cast<std::ptrdiff_t>(to));
    spare.front() = m;
  }
  return spare;
}

template <class K>
void Subtree_fit<K>::remake(std::size_t v, std::size_t r, const std::vector<Arrival>& arrivals,
                            std::vector<std::size_t> spare) {
  const auto [from, to] = rank_block(arrivals, scene_.rank, r);
  builder_.replay(v, std::vector<Arrival>(arrivals.begin() + static_cast<std::ptrdiff_t>(from),
                                          arrivals.begin() + static_cast<std::ptrdiff_t>(to)));
  fit_cells(cells_below(v, r, arrivals, to), spare);
  for (const std::size_t o : spare) discard(o, true);
}

template <class K>
std::vector<std::pair<std::size_t, std::vector<Arrival>>> Subtree_fit<K>::cells_below(
    std::size_t v, std::size_t r, const std::vector<Arrival>& arrivals, std::size_t to) {
  // The later segments' steps; their crossings with the segment of rank r
  // are found again at its new cuts, or are gone.
  const auto s = static_cast<std::uint32_t>(scene_.priority_order[r]);
  std::vector<Arrival> later;
  for (std::size_t k = to; k < arrivals.size(); ++k)
    if (arrivals[k].kind != Arrival::Kind::intersection || other_segment(arrivals[k]) != s) later.push_back(arrivals[k]);
  log_.at[v].insert(log_.at[v].end(), later.begin(), later.end());
  std::map<std::size_t, std::vector<Arrival>> at;
  builder_.reroute(v, later, r + 1, at);
  std::vector<std::pair<std::size_t, std::vector<Arrival>>> cells;
  tops_.push_back(v);
  if (tree_.nodes[v].kind == Cut_kind::leaf) cells.emplace_back(v, log_.at[v]);
  for (auto& [n, got] : at) {
    if (tree_.nodes[n].kind == Cut_kind::leaf) {
      cells.emplace_back(n, std::move(got));
    } else {
      tops_.push_back(n);
      auto& log = log_.at[n];
      log.insert(log.end(), got.begin(), got.end());
    }
  }
  // The cells pick from the old subtrees in turn (fit_cells).
  sort_in_preorder(tree_, cells, [](const auto& c) { return c.first; });
  return cells;
}

namespace {

// The steps without the intersection arrivals of a crossing that cannot lie
// in the cell: the crossing's earlier segment neither walks its edge through
// the cell nor bounds it, or its later segment's crossing walk does not
// reach the cell (no cut of a later segment lies above a cell of the fit:
// drop_unwalked_crossings). A crossing that goes at this instant, below the
// frontier the rerouted steps stop at, leaves such arrivals: they were kept
// to be found below the frontier, and are located by signs that no longer
// put the crossing on that segment's fragment.
std::vector<Arrival> in_cell(const std::vector<Arrival>& steps, const Cell& cell) {
  std::vector<std::uint32_t> walking;  // the segments walking an edge through the cell, sorted
  for (const Arrival& e : steps)
    if (e.kind == Arrival::Kind::edges) walking.push_back(e.segment);
  std::sort(walking.begin(), walking.end());
  std::vector<Arrival> out;
  for (const Arrival& a : steps) {
    if (a.kind == Arrival::Kind::intersection) {
      const std::uint32_t j = other_segment(a);
      if (cell.floor != j && cell.roof != j && !std::binary_search(walking.begin(), walking.end(), j)) continue;
    }
    out.push_back(a);
  }
  drop_unwalked_crossings(out);
  return out;
}

// What an old subtree's log and a cell's arrivals share, ignoring where the
// walks end (a moved wall renames them): the points located and the
// segments walking, sorted.
using Arrival_key = std::tuple<Arrival::Kind, std::uint32_t, Site_point>;

std::vector<Arrival_key> arrival_keys(const std::vector<Arrival>& log) {
  std::vector<Arrival_key> keys;
  keys.reserve(log.size());
  for (const Arrival& a : log) keys.emplace_back(a.kind, a.segment, locates(a) ? a.a : Site_point{});
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::size_t shared(const std::vector<Arrival_key>& a, const std::vector<Arrival_key>& b) {
  std::size_t n = 0;
  for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end();) {
    if (*i < *j) ++i;
    else if (*j < *i) ++j;
    else ++n, ++i, ++j;
  }
  return n;
}

int sides_shared(const Cell& a, const Cell& b) {
  return (a.left == b.left) + (a.right == b.right) + (a.floor == b.floor) + (a.roof == b.roof);
}

}  // namespace

template <class K>
void Subtree_fit<K>::fit_cells(std::vector<std::pair<std::size_t, std::vector<Arrival>>> cells,
                               std::vector<std::size_t>& spare) {
  // Cells that an old subtree makes whole take it first: fitted below a
  // matching top, another cell would use it up.
  std::vector<Fitting> rest;
  for (auto& [cell, all] : cells) {
    std::vector<Arrival> steps = in_cell(all, tree_.nodes[cell].cell);
    if (!take_whole(cell, steps, spare)) rest.push_back({cell, std::move(steps), std::nullopt, 0, std::nullopt});
  }
  // The others get the cuts of their first segment; an old subtree with
  // the same cut on top goes to the cell whose arrivals it shares most,
  // over all the cells here (the first cell to ask may lie beside it).
  for (Fitting& f : rest) first_cuts(f, spare);
  std::vector<std::tuple<std::size_t, std::size_t, std::size_t>> pairs;  // (score, cell's place, spare's place)
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (!rest[i].rank) continue;
    const Bsp_node& made = tree_.nodes[rest[i].cell];
    const std::vector<Arrival_key> want = arrival_keys(rest[i].steps);
    for (std::size_t k = 0; k < spare.size(); ++k)
      if (same_cut(tree_.nodes[spare[k]], made))
        pairs.emplace_back(4 * shared(want, arrival_keys(log_.at[spare[k]])) +
                               sides_shared(tree_.nodes[spare[k]].cell, made.cell),
                           i, k);
  }
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return std::get<0>(a) > std::get<0>(b); });
  std::vector<bool> used(spare.size());
  for (const auto& [score, i, k] : pairs)
    if (!rest[i].old && !used[k]) {
      rest[i].old = spare[k];
      used[k] = true;
    }
  std::vector<std::size_t> left;
  for (std::size_t k = 0; k < spare.size(); ++k)
    if (!used[k]) left.push_back(spare[k]);
  spare = std::move(left);
  for (const Fitting& f : rest) fit(f, spare);
}

template <class K>
bool Subtree_fit<K>::take_whole(std::size_t cell, const std::vector<Arrival>& steps, std::vector<std::size_t>& spare) {
  // The arrivals of an old subtree that holds no failing node: it is the
  // subtree they make.
  auto o = std::find_if(spare.begin(), spare.end(), [&](std::size_t o) { return !dirty_.count(o) && log_.at[o] == steps; });
  // Or one whose cell differs only in walls that moved to the same abscissa
  // without any of its signs there changing: it is renamed.
  if (o == spare.end()) {
    o = renamable(cell, steps, spare);
    if (o == spare.end()) return false;
    rename_walls(*o, tree_.nodes[cell].cell);
  }
  move_node(*o, cell);
  refresh_cells(cell);
  release(*o);
  spare.erase(o);
  ledger_.kept(cell);
  return true;
}

template <class K>
void Subtree_fit<K>::first_cuts(Fitting& f, const std::vector<std::size_t>& spare) {
  const auto first = std::find_if(f.steps.begin(), f.steps.end(),
                                  [](const Arrival& a) { return a.kind != Arrival::Kind::crossings; });
  if (first == f.steps.end()) return;
  const std::size_t r = scene_.rank[first->segment];
  const auto [from, to] = rank_block(f.steps, scene_.rank, r);
  // A crossing walk that reaches a cell is followed there by its segment's
  // intersection or edge arrivals, in its block: no earlier block can hold
  // only walks. Anything else is a log out of step with the tree.
  if (from != 0) throw Bsp_contradiction("cylindrical BSP: a cell's arrivals precede the block of its first cut");
  // With no old subtree topped by a cut of that segment, none can match:
  // the cell is replayed whole, its first cuts made once.
  if (std::none_of(spare.begin(), spare.end(), [&](std::size_t o) { return cut_rank(tree_.nodes[o], scene_.rank) == r; }))
    return;
  f.rank = r;
  f.to = to;
  builder_.replay(f.cell, std::vector<Arrival>(f.steps.begin(), f.steps.begin() + static_cast<std::ptrdiff_t>(to)));
}

template <class K>
void Subtree_fit<K>::fit(const Fitting& f, std::vector<std::size_t>& left) {
  if (!f.rank) {
    builder_.replay(f.cell, f.steps);
    return;
  }
  // The cell's first cuts are made. With no old subtree of the same top
  // left for it (taken by a cell beside it, or the spare of that rank has
  // another cut of the segment on top), the cells below them are fitted to
  // what is left over here, not replayed: the cuts are the replay's own.
  if (!f.old) {
    fit_cells(cells_below(f.cell, *f.rank, f.steps, f.to), left);
    return;
  }
  // The old subtree's cuts of that rank set aside in turn, and the cells
  // below the new ones fitted to what lay below them.
  std::vector<std::size_t> below = set_aside(*f.old, *f.rank);
  release(*f.old);
  fit_cells(cells_below(f.cell, *f.rank, f.steps, f.to), below);
  for (const std::size_t o : below) discard(o, true);
}

namespace {

// The walk ends in `log` at a wall of `was` that moved, named as in `now`.
void rename_ends(std::vector<Arrival>& log, const Cell& was, const Cell& now) {
  for (Arrival& a : log)
    if (!locates(a))
      for (Site_point* q : {&a.a, &a.b})
        for (const int side : {0, 1})
          if (wall(was, side) != wall(now, side) && *q == *wall(was, side)) {
            *q = *wall(now, side);
            break;
          }
}

}  // namespace

template <class K>
std::vector<std::size_t>::iterator Subtree_fit<K>::renamable(std::size_t cell, const std::vector<Arrival>& steps,
                                                             std::vector<std::size_t>& spare) {
  if (!hooks_.renamed) return spare.end();
  const Cell& now = tree_.nodes[cell].cell;
  return std::find_if(spare.begin(), spare.end(), [&](std::size_t o) {
    const Cell& was = tree_.nodes[o].cell;
    // Both walls there before and now, one or both moved, none to the other's place.
    if (dirty_.count(o) || was.floor != now.floor || was.roof != now.roof || was == now || !was.left ||
        !was.right || !now.left || !now.right || now.left == was.right || now.right == was.left ||
        log_.at[o].size() != steps.size())
      return false;
    std::vector<Arrival> log = log_.at[o];
    rename_ends(log, was, now);
    return log == steps && hooks_.renamed(o, now);
  });
}

template <class K>
void Subtree_fit<K>::rename_walls(std::size_t o, const Cell& now) {
  const Cell was = tree_.nodes[o].cell;
  for (const int side : {0, 1})
    if (wall(was, side) != wall(now, side))
      along_wall(tree_, o, side, *wall(was, side), [&](std::size_t x) { rename_ends(log_.at[x], was, now); });
}

template <class K>
void Subtree_fit<K>::move_node(std::size_t from, std::size_t to) {
  Bsp_node& d = tree_.nodes[to];
  const Bsp_node& f = tree_.nodes[from];
  d.kind = f.kind;
  d.point = f.point;
  d.segment = f.segment;
  d.child[0] = f.child[0];
  d.child[1] = f.child[1];
  if (d.kind != Cut_kind::leaf)
    for (const std::int32_t c : d.child) tree_.nodes[static_cast<std::size_t>(c)].parent = static_cast<std::int32_t>(to);
  log_.at[to] = std::move(log_.at[from]);
  log_.at[from].clear();
  ledger_.moved(from, to);
  hooks_.moved(from, to);
}

template <class K>
void Subtree_fit<K>::release(std::size_t o) {
  tree_.nodes[o] = Bsp_node{};
  log_.free.push_back(o);
}

template <class K>
void Subtree_fit<K>::refresh_cells(std::size_t v) {
  std::vector<std::size_t> stack{v};
  while (!stack.empty()) {
    const Bsp_node& node = tree_.nodes[stack.back()];
    stack.pop_back();
    if (node.kind == Cut_kind::leaf) continue;
    for (const int side : {0, 1}) {
      const Cell c = child_cell(node.cell, node, side);
      Bsp_node& child = tree_.nodes[static_cast<std::size_t>(node.child[side])];
      if (child.cell == c) continue;
      child.cell = c;
      if (hooks_.recelled) hooks_.recelled(static_cast<std::size_t>(node.child[side]));
      stack.push_back(static_cast<std::size_t>(node.child[side]));
    }
  }
}

template <class K>
void Subtree_fit<K>::discard(std::size_t v, bool with_root) {
  for (const std::size_t n : tree_.preorder(v)) {
    ledger_.forgot(n);
    hooks_.forget(n);
    if (n != v || with_root) log_.free.push_back(n);
  }
}

#define KVD_INSTANTIATE_SUBTREE_FIT(K) template class Subtree_fit<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SUBTREE_FIT)

}  // namespace kvd::segments
