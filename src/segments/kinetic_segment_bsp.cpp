#include "kvd/segments/kinetic_segment_bsp.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <stdexcept>
#include <type_traits>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/kinetic/batches_until.hpp"
#include "kvd/detail/kinetic/validator.hpp"
#include "kvd/detail/segments/motion_change.hpp"
#include "kvd/detail/segments/subtree_fit.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

template <class K>
Kinetic_segment_bsp<K>::Kinetic_segment_bsp(const K& k, Segment_scene scene, bool validate, Segment_update update,
                                            const std::optional<Time>& from)
    : k_(k),
      scene_(std::move(scene)),
      validate_(validate),
      update_(update),
      now_(from ? *from : k_.time(from_rational<typename K::FT>(scene_.start))),
      bounded_(scene_.end.has_value()),
      end_(bounded_ ? k_.time(from_rational<typename K::FT>(*scene_.end)) : now_),
      pred_(k_, scene_) {
  pred_.record(recorder());
  // The construction decides most keys again at other nodes (seven signs in
  // ten with 3,200 random segments), at the same instant: a key already
  // recorded has its sign read (rule held) instead of polynomials made that
  // record would drop. Not in an update's rebuild, whose batch counts the
  // signs decided.
  pred_.held([this](const Segment_certificate_key& key) -> std::optional<int> {
    if (const Certificate* c = certs_.find(key)) return c->sign;
    return std::nullopt;
  });
  guarded([this] { rebuild(); });
  pred_.held(nullptr);
}

template <class K>
template <class F>
bool Kinetic_segment_bsp<K>::guarded(F f) {
  if constexpr (std::is_same_v<K, Exact_kernel>) {
    f();
    return false;
  } else {
    try {
      f();
      return false;
    } catch (const Bsp_contradiction&) {
      ++recovery_.failed_builds;
    }
    // At now, then at now + 2^i epsilon from the same base.
    const Time base = now_;
    typename K::FT step = k_.epsilon();
    for (int i = 0; i <= kinetic::recovery_steps; ++i, step = step * typename K::FT(2)) {
      if (i > 0) now_ = base + step;  // step = 2^i epsilon
      try {
        rebuild();
        ++recovery_.rebuilds;
        return true;
      } catch (const Bsp_contradiction&) {
      }
    }
    ++recovery_.unrepaired;
    now_ = base;     // where it got stuck, not the last instant tried
    queue_.clear();  // the run stops here
    return true;
  }
}

template <class K>
void Kinetic_segment_bsp<K>::record(const Segment_certificate_key& key, std::vector<P>&& polys, std::int32_t node,
                                    int sign) {
  auto [at, fresh] = certs_.try_emplace(key);
  Certificate& c = *at;
  if (fresh) {
    c.polys = std::move(polys);
    c.sign = sign;
    schedule(key, c);
    index(key);
  }
  if (std::find(c.nodes.begin(), c.nodes.end(), node) != c.nodes.end()) return;
  c.nodes.push_back(node);
  for (const Site_point& x : {key.p, key.q})
    if (x.kind == Site_point::Kind::crossing) by_crossing_[x].emplace_back(key, node);
  if (node < 0) return;
  if (node_keys_.size() <= static_cast<std::size_t>(node)) node_keys_.resize(static_cast<std::size_t>(node) + 1);
  node_keys_[static_cast<std::size_t>(node)].push_back(key);
}

// The index by segment is made at the first flight-plan change, from the
// certificates in force and in limbo, and kept from then on: a run without
// one does not pay for it at every certificate made. It may hold keys of
// certificates gone since (set_motion skips and drops them); when it holds
// twice as many keys as there are certificates, those in limbo counted (an
// update that forgets a large subtree moves most of them there), it is made
// again from both, so at every insertion its size is within a constant of
// theirs (limbo empties at the end of an update, and the next insertion may
// find it twice over and remake it), at a constant amortized cost per
// certificate made.
template <class K>
void Kinetic_segment_bsp<K>::index(const Segment_certificate_key& key) {
  if (!indexing_) return;
  if (++indexed_ <= 2 * (certs_.size() + limbo_.size()) + 64) return enter(key);
  make_index();
}

