// The kernel concept (DESIGN.md section 3) and its three models.
//
// A kernel K provides
//   K::FT    a field of coefficients,
//   K::Poly  polynomials in time over FT (kvd::Poly<FT>),
//   K::Time  an instant on the time line,
// and, on a const K:
//   sign(FT)                -1, 0 or +1; the kernel decides what counts as zero;
//   time(FT)                the instant with that value;
//   compare(Time, Time)     -1, 0 or +1;
//   sign_at(Poly, Time)     the sign of p at t;
//   sign_after(Poly, Time)  the sign of p on (t, t + delta) for small delta;
//   next_root(Poly, Time)   the smallest sign-changing root strictly after t;
//   to_double, to_string    for reports.
//
// To add a kernel: write a class with these members (a floating-point one can
// derive from Float_kernel<FT>), add `static_assert(Kernel<...>)` below, and
// add it to the instantiation lists in src/ (KVD_FOR_EACH_KERNEL in
// kvd/detail/kernel/instantiate.hpp) so that the templates above the kernel are
// compiled for it once.
#pragma once

#include <concepts>
#include <optional>
#include <string>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kernel/float_kernel.hpp"

namespace kvd {

template <class K>
concept Kernel = requires(const K k, const typename K::FT a, const typename K::Poly p,
                          const typename K::Time t) {
  requires std::same_as<typename K::Poly, Poly<typename K::FT>>;
  { k.sign(a) } -> std::same_as<int>;
  { k.time(a) } -> std::same_as<typename K::Time>;
  { k.compare(t, t) } -> std::same_as<int>;
  { k.sign_at(p, t) } -> std::same_as<int>;
  { k.sign_after(p, t) } -> std::same_as<int>;
  { k.next_root(p, t) } -> std::same_as<std::optional<typename K::Time>>;
  { k.to_double(t) } -> std::same_as<double>;
  { k.to_string(t) } -> std::same_as<std::string>;
  { K::name } -> std::convertible_to<const char*>;
};

static_assert(Kernel<Exact_kernel>);
static_assert(Kernel<Double_kernel>);
static_assert(Kernel<Mpfr_kernel>);

}  // namespace kvd
