// The first sign-changing root after the current instant of each
// polynomial a run meets, kept while it still lies ahead: a certificate
// that stays in force, or comes back with the same polynomial, costs no new
// root isolation. In the exact kernel only polynomials of degree 3 and more
// are kept. They are kept in two generations: when the newer holds as many
// as the owner has certificates in force (at least 2^16 by default), the
// older is dropped and the newer becomes the older, and a polynomial found
// in the older moves to the newer. So the cache holds at most about twice
// the certificates in force, not every polynomial of the run (which grew
// without end on long runs).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <optional>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "kvd/kernel/mpfr_number.hpp"

namespace kvd::kinetic {

// A hash of a polynomial's coefficients; equal coefficients (exactly equal
// numbers) hash alike.
struct Coefficients_hash {
  static std::size_t of(const mpq_class& x) {
    std::size_t h = 0;
    for (const mpz_srcptr z : {mpq_numref(x.get_mpq_t()), mpq_denref(x.get_mpq_t())}) {
      h = h * 31 + static_cast<std::size_t>(mpz_sgn(z) + 1);
      for (std::size_t i = 0, n = mpz_size(z); i < n; ++i) h = h * 0x9e3779b97f4a7c15ULL + mpz_getlimbn(z, i);
    }
    return h;
  }
  static std::size_t of(double x) { return std::hash<double>()(x); }
  static std::size_t of(const Mpfr_number& x) { return std::hash<double>()(x.to_double()); }
  template <class FT>
  std::size_t operator()(const std::vector<FT>& c) const {
    std::size_t h = c.size();
    for (const FT& x : c) h = h * 1000003 ^ of(x);
    return h;
  }
};

template <class K>
class Root_cache {
  using Time = typename K::Time;

public:
  // `least`: the generation's size with fewer certificates in force.
  explicit Root_cache(std::size_t least = std::size_t{1} << 16) : least_(least), generation_(least) {}

  // The owner's certificates in force, which sets a generation's size.
  void bound(std::size_t in_force) { generation_ = std::max(in_force, least_); }
  std::size_t size() const { return newer_.size() + older_.size(); }

  const std::optional<Time>& next_root(const K& k, const typename K::Poly& q, const Time& now) {
    // The exact kernel has closed forms for degrees 1 and 2
    // (src/kernel/exact_kernel.cpp), cheaper than the lookup and the copy of
    // the coefficients an entry costs; the floating-point ones bisect.
    if constexpr (std::is_same_v<typename K::FT, mpq_class>)
      if (q.degree() < 3) return uncached_ = k.next_root(q, now);
    auto it = newer_.find(q.coefficients());
    if (it == newer_.end()) {
      if (newer_.size() >= generation_) older_ = std::exchange(newer_, {});
      if (auto kept = older_.extract(q.coefficients())) it = newer_.insert(std::move(kept)).position;
    }
    if (it == newer_.end() || (it->second && k.compare(*it->second, now) <= 0))
      it = newer_.insert_or_assign(q.coefficients(), k.next_root(q, now)).first;
    return it->second;
  }

  // The earliest of the polynomials' next roots after now.
  std::optional<Time> first_root(const K& k, const std::vector<typename K::Poly>& polys, const Time& now) {
    std::optional<Time> first;
    for (const auto& q : polys) {
      const auto& r = next_root(k, q, now);
      if (r && (!first || k.compare(*r, *first) < 0)) first = r;
    }
    return first;
  }
  // The earliest of the certificate's polynomials' next roots after now.
  template <class Certificate>
  std::optional<Time> fails(const K& k, const Certificate& cert, const Time& now) {
    return first_root(k, cert.polys, now);
  }

private:
  using Roots = std::unordered_map<std::vector<typename K::FT>, std::optional<Time>, Coefficients_hash>;
  Roots newer_, older_;
  std::size_t least_, generation_;
  std::optional<Time> uncached_;  // the last root not cached, which next_root returns
};

}  // namespace kvd::kinetic
