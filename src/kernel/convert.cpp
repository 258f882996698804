#include "kvd/kernel/convert.hpp"

#include "kvd/kernel/exact_time.hpp"

namespace kvd {

// Round to nearest, ties to even (mpq_class::get_d truncates).
template <>
double from_rational<double>(const mpq_class& q) {
  return Exact_time(q).to_double();
}

mpq_class to_rational(const Mpfr_number& x) {
  mpq_class q;
  mpfr_get_q(q.get_mpq_t(), x.get());
  return q;
}

}  // namespace kvd
