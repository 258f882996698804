#include "kvd/kernel/float_kernel.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "kvd/kernel/convert.hpp"
#include "kvd/detail/kernel/numeric_roots.hpp"

namespace kvd {

namespace {

double as_double(double x) { return x; }
double as_double(const Mpfr_number& x) { return x.to_double(); }
std::string as_string(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
std::string as_string(const Mpfr_number& x) { return x.to_string(17); }

}  // namespace

template <class FT>
int Float_kernel<FT>::sign(const FT& x) const {
  if (x > epsilon_) return 1;
  if (x < -epsilon_) return -1;
  return 0;
}

template <class FT>
int Float_kernel<FT>::sign_after(const Poly& p, const Time& t) const {
  for (Poly d = p; !d.is_zero(); d = d.derivative()) {
    const int s = sign_at(d, t);
    if (s != 0) return s;
  }
  return 0;
}

template <class FT>
std::optional<FT> Float_kernel<FT>::next_root(const Poly& p, const Time& after) const {
  if (p.degree() < 1) return std::nullopt;
  const FT bound = cauchy_bound(p);
  // A bound that overflowed gives an infinite "root", which is no instant.
  for (auto& r : sign_change_roots(p, after, bound))
    if (is_finite(r) && compare(r, after) > 0) return r;
  return std::nullopt;
}

template <class FT>
double Float_kernel<FT>::to_double(const Time& t) const {
  return as_double(t);
}

template <class FT>
std::string Float_kernel<FT>::to_string(const Time& t) const {
  return as_string(t);
}

template class Float_kernel<double>;
template class Float_kernel<Mpfr_number>;

static Mpfr_number default_mpfr_epsilon(unsigned bits) {
  Mpfr_number::set_default_precision(static_cast<mpfr_prec_t>(bits));
  return Mpfr_number(std::ldexp(1.0, -static_cast<int>(bits / 2)));  // a power of two: exact
}

Mpfr_kernel::Mpfr_kernel(unsigned bits) : Mpfr_kernel(bits, default_mpfr_epsilon(bits)) {}

Mpfr_kernel::Mpfr_kernel(unsigned bits, const Mpfr_number& epsilon)
    : Float_kernel<Mpfr_number>(epsilon), bits_(bits) {
  Mpfr_number::set_default_precision(static_cast<mpfr_prec_t>(bits));
}

}  // namespace kvd
