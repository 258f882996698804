// The kinetic segment BSP on the paper's certificates alone
// (kvd/segments/aeg_kinetic_bsp.hpp).
#include "kvd/segments/aeg_kinetic_bsp.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <set>
#include <tuple>

#include "kvd/detail/kinetic/batches_until.hpp"
#include "kvd/detail/kinetic/validator.hpp"
#include "kvd/detail/segments/motion_change.hpp"
#include "kvd/detail/segments/subtree_fit.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/aeg_certificates.hpp"
#include "kvd/segments/augmented_bsp.hpp"

namespace kvd::segments {

namespace {

// The predicates' recorder for a scope, taken off again however it ends
// (the recorder refers to the scope's locals).
template <class K>
struct Recording {
  const Segment_predicates<K>& pred;
  Recording(const Segment_predicates<K>& p, typename Segment_predicates<K>::Recorder r, bool polynomials = true)
      : pred(p) {
    pred.record(std::move(r), polynomials);
  }
  ~Recording() { pred.record({}); }
  Recording(const Recording&) = delete;
  Recording& operator=(const Recording&) = delete;
};

// While alive, the predicates remember the signs of instant t (which must
// keep its value meanwhile).
template <class K>
struct Remembering {
  const Segment_predicates<K>& pred;
  Remembering(const Segment_predicates<K>& p, const typename K::Time& t) : pred(p) { pred.remember(t); }
  ~Remembering() { pred.forget(); }
  Remembering(const Remembering&) = delete;
  Remembering& operator=(const Remembering&) = delete;
};

// Failures in the order Batch::failing keeps.
bool before(const Aeg_certificate_id& a, const Aeg_certificate_id& b) {
  return std::tie(a.kind, a.index, a.cell.left, a.cell.right, a.cell.floor, a.cell.roof) <
         std::tie(b.kind, b.index, b.cell.left, b.cell.right, b.cell.floor, b.cell.roof);
}

}  // namespace

std::string aeg_certificate_subject(const Aeg_certificate_id& id) {
  switch (id.kind) {
    case Aeg_certificate_kind::endpoint: return point_name(Site_point::endpoint(id.index));
    case Aeg_certificate_kind::flip: return "s" + std::to_string(id.index);
    case Aeg_certificate_kind::transient: break;
  }
  const Cell& c = id.cell;
  std::string t;
  const auto part = [&](const std::string& p) { t += (t.empty() ? "" : ", ") + p; };
  if (c.left && c.right) part("between " + point_name(*c.left) + " and " + point_name(*c.right));
  else if (c.left) part("right of " + point_name(*c.left));
  else if (c.right) part("left of " + point_name(*c.right));
  if (c.floor) part("above s" + std::to_string(*c.floor));
  if (c.roof) part("below s" + std::to_string(*c.roof));
  return t;
}

template <class K>
Aeg_kinetic_bsp<K>::Aeg_kinetic_bsp(const K& k, Segment_scene scene, bool validate)
    : k_(k),
      scene_(std::move(scene)),
      validate_(validate),
      now_(k_.time(from_rational<typename K::FT>(scene_.start))),
      bounded_(scene_.end.has_value()),
      end_(bounded_ ? k_.time(from_rational<typename K::FT>(*scene_.end)) : now_),
      pred_(k_, scene_) {
  rebuild();
}

template <class K>
std::vector<std::pair<Aeg_certificate_id, std::optional<typename K::Time>>> Aeg_kinetic_bsp<K>::certificate_list()
    const {
  std::vector<std::pair<Aeg_certificate_id, std::optional<Time>>> list;
  for (const auto& [v, c] : transient_) list.emplace_back(c.id, c.fails);
  for (const auto* certs : {&endpoint_, &flip_})
    for (const Certificate& c : *certs) list.emplace_back(c.id, c.fails);
  std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return before(a.first, b.first); });
  return list;
}

template <class K>
void Aeg_kinetic_bsp<K>::rebuild() {
  Bsp_builder<K> builder(pred_, now_, tree_, &log_);
  builder.start();
  for (const std::size_t s : scene_.priority_order) builder.insert(static_cast<std::uint32_t>(s));
  transient_.clear();
  queue_.clear();
  by_segment_.clear();
  indexed_ = 0;
  const std::size_t n = pred_.size();
  endpoint_.assign(2 * n, {});
  flip_.assign(n, {});
  leaf_.assign(2 * n, 0);
  beside_.clear();
  points_.clear();
  certify_below(0, {});
  for (std::size_t e = 0; e < 2 * n; ++e) make_endpoint(e);
  for (std::size_t s = 0; s < n; ++s) make_flip(s);
}

template <class K>
void Aeg_kinetic_bsp<K>::ask(const Certificate& c, std::size_t index) {
  counting(phases_.certificates, [&] {
    switch (c.id.kind) {
      case Aeg_certificate_kind::transient: {
        const Cell& w = c.id.cell;
        if (w.left && w.right) pred_.compare_x(*w.left, *w.right, now_);
        if (w.floor && w.roof)
          for (const auto& wall : {w.left, w.right})
            if (wall) pred_.order_at(*wall, *w.roof, *w.floor, now_);
        return;
      }
      case Aeg_certificate_kind::endpoint: {
        const Site_point p = Site_point::endpoint(index);
        for (const auto& s : {c.near.floor, c.near.roof}) {
          if (!s) continue;
          pred_.side(p, *s, now_);
          pred_.compare_x(p, Site_point::endpoint(2 * *s), now_);
          pred_.compare_x(p, Site_point::endpoint(2 * *s + 1), now_);
        }
        return;
      }
      case Aeg_certificate_kind::flip:
        pred_.compare_x(Site_point::endpoint(2 * index + 1), Site_point::endpoint(2 * index), now_);
        return;
    }
  });
}

