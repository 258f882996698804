// A value type over mpfr_t whose precision is given in bits at run time.
//
// Every number made by arithmetic or conversion gets the current thread's
// default precision (`Mpfr_number::set_default_precision`, which
// Mpfr_kernel's constructor calls); a copy keeps the precision of its source.
// All operations round to nearest. Wrappers that take precision in decimal
// digits cannot express "exactly 64 bits", which the error-versus-precision
// experiments need; hence this small wrapper over mpfr_t itself.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <string>

namespace kvd {

class Mpfr_number {
public:
  static mpfr_prec_t default_precision();
  static void set_default_precision(mpfr_prec_t bits);

  Mpfr_number() : Mpfr_number(0L) {}
  Mpfr_number(int v) : Mpfr_number(static_cast<long>(v)) {}  // NOLINT: numeric conversions are implicit
  Mpfr_number(long v);                                      // NOLINT
  Mpfr_number(double v);                                    // NOLINT
  explicit Mpfr_number(const mpq_class& v);
  Mpfr_number(const Mpfr_number& o);
  Mpfr_number(Mpfr_number&& o) noexcept;
  Mpfr_number& operator=(const Mpfr_number& o);
  Mpfr_number& operator=(Mpfr_number&& o) noexcept;
  ~Mpfr_number();

  mpfr_prec_t precision() const { return mpfr_get_prec(v_); }
  mpfr_srcptr get() const { return v_; }
  double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }
  // Scientific notation with `digits` significant decimal digits.
  std::string to_string(int digits = 17) const;

  Mpfr_number operator-() const;
  Mpfr_number& operator+=(const Mpfr_number& o);
  Mpfr_number& operator-=(const Mpfr_number& o);
  Mpfr_number& operator*=(const Mpfr_number& o);
  Mpfr_number& operator/=(const Mpfr_number& o);

  friend Mpfr_number operator+(Mpfr_number a, const Mpfr_number& b) { return a += b; }
  friend Mpfr_number operator-(Mpfr_number a, const Mpfr_number& b) { return a -= b; }
  friend Mpfr_number operator*(Mpfr_number a, const Mpfr_number& b) { return a *= b; }
  friend Mpfr_number operator/(Mpfr_number a, const Mpfr_number& b) { return a /= b; }
  friend bool operator==(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_equal_p(a.v_, b.v_); }
  friend bool operator!=(const Mpfr_number& a, const Mpfr_number& b) { return !(a == b); }
  friend bool operator<(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_less_p(a.v_, b.v_); }
  friend bool operator>(const Mpfr_number& a, const Mpfr_number& b) { return b < a; }
  friend bool operator<=(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_lessequal_p(a.v_, b.v_); }
  friend bool operator>=(const Mpfr_number& a, const Mpfr_number& b) { return b <= a; }

private:
  struct Uninitialised {};
  explicit Mpfr_number(Uninitialised, mpfr_prec_t bits) { mpfr_init2(v_, bits); }
  mpfr_t v_;
};

inline int sign(const Mpfr_number& x) { return mpfr_sgn(x.get()); }
Mpfr_number abs(const Mpfr_number& x);

}  // namespace kvd
