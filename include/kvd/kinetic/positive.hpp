// Certificate polynomials with the sign convention "positive while valid".
#pragma once

#include <vector>

#include "kvd/predicates/classify.hpp"

namespace kvd::kinetic {

// The non-constant polynomials of `polys`, each multiplied by its sign just
// after `now`; constants (and zero) are dropped: they never fail.
template <class K, class Range>
std::vector<typename K::Poly> positive(const predicates::Classifier<K>& c, const Range& polys,
                                       const typename K::Time& now) {
  std::vector<typename K::Poly> out;
  for (const auto& q : polys)
    if (q.degree() >= 1) out.push_back(c.lex_sign(q, now) < 0 ? -q : q);
  return out;
}

}  // namespace kvd::kinetic
