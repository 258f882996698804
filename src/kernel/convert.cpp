#include "kvd/kernel/convert.hpp"

#include "kvd/kernel/exact_time.hpp"

namespace kvd {

// Round to nearest, ties to even (mpq_class::get_d truncates).
template <>
double from_rational<double>(const mpq_class& q) {
  return Exact_time(q).to_double();
}

}  // namespace kvd
