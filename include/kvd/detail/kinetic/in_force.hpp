// The certificates in force, under the ids the event queue knows them by. A
// certificate keeps its id, its failure time and its place in the queue for
// as long as it stays in force with the same polynomials, so a batch
// changes the queue only where certificates came, went, changed or moved to
// another node (and the tree queue repairs only those nodes' paths).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "kvd/kinetic/certificate.hpp"
#include "kvd/detail/flat_map.hpp"
#include "kvd/detail/kinetic/event_queue.hpp"

namespace kvd::kinetic {

template <class K>
class In_force {
public:
  using Poly = typename K::Poly;
  using Time = typename K::Time;
  struct Offer {
    const Certificate<Poly>* certificate;
    bool made;  // made at this update; otherwise the same as the one in force under its key
  };

  // Puts exactly `offers` (distinct keys) in force; `fails(c)` is the
  // failure time of a certificate new in force or with new polynomials.
  template <class Fails>
  void replace(const std::vector<Offer>& offers, Event_queue<K>& queue, Fails fails) {
    std::set<Certificate_key> offered;
    for (const Offer& o : offers) offered.insert(o.certificate->key);
    std::vector<Certificate_key> gone;
    for (const auto& [key, id] : by_key())
      if (!offered.contains(*key)) gone.push_back(*key);
    apply(gone, offers, queue, fails);
  }

  // Takes the keys `gone` out of force and puts `changed` (distinct keys)
  // in force, keeping everything else.
  template <class Fails>
  void apply(const std::vector<Certificate_key>& gone, const std::vector<Offer>& changed, Event_queue<K>& queue,
             Fails fails) {
    for (const Certificate_key& key : gone) {
      const std::size_t id = *ids_.find(key);
      queue.set(id, entries_[id].certificate->node, std::nullopt);
      entries_[id] = Entry{};
      free_.push_back(id);
      ids_.erase(key);
    }
    for (const Offer& o : changed) {
      const Certificate<Poly>& c = *o.certificate;
      auto [slot, fresh] = ids_.try_emplace(c.key);
      if (fresh) *slot = allocate();
      const std::size_t id = *slot;
      Entry& e = entries_[id];
      if (fresh || (o.made && !same_polys(*e.certificate, c))) {
        e.certificate = c;
        e.fails = fails(c);
      } else if (e.certificate->node != c.node) {
        e.certificate->node = c.node;
      } else {
        continue;
      }
      queue.set(id, c.node, e.fails);
    }
  }

  // Forgets every certificate (the queue is reset by the caller).
  void clear() {
    ids_.clear();
    entries_.clear();
    free_.clear();
  }

  const Certificate<Poly>& operator[](std::size_t id) const { return *entries_[id].certificate; }
  // The failure time the queue holds for it.
  const std::optional<Time>& fails(std::size_t id) const { return entries_[id].fails; }
  std::size_t size() const { return ids_.size(); }
  // By key.
  template <class F>
  void for_each(F f) const {
    for (const auto& [key, id] : by_key()) f(*entries_[id].certificate);
  }

private:
  struct Entry {
    std::optional<Certificate<Poly>> certificate;
    std::optional<Time> fails;
  };

  // The entries in force, by key: what is read whole goes in key order, so
  // that nothing depends on the hash table's order.
  std::vector<std::pair<const Certificate_key*, std::size_t>> by_key() const {
    std::vector<std::pair<const Certificate_key*, std::size_t>> out;
    out.reserve(ids_.size());
    ids_.for_each([&](const Certificate_key& key, std::size_t id) { out.emplace_back(&key, id); });
    std::ranges::sort(out, {}, [](const auto& entry) -> const Certificate_key& { return *entry.first; });
    return out;
  }

  std::size_t allocate() {
    if (free_.empty()) {
      entries_.emplace_back();
      return entries_.size() - 1;
    }
    const std::size_t id = free_.back();
    free_.pop_back();
    return id;
  }

  static bool same_polys(const Certificate<Poly>& a, const Certificate<Poly>& b) {
    return std::ranges::equal(a.polys, b.polys,
                              [](const Poly& p, const Poly& q) { return p.coefficients() == q.coefficients(); });
  }

  kvd::detail::Flat_map<Certificate_key, std::size_t, Certificate_key_hash> ids_;
  std::vector<Entry> entries_;  // by id; empty when free
  std::vector<std::size_t> free_;
};

}  // namespace kvd::kinetic
