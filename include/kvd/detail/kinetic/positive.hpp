// Certificate polynomials with the sign convention "positive while valid".
#pragma once

#include <vector>

#include "kvd/predicates/classify.hpp"

namespace kvd::kinetic {

// The non-constant polynomials of `polys` (append_positive: of one, added to
// `out` without an intermediate copy), each multiplied by its sign just
// after `now`; constants (and zero) are dropped: they never fail. Constant
// is by the kernel's zero test (Classifier::vanishes from t^1): in a
// floating-point kernel a value that is constant exactly (a vertex against
// a plane of its own rigid triangle) keeps rounding noise in t, t^2, ....
template <class K>
void append_positive(const predicates::Classifier<K>& c, const typename K::Poly& q, const typename K::Time& now,
                     std::vector<typename K::Poly>& out) {
  if (!c.vanishes(q, 1)) out.push_back(c.lex_sign(q, now) < 0 ? -q : q);
}

template <class K, class Range>
std::vector<typename K::Poly> positive(const predicates::Classifier<K>& c, const Range& polys,
                                       const typename K::Time& now) {
  std::vector<typename K::Poly> out;
  for (const auto& q : polys) append_positive(c, q, now, out);
  return out;
}

}  // namespace kvd::kinetic
