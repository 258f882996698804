// Floating-point real roots, for the floating-point kernels only.
//
// Between two consecutive sign changes of p' the polynomial p is monotone, so
// its sign-changing roots are found by recursion on the derivative and
// bisection inside each monotone piece. The method does no tolerance test of
// its own: a double root perturbed by rounding into two close simple roots is
// reported as two roots, which is exactly the behaviour the floating-point
// build exists to expose.
#pragma once

#include <vector>

#include "kvd/kernel/poly.hpp"

namespace kvd {

// Roots of p in the open interval (lo, hi) at which the computed values of p
// change sign, in increasing order.
template <class FT>
std::vector<FT> sign_change_roots(const Poly<FT>& p, const FT& lo, const FT& hi);

// A value larger than the absolute value of every root (Cauchy's bound,
// computed in FT).
template <class FT>
FT cauchy_bound(const Poly<FT>& p);

}  // namespace kvd
