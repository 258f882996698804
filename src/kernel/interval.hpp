// Certified interval arithmetic on doubles (Boost.Interval), the exact
// kernel's floating-point filter: a sign is decided only when the interval
// excludes zero, and then it is the exact sign.
//
// Interval assumes the processor rounds upward (rounded_arith_opp: a lower
// bound is computed as the negated upper bound of the negated operation), so
// arithmetic on it happens only inside a Rounding_scope, and only in
// translation units compiled with -frounding-math (CMakeLists.txt lists them),
// so that the compiler neither folds nor reorders across the rounding mode.
#pragma once

#include <gmpxx.h>

#include <optional>
#include <span>
#include <vector>

#include <boost/numeric/interval.hpp>

#if defined(__SSE2_MATH__)
#include <xmmintrin.h>

#include <cmath>
#endif

#include "kvd/kernel/exact_time.hpp"
#include "kvd/kernel/poly.hpp"

namespace kvd::filter {

namespace bi = boost::numeric::interval_lib;

#if defined(__SSE2_MATH__)
// Where double arithmetic is SSE2's (x86-64), the rounding mode is MXCSR's
// alone, and a result has no excess precision to strip. Boost's C99 control
// goes through fesetround, which also writes the x87 control word, and
// stores every result to a volatile; this one sets MXCSR, and only when it
// changes (a scope inside a scope reads MXCSR and writes nothing).
struct Rounding_control {
  using rounding_mode = unsigned int;
  static constexpr unsigned int mask = 0x6000;  // MXCSR's rounding-control bits
  static void get_rounding_mode(rounding_mode& m) { m = _mm_getcsr(); }
  static void set_rounding_mode(rounding_mode m) {
    if (_mm_getcsr() != m) _mm_setcsr(m);
  }
  static void set_bits(unsigned int bits) { set_rounding_mode((_mm_getcsr() & ~mask) | bits); }
  static void to_nearest() { set_bits(0x0000); }
  static void downward() { set_bits(0x2000); }
  static void upward() { set_bits(0x4000); }
  static void toward_zero() { set_bits(0x6000); }
  static double force_rounding(const double& r) { return r; }
  static double to_int(const double& r) { return std::nearbyint(r); }
};
#else
using Rounding_control = bi::rounding_control<double>;
#endif
using Rounded = bi::rounded_arith_opp<double, Rounding_control>;
using Interval =
    boost::numeric::interval<double, bi::policies<bi::save_state_nothing<Rounded>, bi::checking_no_nan<double>>>;
// Upward rounding for its lifetime; the caller's mode is restored after.
using Rounding_scope = bi::save_state<Rounded>;

// Inputs of magnitude above 2^64 are not filtered. Below it no expression the
// filter evaluates can overflow: the deepest, a classification value, has
// degree 12 in the coordinates at t and fewer than 2^30 terms, which stays
// below 2^800. So no bound is ever infinite, and no NaN can arise.
inline constexpr double max_input = 18446744073709551616.0;  // 2^64

// The sign of every number in x, or 0 when x holds zero.
inline int sign(const Interval& x) { return x.lower() > 0 ? 1 : (x.upper() < 0 ? -1 : 0); }

// A double interval holding q times 2^-shift (exactly), or none when that
// exceeds max_input: the point where that is a double, else the interval
// one ulp wide that holds it. Call outside a Rounding_scope (GMP converts).
std::optional<Interval> enclose(const mpq_class& q, unsigned long shift = 0);
// A double interval holding the instant: its value, or its isolating
// interval once refined to a relative width of about 2^-50.
std::optional<Interval> enclose(const Exact_time& t);
// The coefficients of p times 2^-shift (exactly) as intervals, lowest degree
// first; none when one is too large. A positive scale keeps every sign.
std::optional<std::vector<Interval>> enclose(const Poly<mpq_class>& p, unsigned long shift = 0);
// A shift that brings every coefficient of the polynomials within 2^50
// (the least, or one more), well inside max_input; values at an instant are
// still checked.
// The exact kernel's integer coordinates (scene_geometry.cpp) give points,
// planes and certificate polynomials coefficients beyond 2^64; a point or
// a plane takes one shift for its four polynomials, so that its dots keep
// their signs and their ratios.
unsigned long shift_for(std::span<const Poly<mpq_class>> polys);

// p(t) by Horner's rule, inside a Rounding_scope; none if a partial value
// overflows (checked at every step: finite operands give no NaN).
std::optional<Interval> evaluate(const std::vector<Interval>& p, const Interval& t);
// The sign of p at the instant t decided by intervals, or 0 when undecided.
int sign_at(const Poly<mpq_class>& p, const Exact_time& t);

}  // namespace kvd::filter
