#include "kvd/kinetic/event_order.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace kvd::kinetic {

// t's canonical isolating interval (for a factor of p) refined until
// Descartes' rule, exact at 1, counts one root of p's square-free part inside
// and none at the ends.
std::pair<mpq_class, mpq_class> isolating_interval(const zpoly::ZPoly& p, const Exact_time& time) {
  const zpoly::ZPoly s = zpoly::square_free(p);
  const Exact_time t = time.canonical();
  for (;;) {
    if (t.is_rational()) return {t.rational(), t.rational()};
    if (zpoly::sign_at(s, t.lower()) != 0 && zpoly::sign_at(s, t.upper()) != 0 &&
        zpoly::descartes_bound(s, t.lower(), t.upper()) == 1)
      return {t.lower(), t.upper()};
    t.refine();
  }
}

int root_multiplicity(const Exact_kernel& k, const zpoly::ZPoly& p, const Exact_time& t) {
  int multiplicity = 0;
  for (zpoly::ZPoly d = p; k.sign_at(zpoly::to_poly(d), t) == 0; d = zpoly::derivative(d)) ++multiplicity;
  return multiplicity;
}

std::size_t Event_order_recorder::id(const Certificate_key& key, const zpoly::ZPoly& p) {
  const std::size_t motions = order_.motion_changes.size();
  const auto [it, fresh] = ids_.try_emplace({key, motions, p}, order_.certificates.size());
  if (fresh) order_.certificates.push_back({key, p, motions});
  return it->second;
}

void Event_order_recorder::in_force(const Exact_time&, const std::vector<Certificate<Exact_kernel::Poly>>& certs) {
  current_.clear();
  std::vector<std::size_t> active;
  // Certificates are numbered as they first appear, listed by their
  // features' text: the certificate file's order.
  std::vector<std::pair<std::string, const Certificate<Exact_kernel::Poly>*>> listed;  // text made once
  for (const auto& c : certs) listed.emplace_back(features(c.key), &c);
  std::ranges::stable_sort(listed, [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [text, c] : listed)
    for (const auto& q : c->polys) {
      // to_zpoly scales by a positive rational: still positive where in force.
      const std::size_t i = id(c->key, zpoly::to_zpoly(q));
      current_[c->key].push_back(i);
      active.push_back(i);
    }
  order_.intervals.push_back(std::move(active));
}

Event_order::Root Event_order_recorder::root(const Failure& f, const Exact_time& t) const {
  const auto it = current_.find(f);
  if (it == current_.end()) throw std::logic_error("event of a certificate not in force: " + features(f));
  // The certificate's polynomial that vanishes at t.
  const auto vanishes = [&](std::size_t i) {
    return k_.sign_at(zpoly::to_poly(order_.certificates[i].polynomial), t) == 0;
  };
  const auto which = std::find_if(it->second.begin(), it->second.end(), vanishes);
  if (which == it->second.end()) throw std::logic_error("no polynomial of " + features(f) + " vanishes at its event");
  const zpoly::ZPoly& p = order_.certificates[*which].polynomial;
  const auto [lo, hi] = isolating_interval(p, t);
  return {*which, lo, hi, root_multiplicity(k_, p, t)};
}

void Event_order_recorder::batch(const Batch<Exact_time>& b, bool collision) {
  bool first = true;
  for (const Failure& f : b.failing) {
    order_.events.push_back({root(f, b.time), !first, collision});
    first = false;
  }
}

void Event_order_recorder::reversal(const Reversal<Exact_time>& r) {
  Event_order::Motion_change change{order_.events.size(), r.time, {}, r.objects, r.motions, r.contact};
  for (const Failure& f : r.collision.failing) change.failing.push_back(root(f, r.collision.time));
  order_.motion_changes.push_back(std::move(change));
}

}  // namespace kvd::kinetic