template <class K>
typename Aeg_kinetic_bsp<K>::Decided Aeg_kinetic_bsp<K>::signs(const Certificate& c, std::size_t index) {
  Decided out;
  // Signs only: the filter may decide them.
  const Recording recording(
      pred_, [&](const Segment_certificate_key& key, std::vector<P>&&, std::int32_t, int sign) { out.emplace_back(key, sign); },
      false);
  ask(c, index);
  return out;
}

template <class K>
void Aeg_kinetic_bsp<K>::make(Certificate& c, std::size_t index) {
  // Every sign decided by arithmetic hands over its polynomials (identities
  // have none: they never change).
  polys_.clear();
  c.decided.clear();
  {
    const Recording recording(pred_, [&](const Segment_certificate_key& key, std::vector<P>&& polys, std::int32_t, int sign) {
      for (P& q : polys) polys_.push_back(std::move(q));
      c.decided.emplace_back(key, sign);
    });
    ask(c, index);
  }
  ++made_;
  c.version = ++versions_;
  roots_.bound(certificates());
  c.fails = roots_.first_root(k_, polys_, now_);
  // A failure after the span's end is no event.
  if (c.fails && bounded_ && k_.compare(*c.fails, end_) > 0) c.fails.reset();
  if (c.fails) queue_.push({*c.fails, c.id.kind, index, c.version});
  this->index(c, index);
}

namespace {

// The segments a point lies on (an endpoint's, or the two of a crossing).
template <class Out>
void segments_of(const Site_point& p, Out add) {
  if (p.kind == Site_point::Kind::endpoint) return add(p.a / 2);
  add(p.a);
  add(p.b);
}

}  // namespace

template <class K>
void Aeg_kinetic_bsp<K>::index(const Certificate& c, std::size_t index) {
  if (by_segment_.empty()) return;  // not made yet: naming makes it
  enter(c, index);
  // At most six entries a certificate (a transient cell's two crossings,
  // floor and roof): twelve is twice that.
  if (indexed_ > 12 * certificates() + 64) reindex();
}

template <class K>
void Aeg_kinetic_bsp<K>::reindex() {
  by_segment_.assign(pred_.size(), {});
  indexed_ = 0;
  for (auto& [v, t] : transient_) enter(t, v);
  for (std::size_t e = 0; e < endpoint_.size(); ++e)
    if (endpoint_[e].version > 0) enter(endpoint_[e], e);
  for (std::size_t s = 0; s < flip_.size(); ++s)
    if (flip_[s].version > 0) enter(flip_[s], s);
}

template <class K>
void Aeg_kinetic_bsp<K>::enter(const Certificate& c, std::size_t index) {
  const Held h{c.id.kind, index};
  named_by(c, index, [&](std::size_t s) {
    by_segment_[s].push_back(h);
    ++indexed_;
  });
}

template <class K>
template <class F>
void Aeg_kinetic_bsp<K>::named_by(const Certificate& c, std::size_t index, F add) const {
  switch (c.id.kind) {
    case Aeg_certificate_kind::transient: {
      const Cell& w = c.id.cell;
      for (const auto& p : {w.left, w.right})
        if (p) segments_of(*p, add);
      for (const auto& s : {w.floor, w.roof})
        if (s) add(*s);
      break;
    }
    case Aeg_certificate_kind::endpoint:
      add(index / 2);
      for (const auto& s : {c.near.floor, c.near.roof})
        if (s) add(*s);
      break;
    case Aeg_certificate_kind::flip: add(index); break;
  }
}

template <class K>
typename Aeg_kinetic_bsp<K>::Certificate& Aeg_kinetic_bsp<K>::held(const Held& h) {
  switch (h.kind) {
    case Aeg_certificate_kind::transient: return transient_.at(h.index);
    case Aeg_certificate_kind::endpoint: return endpoint_[h.index];
    case Aeg_certificate_kind::flip: break;
  }
  return flip_[h.index];
}

