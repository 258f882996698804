// Exact rationals into a kernel's field: exact for mpq, rounded to nearest
// for double and MPFR (at the current precision); and back, exactly (every
// double and every MPFR number is a rational).
#pragma once

#include <gmpxx.h>

#include <cmath>

#include "kvd/kernel/mpfr_number.hpp"
#include "kvd/kernel/poly.hpp"

namespace kvd {

template <class FT>
FT from_rational(const mpq_class& q);

template <>
inline mpq_class from_rational<mpq_class>(const mpq_class& q) {
  return q;
}
template <>
inline Mpfr_number from_rational<Mpfr_number>(const mpq_class& q) {
  return Mpfr_number(q);
}
template <>
double from_rational<double>(const mpq_class& q);  // src/kernel/convert.cpp

// Whether a kernel number is a finite value (not an infinity or a NaN).
inline bool is_finite(const mpq_class&) { return true; }
inline bool is_finite(double d) { return std::isfinite(d); }
inline bool is_finite(const Mpfr_number& x) { return mpfr_number_p(x.get()) != 0; }

inline mpq_class to_rational(const mpq_class& q) { return q; }
inline mpq_class to_rational(double d) { return mpq_class(d); }  // mpq_set_d is exact
mpq_class to_rational(const Mpfr_number& x);

// A polynomial with rational coefficients over FT, coefficient by coefficient.
template <class FT>
Poly<FT> poly_from_rational(const Poly<mpq_class>& p) {
  std::vector<FT> c;
  for (const auto& q : p.coefficients()) c.push_back(from_rational<FT>(q));
  return Poly<FT>(std::move(c));
}

}  // namespace kvd