template <class K>
void Kinetic_segment_bsp<K>::make_index() {
  by_segment_.assign(scene_.segments.size(), {});
  indexed_ = 0;
  indexing_ = true;
  for (const auto* m : {&certs_, &limbo_})
    m->for_each([&](const Segment_certificate_key& k, const Certificate&) {
      enter(k);
      ++indexed_;
    });
}

template <class K>
void Kinetic_segment_bsp<K>::enter(const Segment_certificate_key& key) {
  for (const std::size_t s : named_segments(key)) by_segment_[s].insert(key);
}

template <class K>
typename Segment_predicates<K>::Recorder Kinetic_segment_bsp<K>::recorder() {
  return [this](const Segment_certificate_key& key, std::vector<P>&& polys, std::int32_t node, int sign) {
    record(key, std::move(polys), node, sign);
  };
}

template <class K>
std::vector<typename Kinetic_segment_bsp<K>::Batch> Kinetic_segment_bsp<K>::advance_to(const Time& t) {
  return kinetic::batches_until(*this, k_, t, now_, bounded_ ? std::optional<Time>(end_) : std::nullopt);
}

template <class K>
void Kinetic_segment_bsp<K>::schedule(const Segment_certificate_key& key, Certificate& c) {
  c.version = ++versions_;
  roots_.bound(certificates());
  const std::optional<Time> first = roots_.fails(k_, c, now_);
  // A failure after the span's end is no event.
  if (first && !(bounded_ && k_.compare(*first, end_) > 0)) queue_.push({*first, key, c.version});
}

template <class K>
bool Kinetic_segment_bsp<K>::stale(const Entry& e) const {
  const Certificate* c = certs_.find(e.key);
  return !c || c->version != e.version;
}

template <class K>
void Kinetic_segment_bsp<K>::rebuild() {
  certs_.clear();
  limbo_.clear();
  node_keys_.clear();
  by_crossing_.clear();
  queue_.clear();
  Bsp_builder<K> builder(pred_, now_, tree_, &log_);
  builder.start();
  for (const std::size_t s : scene_.priority_order) builder.insert(static_cast<std::uint32_t>(s));
}

template <class K>
void Kinetic_segment_bsp<K>::drop(const Segment_certificate_key& key, std::int32_t node) {
  for (const Site_point& x : {key.p, key.q}) {
    const auto l = by_crossing_.find(x);
    if (x.kind != Site_point::Kind::crossing || l == by_crossing_.end()) continue;
    l->second.erase(std::remove(l->second.begin(), l->second.end(), std::pair{key, node}), l->second.end());
    if (l->second.empty()) by_crossing_.erase(l);
  }
  Certificate* c = certs_.find(key);
  if (!c) return;  // a failing certificate, gone already
  auto& nodes = c->nodes;
  const auto at = std::find(nodes.begin(), nodes.end(), node);
  if (at == nodes.end()) return;  // made again since, elsewhere
  nodes.erase(at);
  if (!nodes.empty()) return;
  limbo_[key] = std::move(*certs_.take(key));
}

template <class K>
void Kinetic_segment_bsp<K>::unrecord(const Segment_certificate_key& key, std::int32_t node) {
  drop(key, node);
  if (node < 0) return;
  auto& listed = node_keys_[static_cast<std::size_t>(node)];
  listed.erase(std::remove(listed.begin(), listed.end(), key), listed.end());
}

template <class K>
void Kinetic_segment_bsp<K>::move_keys(std::size_t from, std::size_t to) {
  if (from >= node_keys_.size()) return;
  if (node_keys_.size() <= to) node_keys_.resize(to + 1);
  const auto was = static_cast<std::int32_t>(from), is = static_cast<std::int32_t>(to);
  // A node's list may name a key dropped since through by_crossing_: it
  // is in force no more, or no more at `from`, and nothing names it there.
  for (const Segment_certificate_key& key : node_keys_[from]) {
    if (Certificate* c = certs_.find(key)) std::replace(c->nodes.begin(), c->nodes.end(), was, is);
    for (const Site_point& x : {key.p, key.q})
      if (const auto at = by_crossing_.find(x); at != by_crossing_.end())
        std::replace(at->second.begin(), at->second.end(), std::pair{key, was}, std::pair{key, is});
  }
  node_keys_[to] = std::move(node_keys_[from]);
  node_keys_[from].clear();
}

