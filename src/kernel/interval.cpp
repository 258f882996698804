#include "interval.hpp"

#include <algorithm>
#include <cmath>

namespace kvd::filter {

namespace {

// q times 2^-shift, exactly, as an interval; none beyond max_input.
std::optional<Interval> enclose_exactly(const mpq_class& q, unsigned long shift) {
  mpq_class scaled;
  if (shift) mpq_div_2exp(scaled.get_mpq_t(), q.get_mpq_t(), shift);
  const mpq_class& x = shift ? scaled : q;
  const double d = x.get_d();  // truncated toward zero
  if (!(std::fabs(d) <= max_input)) return std::nullopt;
  const int c = cmp(x, d);
  if (c == 0) return Interval(d, d);
  return c > 0 ? Interval(d, std::nextafter(d, HUGE_VAL)) : Interval(std::nextafter(d, -HUGE_VAL), d);
}

}  // namespace

// Without arithmetic on rationals where the double range allows: mpq_get_d
// truncates toward zero, so a nonzero q lies within one ulp of it on the far
// side from zero, and that ulp scales by 2^-shift exactly while the values
// stay normal doubles. Elsewhere (magnitudes near the ends of the double range) the exact path.
std::optional<Interval> enclose(const mpq_class& q, unsigned long shift) {
  const int s = sgn(q);
  if (s == 0) return Interval(0.0, 0.0);
  const mpz_srcptr num = q.get_num_mpz_t(), den = q.get_den_mpz_t();
  const long bits = static_cast<long>(mpz_sizeinbase(num, 2)) - static_cast<long>(mpz_sizeinbase(den, 2));
  if (bits > 1000 || bits < -900 || bits - static_cast<long>(shift) < -900) return enclose_exactly(q, shift);
  const double d = std::ldexp(q.get_d(), -static_cast<int>(shift));
  if (!(std::fabs(d) <= max_input)) return std::nullopt;
  // q is a double exactly (d, scaled exactly) when its denominator is a
  // power of two and its numerator has at most 53 significant bits.
  if (mpz_popcount(den) == 1 && mpz_sizeinbase(num, 2) - mpz_scan1(num, 0) <= 53) return Interval(d, d);
  return s > 0 ? Interval(d, std::nextafter(d, HUGE_VAL)) : Interval(std::nextafter(d, -HUGE_VAL), d);
}

std::optional<Interval> enclose(const Exact_time& t) {
  if (t.is_rational()) return enclose(t.rational());
  // Refinement is exact and shared by every copy of t, so it is paid once.
  for (int i = 0; i < 60 && !t.is_rational(); ++i) {
    mpq_class w = t.upper() - t.lower();
    w <<= 50;
    if (w <= abs(t.lower()) || w <= abs(t.upper())) break;
    t.refine();
  }
  if (t.is_rational()) return enclose(t.rational());
  const auto lo = enclose(t.lower()), hi = enclose(t.upper());
  if (!lo || !hi) return std::nullopt;
  return Interval(lo->lower(), hi->upper());
}

std::optional<std::vector<Interval>> enclose(const Poly<mpq_class>& p, unsigned long shift) {
  std::vector<Interval> r;
  r.reserve(p.coefficients().size());
  for (const mpq_class& c : p.coefficients()) {
    const auto x = enclose(c, shift);
    if (!x) return std::nullopt;
    r.push_back(*x);
  }
  return r;
}

unsigned long shift_for(std::span<const Poly<mpq_class>> polys) {
  long most = 0;  // |c| < 2^(bits(num) - bits(den) + 1)
  for (const Poly<mpq_class>& p : polys)
    for (const mpq_class& c : p.coefficients())
      if (sgn(c) != 0)
        most = std::max(most, static_cast<long>(mpz_sizeinbase(c.get_num_mpz_t(), 2)) -
                                  static_cast<long>(mpz_sizeinbase(c.get_den_mpz_t(), 2)) + 1);
  return most > 50 ? static_cast<unsigned long>(most - 50) : 0;
}

std::optional<Interval> evaluate(const std::vector<Interval>& p, const Interval& t) {
  Interval v(0.0, 0.0);
  for (auto c = p.rbegin(); c != p.rend(); ++c) {
    v = v * t + *c;
    if (!std::isfinite(v.lower()) || !std::isfinite(v.upper())) return std::nullopt;
  }
  return v;
}

int sign_at(const Poly<mpq_class>& p, const Exact_time& t) {
  const auto x = enclose(t);
  const auto c = enclose(p, shift_for({&p, 1}));
  if (!x || !c) return 0;
  const Rounding_scope upward;
  const auto v = evaluate(*c, *x);
  return v ? sign(*v) : 0;
}

}  // namespace kvd::filter
