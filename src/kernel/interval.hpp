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

#include "kvd/kernel/exact_time.hpp"
#include "kvd/kernel/poly.hpp"

namespace kvd::filter {

namespace bi = boost::numeric::interval_lib;
using Interval =
    boost::numeric::interval<double, bi::policies<bi::save_state_nothing<bi::rounded_arith_opp<double>>,
                                                  bi::checking_no_nan<double>>>;
// Upward rounding for its lifetime; the caller's mode is restored after.
using Rounding_scope = bi::save_state<bi::rounded_arith_opp<double>>;

// Inputs of magnitude above 2^64 are not filtered. Below it no expression the
// filter evaluates can overflow: the deepest, a classification value, has
// degree 12 in the coordinates at t and fewer than 2^30 terms, which stays
// below 2^800. So no bound is ever infinite, and no NaN can arise.
inline constexpr double max_input = 18446744073709551616.0;  // 2^64

// The sign of every number in x, or 0 when x holds zero.
inline int sign(const Interval& x) { return x.lower() > 0 ? 1 : (x.upper() < 0 ? -1 : 0); }

// A double interval holding q, or none when |q| exceeds max_input. Call
// outside a Rounding_scope (GMP converts).
std::optional<Interval> enclose(const mpq_class& q);
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