// The node's certificates lose it; those decided nowhere else go.
template <class K>
void Kinetic_segment_bsp<K>::forget(std::size_t node) {
  if (node >= node_keys_.size()) return;
  for (const auto& key : node_keys_[node]) drop(key, static_cast<std::int32_t>(node));
  node_keys_[node] = std::vector<Segment_certificate_key>();  // released: the slot may come back small
}

template <class K>
bool Kinetic_segment_bsp<K>::replay(const std::vector<Replay_root>& roots, const std::vector<std::int32_t>& failing,
                                    std::size_t& added) {
  // A subtree holding a failing node changes: it is not taken whole.
  std::set<std::size_t> dirty;
  for (const std::int32_t f : failing)
    for (std::int32_t a = f; a >= 0 && dirty.insert(static_cast<std::size_t>(a)).second;)
      a = tree_.nodes[static_cast<std::size_t>(a)].parent;
  std::vector<std::vector<Arrival>> arrivals;
  std::vector<std::vector<std::size_t>> spare;
  Bsp_builder<K> builder(pred_, now_, tree_, &log_);
  Subtree_fit<K> fit(tree_, log_, scene_, builder, dirty,
                     {[this](std::size_t n) { forget(n); }, [this](std::size_t f, std::size_t t) { move_keys(f, t); }, {}, {}});
  for (const Replay_root& root : roots) {
    const std::size_t v = root.node;
    if constexpr (!std::is_same_v<K, Exact_kernel>) fit.ledger().read(v);
    else if (validate_) fit.ledger().audit(v);
    arrivals.push_back(log_.at[v]);
    if (root.rank) spare.push_back(fit.set_aside(v, *root.rank, root.several));
    else {  // replayed whole
      spare.emplace_back();
      fit.discard(v, false);
    }
  }
  bool changed = false;
  for (std::size_t k = 0; k < roots.size(); ++k) {
    const std::size_t v = roots[k].node;
    if (roots[k].rank) fit.remake(v, *roots[k].rank, arrivals[k], std::move(spare[k]));
    else builder.replay(v, arrivals[k]);
    changed = fit.ledger().changed(v) || changed;
  }
  added += builder.added();
  // A crossing cut below a root before and nowhere now (both of a crossing's
  // cuts lie below the node where it is found, and one found above a root is
  // kept; a crossing may move from one root's subtree to another's): its
  // certificates above the roots go.
  std::vector<std::size_t> nodes;
  for (const Replay_root& root : roots) nodes.push_back(root.node);
  const std::vector<Site_point> gone = fit.ledger().gone(nodes, log_, scene_.rank);
  for (const Site_point& x : gone) {
    const auto it = by_crossing_.find(x);
    if (it == by_crossing_.end()) continue;
    for (const auto& [key, node] : std::vector(it->second)) drop(key, node);
  }
  // And its location, logged above the roots, too (each ancestor once),
  // and above the cells taken whole.
  // (tops: nodes made above cells taken whole, whose logs may name a crossing gone)
  std::set<std::size_t> above(fit.tops().begin(), fit.tops().end());
  for (const Replay_root& root : roots) {
    if (gone.empty()) break;
    std::int32_t a = tree_.nodes[root.node].parent;
    while (a >= 0 && above.insert(static_cast<std::size_t>(a)).second) a = tree_.nodes[static_cast<std::size_t>(a)].parent;
  }
  unlog_crossings(log_, above, gone);
  return changed;
}

template <class K>
std::optional<typename K::Time> Kinetic_segment_bsp<K>::next_event_time() {
  return queue_.next([this](const Entry& e) { return stale(e); });
}

