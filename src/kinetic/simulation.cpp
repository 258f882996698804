#include "kvd/kinetic/simulation.hpp"

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

}  // namespace kvd::kinetic
