#include "kvd/kinetic/full_simulation.hpp"

#include <map>

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

Full_simulation simulate_full(const scene::Scene& s, const Full_options& options) {
  const Exact_kernel k;
  const predicates::Classifier<Exact_kernel> c(k, s);
  Full_simulation sim;
  Exact_time now(s.start);
  tree::Evaluated evaluated;
  tree::Kvd_tree current = tree::build(c, now, &evaluated);
  // Next roots are cached per distinct polynomial (its coefficients).
  std::map<std::vector<mpq_class>, std::optional<Exact_time>> next_root;
  while (sim.events.size() < options.max_events) {
    std::map<std::vector<mpq_class>, Poly<mpq_class>> polys;
    for (const auto& [v, p] : evaluated)
      for (auto& q : c.certificate(v, p)) polys.emplace(q.coefficients(), q);
    std::optional<Exact_time> first;
    std::size_t failing = 0;
    for (const auto& [key, q] : polys) {
      auto it = next_root.find(key);
      if (it == next_root.end() || (it->second && k.compare(*it->second, now) <= 0))
        it = next_root.insert_or_assign(key, k.next_root(q, now)).first;
      const auto& r = it->second;
      if (!r) continue;
      const int cmp = first ? k.compare(*r, *first) : -1;
      if (cmp < 0) first = *r, failing = 1;
      else if (cmp == 0) ++failing;
    }
    if (!first || (s.end && k.compare(*first, Exact_time(*s.end)) > 0)) break;
    if (options.validate && sim.valid) {
      const mpq_class mid = rational_between(now, *first);
      const auto diff = tree::first_difference(current, tree::build(c, Exact_time(mid)));
      if (diff) {
        sim.valid = false;
        sim.failure = "between " + now.to_string() + " and " + first->to_string() + ", at " + mid.get_str() +
                      ", the tree in force differs from a fresh build: " + *diff;
      }
    }
    evaluated.clear();
    tree::Kvd_tree next = tree::build(c, *first, &evaluated);
    sim.events.push_back({*first, failing, polys.size(), tree::first_difference(current, next).has_value()});
    current = std::move(next);
    now = *first;
  }
  return sim;
}

}  // namespace kvd::kinetic