template <class K>
typename Kinetic_segment_bsp<K>::Batch Kinetic_segment_bsp<K>::advance() {
  if (validate_ && validate(*next_event_time()) && !next_event_time()) {
    // A floating-point run adopted a fresh build, after which nothing fails.
    Batch adopted{now_, {}, {}, true, certs_.size(), 0, tree_.counts().nodes};
    return adopted;
  }
  const Time t = *next_event_time();
  Batch b{t, {}, {}, false, 0, 0, 0};
  while (!queue_.empty() && (stale(queue_.top()) || k_.compare(queue_.top().time, t) == 0)) {
    if (!stale(queue_.top())) b.failing.push_back(queue_.top().key);
    queue_.pop();
  }
  // In key order, not the heap's, so that the update does not depend on
  // when the heap was last swept.
  std::sort(b.failing.begin(), b.failing.end());
  b.failing.erase(std::unique(b.failing.begin(), b.failing.end()), b.failing.end());
  std::vector<Failing> failing;
  for (const auto& key : b.failing) failing.emplace_back(key, certs_.at(key).nodes);
  const std::vector<std::size_t> turning = turning_segments(b.failing);
  for (const auto& key : b.failing) ++b.events[static_cast<std::size_t>(event_in_batch(key, scene_.rank, turning))];
  const auto start = std::chrono::steady_clock::now();
  const Segment_rule_counts signs = pred_.counts();
  now_ = t;
  // The failing certificates go first: those decided again get a new failure time.
  for (const auto& key : b.failing) certs_.erase(key);
  b.changed = guarded([&] { b.changed = update(failing, b); }) || b.changed;
  next_event_time();  // up to the next queue minimum: stale entries off the heap
  queue_.trim([this](const Entry& e) { return stale(e); });
  b.update_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  b.signs = pred_.counts().decided() - signs.decided();
  b.held = pred_.counts().held - signs.held;
  b.repeated = pred_.counts().repeated - signs.repeated;
  b.certificates = certs_.size();
  return b;
}

template <class K>
bool Kinetic_segment_bsp<K>::validate(const Time& t) {
  const Segment_predicates<K> oracle(k_, scene_);
  const Time mid = kinetic::between(k_, now_, t);
  ++validations_;
  const std::string where = "the tree in force before t = " + k_.to_string(t);
  try {
    if (build_cylindrical_bsp(oracle, mid).text() == tree_.text()) return false;
    failures_.push_back(where + " differs from a fresh build at t = " + k_.to_string(mid));
  } catch (const Bsp_contradiction& e) {
    if constexpr (std::is_same_v<K, Exact_kernel>) throw;
    failures_.push_back(where + ": the fresh build at t = " + k_.to_string(mid) + " contradicts itself (" + e.what() +
                        ")");
    return false;
  }
  if constexpr (std::is_same_v<K, Exact_kernel>) {
    return false;  // a bug, reported; nothing to repair
  } else {
    // An event was missed: the run adopts the fresh build and its instant.
    ++recovery_.stale_trees;
    now_ = mid;
    guarded([this] { rebuild(); });
    ++recovery_.rebuilds;
    return true;
  }
}

