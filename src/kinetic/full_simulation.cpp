#include "kvd/kinetic/full_simulation.hpp"

#include <algorithm>
#include <map>

#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"

namespace kvd::kinetic {

mpq_class rational_between(const Exact_time& a, const Exact_time& b) {
  for (;;) {
    const mpq_class lo = a.is_rational() ? a.rational() : a.upper();
    const mpq_class hi = b.is_rational() ? b.rational() : b.lower();
    if (lo < hi) return (lo + hi) / 2;
    a.refine();
    b.refine();
  }
}

namespace {

// A time strictly between a < b: a rational in the exact kernel, the
// midpoint in the floating-point ones.
Exact_time between(const Exact_kernel&, const Exact_time& a, const Exact_time& b) {
  return Exact_time(rational_between(a, b));
}
template <class K>
typename K::Time between(const K&, const typename K::Time& a, const typename K::Time& b) {
  return (a + b) / typename K::FT(2);
}

}  // namespace

template <class K>
Full_simulation<typename K::Time> simulate_full(const K& k, const scene::Scene& s, const Full_options& options) {
  using Time = typename K::Time;
  using FT = typename K::FT;
  const predicates::Classifier<K> c(k, s);
  Full_simulation<Time> sim;
  Time now = k.time(from_rational<FT>(s.start));
  tree::Evaluated evaluated;
  tree::Kvd_tree current = tree::build(c, now, &evaluated);
  // Checks the tree in force on (from, to) against a fresh build at a
  // rational time strictly between: a difference is a missed event.
  auto validate = [&](const Time& from, const Time& to, const tree::Kvd_tree& in_force) {
    const Time mid = between(k, from, to);
    const auto diff = tree::first_difference(in_force, tree::build(c, mid));
    if (!diff) return;
    if (sim.validation_failures++ == 0)
      sim.failure = "between " + k.to_string(from) + " and " + k.to_string(to) + ", at " + k.to_string(mid) +
                    ", the tree in force differs from a fresh build: " + *diff;
  };
  std::optional<std::pair<Time, tree::Kvd_tree>> before_last;  // for Validation::end
  std::optional<Time> limit;
  if (s.end) limit = k.time(from_rational<FT>(*s.end));
  if (options.until) {
    const Time until = k.time(from_rational<FT>(*options.until));
    if (!limit || k.compare(until, *limit) < 0) limit = until;
  }
  // Next roots are cached per distinct polynomial (its coefficients).
  std::map<std::vector<FT>, std::optional<Time>> next_root;
  while (sim.failures < options.max_events) {
    // Distinct polynomials, each with the certificates that have it.
    std::map<std::vector<FT>, std::pair<typename K::Poly, tree::Evaluated>> polys;
    // A classification evaluated for several fragments is one certificate.
    std::sort(evaluated.begin(), evaluated.end());
    evaluated.erase(std::unique(evaluated.begin(), evaluated.end()), evaluated.end());
    std::size_t certificates = 0;
    for (const auto& [v, p] : evaluated) {
      const auto& qs = c.certificate(v, p);
      certificates += !qs.empty();
      for (const auto& q : qs) polys.try_emplace(q.coefficients(), q, tree::Evaluated{}).first->second.second.emplace_back(v, p);
    }
    std::optional<Time> first;
    tree::Evaluated failing;
    for (const auto& [key, entry] : polys) {
      const auto& [q, owners] = entry;
      auto it = next_root.find(key);
      if (it == next_root.end() || (it->second && k.compare(*it->second, now) <= 0))
        it = next_root.insert_or_assign(key, k.next_root(q, now)).first;
      const auto& r = it->second;
      if (!r) continue;
      const int cmp = first ? k.compare(*r, *first) : -1;
      if (cmp < 0) first = *r, failing = owners;
      else if (cmp == 0) failing.insert(failing.end(), owners.begin(), owners.end());
    }
    if (!first || (limit && k.compare(*first, *limit) > 0)) break;
    if (options.validate == Validation::every) validate(now, *first, current);
    evaluated.clear();
    tree::Kvd_tree next;
    try {
      next = tree::build(c, *first, &evaluated);
    } catch (const tree::Build_error& e) {
      sim.collision = "collision at t = " + k.to_string(*first) + ": " + e.what();
      if (options.validate == Validation::end) before_last.emplace(now, current);  // current stays in force
      now = *first;
      break;
    }
    // A certificate with two polynomials failing together counts once.
    std::sort(failing.begin(), failing.end());
    failing.erase(std::unique(failing.begin(), failing.end()), failing.end());
    sim.failures += failing.size();
    sim.simultaneous_batches += failing.size() >= 2;
    sim.events.push_back({*first, std::move(failing), certificates, tree::first_difference(current, next).has_value()});
    if (options.validate == Validation::end) before_last.emplace(now, std::move(current));
    current = std::move(next);
    now = *first;
    if (options.progress) options.progress(sim.events.size(), sim.failures);
  }
  if (options.validate == Validation::end && before_last) validate(before_last->first, now, before_last->second);
  sim.time_reached = now;
  sim.structure_hash = tree::structure_hash(current);
  return sim;
}

#define KVD_INSTANTIATE_SIMULATE(K) \
  template Full_simulation<K::Time> simulate_full<K>(const K&, const scene::Scene&, const Full_options&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SIMULATE)

}  // namespace kvd::kinetic
