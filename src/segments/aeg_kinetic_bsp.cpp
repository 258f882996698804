// The kinetic segment BSP on the paper's certificates alone
// (kvd/segments/aeg_kinetic_bsp.hpp).
#include "kvd/segments/aeg_kinetic_bsp.hpp"

#include "kvd/detail/kinetic/validator.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/segments/aeg_certificates.hpp"

namespace kvd::segments {

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
  make();
}

template <class K>
template <class F>
void Aeg_kinetic_bsp<K>::add(const Aeg_certificate_id& id, F decide) {
  polys_.clear();
  decide();
  std::optional<Time> first;
  for (const P& q : polys_) {
    const auto& r = roots_.next_root(k_, q, now_);
    if (r && (!first || k_.compare(*r, *first) < 0)) first = r;
  }
  if (first && bounded_ && k_.compare(*first, end_) > 0) first.reset();  // after the span: no event
  certs_.push_back({id, first});
}

template <class K>
void Aeg_kinetic_bsp<K>::make() {
  pred_.record({});
  tree_ = build_cylindrical_bsp(pred_, now_);
  certs_.clear();
  const std::size_t n = pred_.size();
  std::vector<std::array<std::int64_t, 2>> near;
  for (std::size_t e = 0; e < 2 * n; ++e) near.push_back(aeg_neighbours(tree_, pred_, now_, e));
  // From here on every sign decided by arithmetic hands over its polynomials
  // (identities have none: they never change).
  pred_.record([this](const Segment_certificate_key&, std::vector<P>&& polys, std::int32_t, int) {
    for (P& q : polys) polys_.push_back(std::move(q));
  });
  for (const std::size_t v : transient_nodes(tree_)) {
    const Cell& c = tree_.nodes[v].cell;
    add({Aeg_certificate_kind::transient, 0, c}, [&] {
      if (c.left && c.right) pred_.compare_x(*c.left, *c.right, now_);
      if (c.floor && c.roof)
        for (const auto& wall : {c.left, c.right})
          if (wall) pred_.order_at(*wall, *c.roof, *c.floor, now_);
    });
  }
  for (std::size_t e = 0; e < 2 * n; ++e)
    add({Aeg_certificate_kind::endpoint, e, {}}, [&] {
      const Site_point p = Site_point::endpoint(e);
      for (const std::int64_t s : near[e]) {
        if (s < 0) continue;
        const auto j = static_cast<std::size_t>(s);
        pred_.side(p, j, now_);
        pred_.compare_x(p, Site_point::endpoint(2 * j), now_);
        pred_.compare_x(p, Site_point::endpoint(2 * j + 1), now_);
      }
    });
  for (std::size_t s = 0; s < n; ++s)
    add({Aeg_certificate_kind::flip, s, {}},
        [&] { pred_.compare_x(Site_point::endpoint(2 * s + 1), Site_point::endpoint(2 * s), now_); });
  pred_.record({});
}

template <class K>
std::optional<typename K::Time> Aeg_kinetic_bsp<K>::next_event_time() const {
  std::optional<Time> first;
  for (const Certificate& c : certs_)
    if (c.fails && (!first || k_.compare(*c.fails, *first) < 0)) first = c.fails;
  return first;
}

template <class K>
typename Aeg_kinetic_bsp<K>::Batch Aeg_kinetic_bsp<K>::advance() {
  Batch b{*next_event_time(), {}, false, 0};
  if (validate_) {
    const Time mid = kinetic::between(k_, now_, b.time);
    ++validations_;
    if (build_cylindrical_bsp(Segment_predicates<K>(k_, scene_), mid).text() != tree_.text())
      failures_.push_back("the tree in force before t = " + k_.to_string(b.time) + " differs from a fresh build at t = " +
                          k_.to_string(mid));
  }
  for (const Certificate& c : certs_)
    if (c.fails && k_.compare(*c.fails, b.time) == 0) b.failing.push_back(c.id);
  const std::string before = tree_.text();
  now_ = b.time;
  make();
  b.changed = tree_.text() != before;
  b.certificates = certs_.size();
  return b;
}

template class Aeg_kinetic_bsp<Exact_kernel>;

}  // namespace kvd::segments
