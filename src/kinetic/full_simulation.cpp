#include "kvd/kinetic/full_simulation.hpp"

#include <algorithm>
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
  // Checks the tree in force on (from, to) against a fresh build at a
  // rational time strictly between: a difference is a missed event.
  auto validate = [&](const Exact_time& from, const Exact_time& to, const tree::Kvd_tree& in_force) {
    const mpq_class mid = rational_between(from, to);
    const auto diff = tree::first_difference(in_force, tree::build(c, Exact_time(mid)));
    if (!diff) return;
    if (sim.validation_failures++ == 0)
      sim.failure = "between " + from.to_string() + " and " + to.to_string() + ", at " + mid.get_str() +
                    ", the tree in force differs from a fresh build: " + *diff;
  };
  std::optional<std::pair<Exact_time, tree::Kvd_tree>> before_last;  // for Validation::end
  std::optional<Exact_time> limit;
  if (s.end) limit = Exact_time(*s.end);
  if (options.until && (!limit || k.compare(Exact_time(*options.until), *limit) < 0)) limit = Exact_time(*options.until);
  // Next roots are cached per distinct polynomial (its coefficients).
  std::map<std::vector<mpq_class>, std::optional<Exact_time>> next_root;
  while (sim.failures < options.max_events) {
    // Distinct polynomials, each with the certificates that have it.
    std::map<std::vector<mpq_class>, std::pair<Poly<mpq_class>, tree::Evaluated>> polys;
    // A classification evaluated for several fragments is one certificate.
    std::sort(evaluated.begin(), evaluated.end());
    evaluated.erase(std::unique(evaluated.begin(), evaluated.end()), evaluated.end());
    std::size_t certificates = 0;
    for (const auto& [v, p] : evaluated) {
      const auto qs = c.certificate(v, p);
      certificates += !qs.empty();
      for (auto& q : qs) polys.try_emplace(q.coefficients(), q, tree::Evaluated{}).first->second.second.emplace_back(v, p);
    }
    std::optional<Exact_time> first;
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
    if (options.validate == Validation::end) before_last.emplace(now, current);
    evaluated.clear();
    tree::Kvd_tree next;
    try {
      next = tree::build(c, *first, &evaluated);
    } catch (const tree::Build_error& e) {
      sim.collision = "collision at t = " + first->to_string() + ": " + e.what();
      now = *first;
      break;
    }
    // A certificate with two polynomials failing together counts once.
    std::sort(failing.begin(), failing.end());
    failing.erase(std::unique(failing.begin(), failing.end()), failing.end());
    sim.failures += failing.size();
    sim.simultaneous_batches += failing.size() >= 2;
    const std::size_t count = failing.size();
    sim.events.push_back({*first, std::move(failing), count, certificates, tree::first_difference(current, next).has_value()});
    current = std::move(next);
    now = *first;
  }
  if (options.validate == Validation::end && before_last) validate(before_last->first, now, before_last->second);
  sim.time_reached = now;
  sim.structure_hash = tree::structure_hash(current);
  return sim;
}

}  // namespace kvd::kinetic