template <class K>
std::vector<typename Aeg_kinetic_bsp<K>::Held> Aeg_kinetic_bsp<K>::naming(std::size_t s) {
  if (by_segment_.empty()) reindex();
  // An entry stays while a certificate in force at its place names s: a
  // node slot's may be another cell's since, and an endpoint's another
  // leaf's.
  const auto names = [&](const Held& h) {
    if (h.kind == Aeg_certificate_kind::transient && !transient_.count(h.index)) return false;
    const Certificate& c = held(h);
    if (c.version == 0) return false;
    bool found = false;
    named_by(c, h.index, [&](std::size_t t) { found = found || t == s; });
    return found;
  };
  std::vector<Held>& entries = by_segment_[s];
  std::erase_if(entries, [&](const Held& h) { return !names(h); });
  std::vector<Held> out = entries;
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

template <class K>
void Aeg_kinetic_bsp<K>::make_transient(std::size_t v) {
  const Cell c = tree_.nodes[v].cell;
  Certificate& cert = transient_[v];
  if (const auto it = spare_.find(c); it != spare_.end()) {
    cert = it->second;
    spare_.erase(it);
    cert.version = ++versions_;
    if (cert.fails) queue_.push({*cert.fails, Aeg_certificate_kind::transient, v, cert.version});
    index(cert, v);
    return;
  }
  cert.id = {Aeg_certificate_kind::transient, 0, c};
  make(cert, v);
}

template <class K>
void Aeg_kinetic_bsp<K>::make_endpoint(std::size_t e, std::size_t from, bool near) {
  // The leaf beside p: its floor and roof are p's neighbours.
  const std::size_t v = counting(phases_.leaves, [&] {
    // With `near`, from `from` or the first node above it whose cell holds
    // the endpoint inside now (an endpoint on the cell's wall lies inside
    // the cell of that wall's cut, a few nodes up, unless it meets a cut).
    std::size_t start = from;
    if (near)
      while (start != 0 && !inside(Site_point::endpoint(e), start))
        start = static_cast<std::size_t>(tree_.nodes[start].parent);
    return aeg_leaf(tree_, pred_, now_, e, start);
  });
  leaf_[e] = v;
  beside_[v].push_back(e);
  const Cell& c = tree_.nodes[v].cell;
  Certificate& cert = endpoint_[e];
  if (cert.version > 0 && !failing_endpoints_.count(e) && cert.near.floor == c.floor && cert.near.roof == c.roof)
    return;
  cert.id = {Aeg_certificate_kind::endpoint, e, {}};
  cert.near = c;
  make(cert, e);
}

template <class K>
void Aeg_kinetic_bsp<K>::detach(std::size_t e) {
  std::vector<std::size_t>& near = beside_[leaf_[e]];
  near.erase(std::remove(near.begin(), near.end(), e), near.end());
}

template <class K>
void Aeg_kinetic_bsp<K>::remake_beside(std::size_t n, std::size_t from, bool near) {
  const auto it = beside_.find(n);
  if (it == beside_.end()) return;
  std::vector<std::size_t> endpoints = std::move(it->second);
  beside_.erase(it);
  std::sort(endpoints.begin(), endpoints.end());
  for (const std::size_t e : endpoints) make_endpoint(e, from, near);
}

template <class K>
bool Aeg_kinetic_bsp<K>::inside(const Site_point& p, std::size_t n) const {
  const Cell& c = tree_.nodes[n].cell;
  const auto is = [](const Segment_sign& s, int side) { return s.rule == Segment_rule::value && s.sign == side; };
  return (!c.left || is(pred_.compare_x(p, *c.left, now_), 1)) && (!c.right || is(pred_.compare_x(p, *c.right, now_), -1)) &&
         (!c.floor || is(pred_.side(p, *c.floor, now_), 1)) && (!c.roof || is(pred_.side(p, *c.roof, now_), -1));
}

template <class K>
void Aeg_kinetic_bsp<K>::make_flip(std::size_t s) {
  Certificate& cert = flip_[s];
  cert.id = {Aeg_certificate_kind::flip, s, {}};
  make(cert, s);
}

template <class K>
bool Aeg_kinetic_bsp<K>::certify_below(std::size_t v, const Kept& kept, bool inside) {
  if (points_.size() < tree_.nodes.size()) points_.resize(tree_.nodes.size());
  const bool top = kept.tops.count(v) > 0;
  if (inside && !top && !kept.recelled.count(v)) return points_[v];
  const Bsp_node& n = tree_.nodes[v];
  bool points = point_cut(n);
  if (n.kind != Cut_kind::leaf)
    for (const std::int32_t c : n.child) points = certify_below(static_cast<std::size_t>(c), kept, inside || top) || points;
  points_[v] = points;
  // A node kept by an update keeps its certificate while its cell stays.
  const auto it = transient_.find(v);
  if (points || n.parent < 0 || !point_cut(tree_.nodes[static_cast<std::size_t>(n.parent)])) {
    if (it != transient_.end()) transient_.erase(it);
  } else if (it == transient_.end() || !(it->second.id.cell == n.cell)) {
    make_transient(v);
  }
  return points;
}

template <class K>
std::optional<std::string> Aeg_kinetic_bsp<K>::certified_afresh() const {
  std::optional<std::string> wrong;
  std::size_t transient = 0;
  const auto check = [&](const auto& self, std::size_t v) -> bool {
    const Bsp_node& n = tree_.nodes[v];
    bool points = point_cut(n);
    if (n.kind != Cut_kind::leaf)
      for (const std::int32_t c : n.child) points = self(self, static_cast<std::size_t>(c)) || points;
    const bool is = !points && n.parent >= 0 && point_cut(tree_.nodes[static_cast<std::size_t>(n.parent)]);
    const auto it = transient_.find(v);
    if (is) ++transient;
    if (wrong) return points;
    if (v >= points_.size() || static_cast<bool>(points_[v]) != points)
      wrong = "node " + std::to_string(v) + " (" + cut_name(n) + ") is kept as " +
              (points ? "holding no point cut below it" : "holding a point cut below it");
    else if (is != (it != transient_.end()) || (is && !(it->second.id.cell == n.cell)))
      wrong = "node " + std::to_string(v) + " (" + cut_name(n) + ") has " +
              (is ? "no transient certificate of its cell" : "a transient certificate, not being transient");
    return points;
  };
  check(check, 0);
  if (!wrong && transient != transient_.size())
    wrong = std::to_string(transient_.size()) + " transient certificates are in force for " + std::to_string(transient) +
            " transient nodes";
  return wrong;
}

template <class K>
std::size_t Aeg_kinetic_bsp<K>::subjects(const Entry& e, std::vector<Site_point>& points,
                                         std::vector<std::size_t>& segments) const {
  switch (e.kind) {
    case Aeg_certificate_kind::transient: {
      const Cell& c = transient_.at(e.index).id.cell;
      for (const auto& w : {c.left, c.right})
        if (w) points.push_back(*w);
      for (const auto& s : {c.floor, c.roof})
        if (s) segments.push_back(*s);
      return e.index;
    }
    case Aeg_certificate_kind::endpoint: {
      points.push_back(Site_point::endpoint(e.index));
      if (!collinear(e.index).empty()) segments.push_back(e.index / 2);
      const Cell& c = tree_.nodes[leaf_[e.index]].cell;
      for (const auto& s : {c.floor, c.roof})
        if (s) {
          segments.push_back(*s);
          points.push_back(Site_point::endpoint(2 * *s));
          points.push_back(Site_point::endpoint(2 * *s + 1));
        }
      return leaf_[e.index];
    }
    case Aeg_certificate_kind::flip: segments.push_back(e.index); break;
  }
  return 0;
}

template <class K>
std::vector<std::size_t> Aeg_kinetic_bsp<K>::collinear(std::size_t e) const {
  const Cell& c = tree_.nodes[leaf_[e]].cell;
  const auto on = [&](std::size_t p, std::uint32_t s) {
    return pred_.side(Site_point::endpoint(p), s, now_).rule != Segment_rule::value;
  };
  std::vector<std::size_t> out;
  for (const auto& s : {c.floor, c.roof})
    if (s && on(e, *s) && on(e ^ 1U, *s)) out.push_back(*s);
  return out;
}

template <class K>
std::vector<std::size_t> Aeg_kinetic_bsp<K>::passing(std::size_t e) const {
  const std::vector<std::size_t>& rank = scene_.rank;
  std::vector<std::size_t> on = collinear(e);
  on.push_back(e / 2);
  std::size_t first = rank.size();
  for (const std::size_t s : on) first = std::min(first, rank[s]);
  // Down the nodes whose log holds a step of one of them (every segment's
  // first step is at the root).
  std::vector<std::size_t> out, stack{0};
  std::vector<std::pair<std::size_t, std::size_t>> blocks;  // their steps in the node's log
  std::vector<Segment_certificate_key> keys;
  while (!stack.empty()) {
    const std::size_t v = stack.back();
    stack.pop_back();
    const std::vector<Arrival>& log = log_.at[v];
    blocks.clear();
    for (const std::size_t s : on)
      if (const auto block = rank_block(log, rank, rank[s]); block.first != block.second) blocks.push_back(block);
    if (blocks.empty()) continue;
    const Bsp_node& n = tree_.nodes[v];
    if (cut_rank(n, rank) >= first) {
      out.push_back(v);
      continue;
    }
    keys.clear();
    for (const auto& [from, to] : blocks)
      for (std::size_t i = from; i < to; ++i) decided_keys(n, log[i], keys);
    if (std::any_of(keys.begin(), keys.end(), [&](const Segment_certificate_key& k) { return vanishes(k); })) return {0};
    for (const std::int32_t ch : n.child) stack.push_back(static_cast<std::size_t>(ch));
  }
  return out;
}

template <class K>
std::vector<std::size_t> Aeg_kinetic_bsp<K>::roots(const Entry& e) const {
  if (e.kind == Aeg_certificate_kind::endpoint && !collinear(e.index).empty()) return passing(e.index);
  if (e.kind == Aeg_certificate_kind::flip) {
    // A replay of the segment's first cuts remakes what lies below them.
    std::vector<std::size_t> out = tops(e.index);
    for (std::size_t& r : out) r = above_ties(r, Site_point::endpoint(2 * e.index));
    return out;
  }
  // The cuts the certificate is about, and the node its path starts from.
  std::vector<Site_point> points;
  std::vector<std::size_t> segments;
  const std::size_t from = subjects(e, points, segments);
  std::size_t top = from;
  for (std::int32_t a = tree_.nodes[from].parent; a >= 0; a = tree_.nodes[static_cast<std::size_t>(a)].parent) {
    const Bsp_node& n = tree_.nodes[static_cast<std::size_t>(a)];
    if (n.kind == Cut_kind::edge ? std::count(segments.begin(), segments.end(), n.segment) > 0
                                 : std::count(points.begin(), points.end(), n.point) > 0)
      top = static_cast<std::size_t>(a);
  }
  // The event happens where the certificate's first point is (an endpoint;
  // a transient cell's walls, which meet there or at which floor and roof
  // meet).
  return {above_ties(top, points.front())};
}

template <class K>
std::set<std::size_t> Aeg_kinetic_bsp<K>::changing(const std::vector<Entry>& entries,
                                                   const std::vector<std::size_t>& roots,
                                                   std::vector<std::size_t> at) const {
  std::vector<Site_point> points;
  std::vector<std::size_t> segments, turning;
  for (const Entry& e : entries) {
    const std::size_t from = subjects(e, points, segments);
    if (e.kind == Aeg_certificate_kind::flip) turning.push_back(e.index);
    else at.push_back(from);
  }
  std::sort(points.begin(), points.end());
  std::sort(segments.begin(), segments.end());
  const auto named = [&](const Bsp_node& n) {
    if (n.kind == Cut_kind::edge) return std::binary_search(segments.begin(), segments.end(), n.segment);
    if (std::binary_search(points.begin(), points.end(), n.point)) return true;
    return std::any_of(turning.begin(), turning.end(), [&](std::size_t s) { return n.point.on(s); });
  };
  // A cut lies only where the steps of the segment that made it arrived, and
  // every node on the way logged them: without a flip (whose segment's
  // points are cut by other segments' steps too), the search goes down only
  // where those segments' blocks are.
  std::vector<std::size_t> ranks;
  for (const std::size_t j : segments) ranks.push_back(scene_.rank[j]);
  for (const Site_point& p : points) ranks.push_back(point_rank(p, scene_.rank));
  std::sort(ranks.begin(), ranks.end());
  ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
  const auto reached = [&](std::size_t n) {
    if (!turning.empty()) return true;
    return std::any_of(ranks.begin(), ranks.end(), [&](std::size_t r) {
      const auto [from, to] = rank_block(log_.at[n], scene_.rank, r);
      return from != to;
    });
  };
  for (const std::size_t v : roots) {
    std::vector<std::size_t> stack{v};
    while (!stack.empty()) {
      const std::size_t n = stack.back();
      stack.pop_back();
      const Bsp_node& q = tree_.nodes[n];
      if (q.kind == Cut_kind::leaf) continue;
      if (named(q)) at.push_back(n);
      for (const std::int32_t c : q.child)
        if (reached(static_cast<std::size_t>(c))) stack.push_back(static_cast<std::size_t>(c));
    }
  }
  std::set<std::size_t> out;
  for (const std::size_t n : at)
    for (auto a = static_cast<std::int32_t>(n); a >= 0 && out.insert(static_cast<std::size_t>(a)).second;)
      a = tree_.nodes[static_cast<std::size_t>(a)].parent;
  return out;
}

template <class K>
std::vector<std::size_t> Aeg_kinetic_bsp<K>::tops(std::size_t s) const {
  const std::size_t r = scene_.rank[s];
  std::vector<std::size_t> out, stack{0};
  while (!stack.empty()) {
    const std::size_t v = stack.back();
    stack.pop_back();
    const Bsp_node& n = tree_.nodes[v];
    if (cut_rank(n, scene_.rank) == r) {
      out.push_back(v);
      continue;
    }
    if (n.kind == Cut_kind::leaf) continue;
    for (const std::int32_t c : n.child) {
      const auto [from, to] = rank_block(log_.at[static_cast<std::size_t>(c)], scene_.rank, r);
      if (from != to) stack.push_back(static_cast<std::size_t>(c));
    }
  }
  return out;
}

template <class K>
std::size_t Aeg_kinetic_bsp<K>::first_cut(std::size_t v) const {
  const std::size_t own = cut_rank(tree_.nodes[v], scene_.rank);
  for (std::int32_t a = tree_.nodes[v].parent;
       a >= 0 && cut_rank(tree_.nodes[static_cast<std::size_t>(a)], scene_.rank) == own;)
    v = static_cast<std::size_t>(a), a = tree_.nodes[v].parent;
  return v;
}

template <class K>
std::vector<std::size_t> Aeg_kinetic_bsp<K>::remade_roots(const std::vector<Entry>& entries,
                                                          std::vector<std::size_t>& searched) const {
  // Their ties are read at the batch's instant (signs that vanish there cost
  // most: they are why a flip done in place does not read them). Each is
  // made again from its segment's first cut above it; the cuts of that
  // segment's other subtrees there change no sign, so only the named
  // subtree is searched.
  std::set<std::size_t> named;
  for (const Entry& e : entries)
    for (const std::size_t r : roots(e)) named.insert(r);
  searched = outermost(named);
  std::set<std::size_t> raised;
  for (const std::size_t r : searched) raised.insert(first_cut(r));
  return outermost(raised);
}

template <class K>
std::vector<Replay_root> Aeg_kinetic_bsp<K>::reroute_apart(const std::vector<Entry>& entries,
                                                           std::vector<std::size_t>& asked,
                                                           std::vector<std::size_t>& searched,
                                                           std::vector<std::size_t>& remade) {
  // Which pass the guards alone, each with the nodes it would change below
  // (checked only: the check stops them).
  std::vector<std::pair<Entry, std::vector<std::size_t>>> alone;
  std::vector<Entry> rest;
  std::vector<std::size_t> unused;
  for (const Entry& e : entries) {
    std::optional<std::vector<std::size_t>> region;
    reroutes({e}, unused, [&](const std::vector<std::size_t>& nodes, bool nested) {
      if (!nested) region = nodes;
      return false;
    });
    if (region) alone.emplace_back(e, std::move(*region));
    else rest.push_back(e);
  }
  // What a reroute changes lies below its tops and frontier nodes, and
  // what the others change inside their subtrees: apart, neither sees the
  // other's. One that is not apart from the others' subtrees joins them,
  // until all left are.
  std::vector<std::size_t> rest_searched, rest_roots;
  const auto related = [&](std::size_t a, std::size_t b) {
    return a == b || below_any(tree_, a, [&](std::size_t x) { return x == b; }) ||
           below_any(tree_, b, [&](std::size_t x) { return x == a; });
  };
  const auto apart = [&](const std::vector<std::size_t>& region) {
    return std::none_of(rest_roots.begin(), rest_roots.end(), [&](std::size_t v) {
      return std::any_of(region.begin(), region.end(), [&](std::size_t x) { return related(v, x); });
    });
  };
  for (bool joined = true; joined;) {
    if (alone.empty() || rest.empty()) return {};
    rest_roots = remade_roots(rest, rest_searched);
    joined = false;
    std::erase_if(alone, [&](const auto& a) {
      if (apart(a.second)) return false;
      rest.push_back(a.first);
      return joined = true;
    });
  }
  std::vector<Entry> rerouted;
  for (const auto& a : alone) rerouted.push_back(a.first);
  std::vector<Replay_root> top = reroutes(
      rerouted, asked, [&](const std::vector<std::size_t>& region, bool nested) { return !nested && apart(region); });
  if (top.empty()) return {};
  searched = std::move(rest_searched);
  remade = std::move(rest_roots);
  return top;
}

template <class K>
std::vector<std::size_t> Aeg_kinetic_bsp<K>::outermost(const std::set<std::size_t>& nodes) const {
  std::vector<std::size_t> out;
  for (const std::size_t r : nodes)
    if (!below_any(tree_, r, [&](std::size_t a) { return nodes.count(a) > 0; })) out.push_back(r);
  return out;
}

template <class K>
bool Aeg_kinetic_bsp<K>::ties(const Bsp_node& n, const Site_point& at, bool identities) const {
  return counting(phases_.ties, [&] {
    return tied(n.kind == Cut_kind::edge ? pred_.side(at, n.segment, now_) : pred_.compare_x(at, n.point, now_),
                identities);
  });
}

template <class K>
std::size_t Aeg_kinetic_bsp<K>::above_ties(std::size_t top, const Site_point& at, bool identities) const {
  for (std::int32_t a = tree_.nodes[top].parent; a >= 0; a = tree_.nodes[static_cast<std::size_t>(a)].parent)
    if (ties(tree_.nodes[static_cast<std::size_t>(a)], at, identities)) top = static_cast<std::size_t>(a);
  return top;
}

template <class K>
bool Aeg_kinetic_bsp<K>::crossing(std::size_t i, std::size_t j) const {
  const auto apart = [&](std::size_t p, std::size_t q) {
    return pred_.side(Site_point::endpoint(2 * p), q, now_).sign !=
           pred_.side(Site_point::endpoint(2 * p + 1), q, now_).sign;
  };
  return apart(i, j) && apart(j, i);
}

template <class K>
bool Aeg_kinetic_bsp<K>::replay(const std::vector<Replay_root>& roots, std::set<std::size_t> dirty, Batch& b) {
  bool changed = false;
  // The endpoints beside a slot whose certificates went (taken off it at
  // once: the slot may be used again, and moved, before they are looked at
  // again), and nodes kept whole with a new cell; each with the node the
  // endpoints are found again from.
  std::vector<std::pair<std::size_t, std::size_t>> homeless, recelled;
  std::size_t from = 0;
  // The frontier roots: an endpoint below one may have moved to another's,
  // so it is looked for there only while inside.
  std::set<std::size_t> near;
  const auto unmake = [&](std::size_t n) {
    if (const auto it = transient_.find(n); it != transient_.end()) {
      spare_.emplace(it->second.id.cell, it->second);
      transient_.erase(it);
    }
  };
  Bsp_builder<K> builder(pred_, now_, tree_, &log_);
  // Validating, the way down to a crossing found below is decided again: a
  // check that the root was high enough.
  if (!validate_) builder.log_traces_only();
  Subtree_fit<K> fit(tree_, log_, scene_, builder, dirty,
                     {[&](std::size_t n) {
                        unmake(n);
                        if (const auto it = beside_.find(n); it != beside_.end()) {
                          for (const std::size_t e : it->second) homeless.emplace_back(e, from);
                          beside_.erase(it);
                        }
                      },
                      [&](std::size_t f, std::size_t to) {
                        unmake(f);
                        const auto it = beside_.find(f);
                        if (it == beside_.end()) return;
                        const std::vector<std::size_t> moved = std::move(it->second);
                        beside_.erase(it);
                        for (const std::size_t e : moved) leaf_[e] = to;
                        auto& list = beside_[to];
                        list.insert(list.end(), moved.begin(), moved.end());
                        // Its new slot keeps its own cell, which a remake below a
                        // frontier node may have made smaller than the old one.
                        recelled.emplace_back(to, from);
                      },
                      [&](std::size_t n) { recelled.emplace_back(n, from); },
                      [&](std::size_t o, const Cell& now) { return walls_renamed(o, now); }});
  // Every subtree is made again before any certificate: an endpoint may move
  // from one frontier node to another.
  for (const auto& [v, frontier, several] : roots) {
    from = v;
    if (frontier) near.insert(v);
    if (validate_) fit.ledger().audit(v);
    std::vector<Arrival> arrivals = log_.at[v];
    // A root not on a frontier is its segment's first cut on its path
    // (update raised it there, first_cut), or a leaf.
    std::optional<std::size_t> r = frontier;
    if (const std::size_t own = cut_rank(tree_.nodes[v], scene_.rank); !r && own < scene_.rank.size()) r = own;
    if (r) {
      // v, the first cut of its segment on its path (or a frontier node of
      // segment r), is made again with the segment's cuts below it; the old
      // subtrees of later cuts below them are kept where their arrivals did
      // not change. A crossing of two later segments found below v is logged
      // at v, and a remake locates it as logged: one gone now goes (one born
      // now is found below).
      std::erase_if(arrivals, [&](const Arrival& a) {
        return a.kind == Arrival::Kind::intersection && scene_.rank[a.a.a] > *r && scene_.rank[a.a.b] > *r &&
               !crossing(a.a.a, a.a.b);
      });
      fit.remake(v, *r, arrivals, fit.set_aside(v, *r, several));
    } else {
      fit.discard(v, false);
      builder.replay(v, arrivals);
    }
    changed = fit.ledger().changed(v) || changed;
    ++b.replays;
    b.frontier_replays += frontier.has_value();
  }
  // The certificates of the nodes made, and of the kept ones with a new
  // cell (certify_below keeps a node's certificate only with its cell).
  Kept kept;
  kept.tops = fit.ledger().kept();
  for (const auto& r : recelled) kept.recelled.insert(r.first);
  for (const Replay_root& root : roots) certify_below(root.node, kept);
  // The ancestors' transience may change with the point cuts below a root:
  // walking up, each node's other child is read from points_ (every root
  // is certified by now).
  for (const Replay_root& root : roots) {
    bool points = points_[root.node];
    for (std::size_t c = root.node; tree_.nodes[c].parent >= 0;) {
      const auto u = static_cast<std::size_t>(tree_.nodes[c].parent);
      const Bsp_node& n = tree_.nodes[u];
      points = points || point_cut(n) || points_[static_cast<std::size_t>(n.child[n.child[0] == std::int32_t(c)])];
      points_[u] = points;
      const bool is = !points && n.parent >= 0 && point_cut(tree_.nodes[static_cast<std::size_t>(n.parent)]);
      if (!is) transient_.erase(u);
      else if (!transient_.count(u)) make_transient(u);
      c = u;
    }
  }
  // The endpoints beside a node gone, and beside a node kept whose cell
  // moved (it may no longer be the leaf beside them), found again.
  std::sort(homeless.begin(), homeless.end());
  for (const auto& [e, up] : homeless) make_endpoint(e, up, near.count(up) > 0);
  for (const auto& [n, up] : recelled) remake_beside(n, up, near.count(up) > 0);
  spare_.clear();  // cells gone with their nodes
  b.nodes_rebuilt += builder.added();
  // A crossing cut below a root before and nowhere now: its location, logged
  // above the roots and above the cells taken whole, goes.
  std::vector<std::size_t> nodes;
  for (const Replay_root& root : roots) nodes.push_back(root.node);
  const std::vector<Site_point> lost = fit.ledger().gone(nodes, log_, scene_.rank);
  std::set<std::size_t> above(fit.tops().begin(), fit.tops().end());
  for (const Replay_root& root : roots)
    for (std::int32_t a = tree_.nodes[root.node].parent; a >= 0 && above.insert(static_cast<std::size_t>(a)).second;)
      a = tree_.nodes[static_cast<std::size_t>(a)].parent;
  unlog_crossings(log_, above, lost);
  return changed;
}

template <class K>
bool Aeg_kinetic_bsp<K>::stale(const Entry& e) const {
  switch (e.kind) {
    case Aeg_certificate_kind::transient: {
      const auto it = transient_.find(e.index);
      return it == transient_.end() || it->second.version != e.version;
    }
    case Aeg_certificate_kind::endpoint: return endpoint_[e.index].version != e.version;
    case Aeg_certificate_kind::flip: return flip_[e.index].version != e.version;
  }
  return true;
}

template <class K>
std::optional<typename K::Time> Aeg_kinetic_bsp<K>::next_event_time() {
  return queue_.next([this](const Entry& e) { return stale(e); });
}

template <class K>
typename Aeg_kinetic_bsp<K>::Batch Aeg_kinetic_bsp<K>::advance() {
  Batch b;
  b.time = *next_event_time();
  // Validation's own predicates: its signs are not the run's.
  const std::optional<Segment_predicates<K>> fresh =
      validate_ ? std::optional<Segment_predicates<K>>(std::in_place, k_, scene_) : std::nullopt;
  if (fresh) {
    const Time mid = kinetic::between(k_, now_, b.time);
    ++validations_;
    if (build_cylindrical_bsp(*fresh, mid).text() != tree_.text())
      failures_.push_back("the tree in force before t = " + k_.to_string(b.time) + " differs from a fresh build at t = " +
                          k_.to_string(mid));
  }
  const auto start = std::chrono::steady_clock::now();
  const std::size_t made = made_;
  // The failing certificates.
  std::vector<Entry> entries;
  while (!queue_.empty() && (stale(queue_.top()) || k_.compare(queue_.top().time, b.time) == 0)) {
    const Entry e = queue_.top();
    queue_.pop();
    if (!stale(e)) entries.push_back(e);
  }
  // Seed 003's augmented BSP, as the tree in force reads it: flips alone
  // must leave it as it was (augmented_bsp.hpp). Only a batch with a flip
  // can turn one in place.
  const bool flips = std::any_of(entries.begin(), entries.end(),
                                 [](const Entry& e) { return e.kind == Aeg_certificate_kind::flip; });
  std::string augmented;
  std::chrono::steady_clock::duration aside{};  // validation's, not the update's
  if (fresh && flips) {
    const auto t0 = std::chrono::steady_clock::now();
    augmented = augment(tree_, *fresh, now_).text();
    aside = std::chrono::steady_clock::now() - t0;
  }
  const Segment_rule_counts signs = pred_.counts();
  now_ = b.time;
  update(std::move(entries), b);
  if (fresh)
    if (const std::optional<std::string> wrong = certified_afresh())
      failures_.push_back("after the batch at t = " + k_.to_string(b.time) + ", " + *wrong);
  next_event_time();  // up to the next queue minimum: stale entries off the heap
  queue_.trim([this](const Entry& e) { return stale(e); });
  b.update_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start - aside).count();
  b.signs = pred_.counts().decided() - signs.decided();
  b.held = pred_.counts().held - signs.held;
  b.repeated = pred_.counts().repeated - signs.repeated;
  b.certificates = certificates();
  b.certificates_made = made_ - made;
  if (fresh && flips && b.flipped_in_place > 0 && augment(tree_, *fresh, now_).text() != augmented)
    failures_.push_back("the flips turned in place at t = " + k_.to_string(b.time) + " changed the augmented BSP");
  return b;
}

