#include "kvd/kernel/mpfr_number.hpp"

#include <cstdio>
#include <utility>
#include <vector>

namespace kvd {

namespace {
thread_local mpfr_prec_t current_precision = 128;
}

mpfr_prec_t Mpfr_number::default_precision() { return current_precision; }
void Mpfr_number::set_default_precision(mpfr_prec_t bits) { current_precision = bits; }

Mpfr_number::Mpfr_number(long v) : Mpfr_number(Uninitialised{}, current_precision) {
  mpfr_set_si(v_, v, MPFR_RNDN);
}
Mpfr_number::Mpfr_number(double v) : Mpfr_number(Uninitialised{}, current_precision) {
  mpfr_set_d(v_, v, MPFR_RNDN);
}
Mpfr_number::Mpfr_number(const mpq_class& v) : Mpfr_number(Uninitialised{}, current_precision) {
  mpfr_set_q(v_, v.get_mpq_t(), MPFR_RNDN);
}
Mpfr_number::Mpfr_number(const Mpfr_number& o) : Mpfr_number(Uninitialised{}, o.precision()) {
  mpfr_set(v_, o.v_, MPFR_RNDN);
}
Mpfr_number::Mpfr_number(Mpfr_number&& o) noexcept : Mpfr_number(Uninitialised{}, MPFR_PREC_MIN) {
  mpfr_swap(v_, o.v_);
}
Mpfr_number& Mpfr_number::operator=(const Mpfr_number& o) {
  if (this != &o) {
    mpfr_set_prec(v_, o.precision());
    mpfr_set(v_, o.v_, MPFR_RNDN);
  }
  return *this;
}
Mpfr_number& Mpfr_number::operator=(Mpfr_number&& o) noexcept {
  mpfr_swap(v_, o.v_);
  return *this;
}
Mpfr_number::~Mpfr_number() { mpfr_clear(v_); }

std::string Mpfr_number::to_string(int digits) const {
  const int n = mpfr_snprintf(nullptr, 0, "%.*Re", digits - 1, v_);
  std::vector<char> buf(static_cast<std::size_t>(n) + 1);
  mpfr_snprintf(buf.data(), buf.size(), "%.*Re", digits - 1, v_);
  return std::string(buf.data());
}

// Results are rounded to the default precision, not to the operands'.
#define KVD_MPFR_COMPOUND(op, fn)                                \
  Mpfr_number& Mpfr_number::operator op(const Mpfr_number& o) {  \
    Mpfr_number r(Uninitialised{}, current_precision);          \
    fn(r.v_, v_, o.v_, MPFR_RNDN);                               \
    return *this = std::move(r);                                 \
  }
KVD_MPFR_COMPOUND(+=, mpfr_add)
KVD_MPFR_COMPOUND(-=, mpfr_sub)
KVD_MPFR_COMPOUND(*=, mpfr_mul)
KVD_MPFR_COMPOUND(/=, mpfr_div)
#undef KVD_MPFR_COMPOUND

Mpfr_number Mpfr_number::operator-() const {
  Mpfr_number r(Uninitialised{}, current_precision);
  mpfr_neg(r.v_, v_, MPFR_RNDN);
  return r;
}

Mpfr_number abs(const Mpfr_number& x) { return sign(x) < 0 ? -x : x; }

}  // namespace kvd
