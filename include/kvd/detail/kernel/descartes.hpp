// Real-root isolation of square-free integer polynomials by Descartes' rule of
// signs with bisection (the Vincent–Collins–Akritas method).
#pragma once

#include <functional>

#include "kvd/kernel/exact_time.hpp"

namespace kvd {

// Visits the real roots of the square-free polynomial q lying in the open
// interval (lo, hi), in increasing order, each as an exact time with an
// isolating interval. Stops as soon as `visit` returns true, and then returns
// true; returns false when every root was visited.
bool isolate_real_roots(const zpoly::ZPoly& q, const mpq_class& lo, const mpq_class& hi,
                        const std::function<bool(const Exact_time&)>& visit);

}  // namespace kvd