template <class K>
void Aeg_kinetic_bsp<K>::update(std::vector<Entry> entries, Batch& b) {
  // In the order of what the certificates are about, not the heap's nor the
  // slots': which part of the update first asks a key two parts share
  // (Batch::phases), and so which signs it decides, does not depend on when
  // the heap was last swept or refilled.
  std::sort(entries.begin(), entries.end(), [this](const Entry& x, const Entry& y) {
    return before(held({x.kind, x.index}).id, held({y.kind, y.index}).id);
  });
  // A key asked again at now_ is answered from its first decision, unless a
  // certificate being made needs its polynomials.
  const Remembering<K> remembering(pred_, now_);
  phases_ = {};
  std::set<std::size_t> failing_transient;
  std::vector<std::size_t> turning;
  for (const Entry& e : entries) {
    b.failing.push_back(held({e.kind, e.index}).id);
    // A failing certificate is made again, not kept.
    if (e.kind == Aeg_certificate_kind::flip) turning.push_back(e.index);
    else if (e.kind == Aeg_certificate_kind::endpoint) failing_endpoints_.insert(e.index);
    else failing_transient.insert(e.index);
  }
  std::map<std::size_t, std::uint64_t> was;  // the failing endpoints' certificates, by version
  for (const std::size_t e : failing_endpoints_) was.emplace(e, endpoint_[e].version);
  // A turning segment's endpoints have their far side changed: they leave
  // their leaves' lists now, and are found again from the root after the
  // update, whether the flip is done in place or replayed.
  for (const std::size_t s : turning)
    for (const std::size_t e : {2 * s, 2 * s + 1}) detach(e);
  if (!turning.empty() && failing_endpoints_.empty() && flip_in_place(turning, failing_transient, b)) {
    b.changed = true;
  } else if (!entries.empty()) {
    // Where the changes are looked for: the reroutes' roots, and the
    // subtrees the other failing certificates name.
    std::vector<std::size_t> asked, searched, remade;
    std::vector<Replay_root> top = reroutes(entries, asked);
    if (top.empty() && entries.size() > 1) top = reroute_apart(entries, asked, searched, remade);
    if (top.empty()) remade = remade_roots(entries, searched);
    for (const Replay_root& r : top) searched.push_back(r.node);
    for (const std::size_t r : remade) top.push_back({r, std::nullopt});
    // In preorder: the endpoints of a node a remake lets go are looked for
    // from the root being made again then.
    sort_in_preorder(tree_, top, [](const Replay_root& r) { return r.node; });
    std::set<std::size_t> dirty = changing(entries, searched, std::move(asked));
    for (const std::size_t v : failing_transient) transient_.erase(v);
    b.changed = replay(top, std::move(dirty), b);
  }
  // Every failing transient node and endpoint certificate lay below a root,
  // and was made again there; a flip's is made again here.
  for (const std::size_t s : turning) {
    make_flip(s);
    for (const std::size_t e : {2 * s, 2 * s + 1}) make_endpoint(e);
  }
  // A failing endpoint certificate left as it was (its leaf neither gone
  // nor given a new cell) is found again from the root: kept, its old
  // failure would come back.
  for (const auto& [e, version] : was)
    if (endpoint_[e].version == version) {
      detach(e);
      make_endpoint(e);
    }
  failing_endpoints_.clear();
  b.phases = phases_;
}