template <class K>
bool Kinetic_segment_bsp<K>::update(const std::vector<Failing>& failing, Batch& b) {
  if (update_ == Segment_update::rebuild) {
    const std::string before = tree_.text();
    rebuild();
    b.nodes_rebuilt += tree_.counts().nodes;
    return tree_.text() != before;
  }
  // The signs of the certificates in force hold (they fail later), and are
  // read rather than computed again, whether their nodes stay or are made
  // again; the failing ones are gone (advance, set_motion), and so are their
  // entries at the nodes that decided them, since the frontier replay keeps
  // some of those nodes and decides the keys there again.
  pred_.held([this](const Segment_certificate_key& key) -> std::optional<int> {
    if (const Certificate* c = certs_.find(key)) return c->sign;
    std::optional<Certificate> c = limbo_.take(key);
    if (!c) return std::nullopt;
    const int sign = c->sign;
    certs_[key] = std::move(*c);
    return sign;
  });
  struct Done {
    Kinetic_segment_bsp& run;
    ~Done() {
      run.pred_.held(nullptr);
      run.limbo_.clear();
    }
  } done{*this};
  for (const auto& [key, at] : failing)
    for (const std::int32_t n : at) unrecord(key, n);
  // The topmost of the nodes: a node below another is replayed with it. A
  // sign decided at no node (a flip certificate) has nothing to replay: what
  // a flip changes, other signs decided in the segment's cells tell.
  std::vector<std::int32_t> nodes;
  for (const auto& f : failing) nodes.insert(nodes.end(), f.second.begin(), f.second.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  nodes.erase(std::remove(nodes.begin(), nodes.end(), -1), nodes.end());
  const std::map<std::size_t, std::size_t> flips =
      update_ == Segment_update::local ? flip_frontiers(failing, nodes) : std::map<std::size_t, std::size_t>{};
  std::vector<Replay_root> roots;
  for (const std::int32_t n : nodes) {
    const auto u = static_cast<std::size_t>(n);
    if (below_any(tree_, u, [&](std::size_t a) {
          return std::binary_search(nodes.begin(), nodes.end(), static_cast<std::int32_t>(a));
        }))
      continue;
    std::optional<std::vector<Replay_root>> frontier;
    if (update_ == Segment_update::local) frontier = frontier_replay(u, failing, nodes);
    if (const auto r = flips.find(u); !frontier && r != flips.end()) frontier = std::vector<Replay_root>{{u, r->second}};
    ++(frontier ? b.frontier_replays : b.subtree_replays);
    if (frontier) roots.insert(roots.end(), frontier->begin(), frontier->end());
    else roots.push_back({u, std::nullopt});
  }
  const bool changed = replay(roots, nodes, b.nodes_rebuilt);
  // The signs decided at no node, gone with the failure, decided again.
  pred_.at_node(-1);
  for (const auto& [key, at] : failing)
    if (std::find(at.begin(), at.end(), -1) != at.end()) pred_.compare_x(key.p, key.q, now_);
  return changed;
}

template <class K>
bool Kinetic_segment_bsp<K>::set_motion(std::size_t segment, const Segment_motion& motion) {
  check_motion_change(k_, scene_, segment, motion, now_, bounded_ ? std::optional<Time>(end_) : std::nullopt);
  scene_.segments[segment].motion = motion;
  pred_.refresh(segment, now_);
  // The certificates naming the segment, found through the index (Lemma 3.1:
  // their number, not that of all certificates; keys gone since are dropped),
  // decided again: the same sign makes new polynomials and a new failure
  // time; another sign is a change now.
  std::vector<Segment_certificate_key> named;
  if (!indexing_) make_index();
  auto& indexed = by_segment_[segment];
  for (auto it = indexed.begin(); it != indexed.end();)
    if (certs_.find(*it)) named.push_back(*it++);
    else it = indexed.erase(it);
  std::sort(named.begin(), named.end());  // the index's order is its hash's
  std::vector<Failing> failing;
  for (const auto& key : named) {
    Certificate& c = certs_.at(key);
    std::vector<P> polys;
    int sign = 0;
    pred_.record([&](const Segment_certificate_key&, std::vector<P>&& q, std::int32_t, int s) {
      polys = std::move(q);
      sign = s;
    });
    pred_.sign_of(key, now_);
    if (sign != c.sign) {
      failing.emplace_back(key, c.nodes);
      certs_.erase(key);
      continue;
    }
    c.polys = std::move(polys);
    schedule(key, c);
  }
  pred_.record(recorder());
  Batch b{now_, {}, {}, false, 0, 0, 0};
  bool tree_changed = false;
  if (!failing.empty())
    tree_changed = guarded([&] { tree_changed = update(failing, b); }) || tree_changed;
  return tree_changed;
}

template <class K>
std::vector<std::pair<Segment_certificate_key, std::vector<std::int32_t>>> Kinetic_segment_bsp<K>::certificate_list()
    const {
  // Nodes renumbered as tree() numbers them: in pre-order.
  const std::vector<std::size_t> order = tree_.preorder();
  std::vector<std::int32_t> id(tree_.nodes.size(), -1);
  for (std::size_t i = 0; i < order.size(); ++i) id[order[i]] = static_cast<std::int32_t>(i);
  std::vector<std::pair<Segment_certificate_key, std::vector<std::int32_t>>> list;
  certs_.for_each([&](const Segment_certificate_key& key, const Certificate& c) {
    std::vector<std::int32_t> nodes;
    for (const std::int32_t n : c.nodes) nodes.push_back(n < 0 ? -1 : id[static_cast<std::size_t>(n)]);
    std::sort(nodes.begin(), nodes.end());
    list.emplace_back(key, std::move(nodes));
  });
  std::sort(list.begin(), list.end());
  return list;
}

template <class K>
std::vector<std::vector<Arrival>> Kinetic_segment_bsp<K>::arrivals() const {
  std::vector<std::vector<Arrival>> out;
  for (const std::size_t n : tree_.preorder()) out.push_back(log_.at[n]);
  return out;
}

#define KVD_INSTANTIATE_KINETIC_SEGMENT_BSP(K) template class Kinetic_segment_bsp<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_KINETIC_SEGMENT_BSP)

}  // namespace kvd::segments
