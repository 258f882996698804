// The first sign-changing root after the current instant of each
// polynomial a run meets, kept while it still lies ahead: a certificate
// that stays in force, or comes back with the same polynomial, costs no new
// root isolation.
#pragma once

#include <map>
#include <optional>
#include <vector>

namespace kvd::kinetic {

template <class K>
class Root_cache {
  using Time = typename K::Time;

public:
  const std::optional<Time>& next_root(const K& k, const typename K::Poly& q, const Time& now) {
    auto it = roots_.find(q.coefficients());
    if (it == roots_.end() || (it->second && k.compare(*it->second, now) <= 0))
      it = roots_.insert_or_assign(q.coefficients(), k.next_root(q, now)).first;
    return it->second;
  }

  // The earliest of the certificate's polynomials' next roots after now.
  template <class Certificate>
  std::optional<Time> fails(const K& k, const Certificate& cert, const Time& now) {
    std::optional<Time> first;
    for (const auto& q : cert.polys) {
      const auto& r = next_root(k, q, now);
      if (r && (!first || k.compare(*r, *first) < 0)) first = r;
    }
    return first;
  }

private:
  std::map<std::vector<typename K::FT>, std::optional<Time>> roots_;
};

}  // namespace kvd::kinetic