template <class K>
std::vector<typename Aeg_kinetic_bsp<K>::Batch> Aeg_kinetic_bsp<K>::advance_to(const Time& t) {
  return kinetic::batches_until(*this, k_, t, now_, bounded_ ? std::optional<Time>(end_) : std::nullopt);
}

template <class K>
typename Aeg_kinetic_bsp<K>::Batch Aeg_kinetic_bsp<K>::set_motion(std::size_t segment, const Segment_motion& motion) {
  check_motion_change(k_, scene_, segment, motion, now_, bounded_ ? std::optional<Time>(end_) : std::nullopt);
  Batch b;
  b.time = now_;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t made = made_;
  // The certificates naming the segment (Lemma 3.1), their signs just after
  // now under the old motion and then the new: the same signs make new
  // polynomials and a new failure time; other signs are a failure now.
  const std::vector<Held> named = naming(segment);
  std::vector<Decided> was;
  for (const Held& h : named) was.push_back(signs(held(h), h.index));
  scene_.segments[segment].motion = motion;
  pred_.refresh(segment, now_);
  std::vector<Entry> failing;
  for (std::size_t i = 0; i < named.size(); ++i) {
    const Held& h = named[i];
    Certificate& c = held(h);
    // Same signs: the tree stays, and an endpoint's leaf with it.
    if (signs(c, h.index) != was[i]) failing.push_back({now_, h.kind, h.index, c.version});
    else make(c, h.index);
  }
  update(std::move(failing), b);
  b.update_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  b.certificates = certificates();
  b.certificates_made = made_ - made;
  return b;
}

template class Aeg_kinetic_bsp<Exact_kernel>;

}  // namespace kvd::segments
