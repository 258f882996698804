// Polynomials in time t over a coefficient field FT: c0 + c1 t + ... + cn t^n.
//
// The coefficient vector is always trimmed: its last entry is non-zero, and
// the zero polynomial has no coefficients (degree -1). "Zero" here is the
// exact zero of FT (c == 0): a polynomial is an arithmetic value, and what a
// floating-point kernel treats as negligibly small is the kernel's decision,
// not the container's.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <initializer_list>
#include <type_traits>
#include <utility>
#include <vector>

namespace kvd {

namespace detail {
// Rational polynomials whose coefficients are all integers (those the exact
// kernel builds from its integer coordinates) multiplied and added on the
// numerators alone: no gcd, no temporary. False, with `out` unspecified,
// when a coefficient is not an integer (src/kernel/poly_integer.cpp).
bool integer_product(const std::vector<mpq_class>& a, const std::vector<mpq_class>& b, std::vector<mpq_class>& out);
// a += b (or -= b), for a at least as long as b.
bool integer_add(std::vector<mpq_class>& a, const std::vector<mpq_class>& b, bool subtract);
}  // namespace detail

template <class FT>
class Poly {
public:
  using Coefficient = FT;

  Poly() = default;
  Poly(const FT& c) : c_{c} { trim(); }  // NOLINT: constants convert implicitly
  Poly(int c) : c_{FT(c)} { trim(); }    // NOLINT
  Poly(std::initializer_list<FT> c) : c_(c) { trim(); }
  explicit Poly(std::vector<FT> c) : c_(std::move(c)) { trim(); }

  // The monomial c * t^k.
  static Poly monomial(const FT& c, int k) {
    std::vector<FT> v(static_cast<std::size_t>(k) + 1, FT(0));
    v.back() = c;
    return Poly(std::move(v));
  }

  // -1 for the zero polynomial.
  int degree() const { return static_cast<int>(c_.size()) - 1; }
  bool is_zero() const { return c_.empty(); }
  // Coefficient of t^i (zero past the degree).
  FT operator[](int i) const {
    return (i >= 0 && i < static_cast<int>(c_.size())) ? c_[static_cast<std::size_t>(i)] : FT(0);
  }
  const FT& leading() const { return c_.back(); }
  const std::vector<FT>& coefficients() const { return c_; }

  // Horner evaluation; works for any R that FT converts into (numbers, or
  // another polynomial for composition).
  FT operator()(const FT& t) const {
    FT r(0);
    for (auto it = c_.rbegin(); it != c_.rend(); ++it) r = r * t + *it;
    return r;
  }

  Poly derivative() const {
    std::vector<FT> d;
    for (std::size_t i = 1; i < c_.size(); ++i) d.push_back(c_[i] * FT(static_cast<long>(i)));
    return Poly(std::move(d));
  }

  Poly operator-() const {
    Poly r(*this);
    for (auto& x : r.c_) x = -x;
    return r;
  }
  Poly& operator+=(const Poly& o) { return add(o, false); }
  Poly& operator-=(const Poly& o) { return add(o, true); }
  Poly& operator*=(const Poly& o) { return *this = *this * o; }

  friend Poly operator+(Poly a, const Poly& b) { return a += b; }
  friend Poly operator-(Poly a, const Poly& b) { return a -= b; }
  friend Poly operator*(const Poly& a, const Poly& b) {
    if (a.is_zero() || b.is_zero()) return Poly();
    if constexpr (std::is_same_v<FT, mpq_class>) {
      std::vector<FT> r;
      if (detail::integer_product(a.c_, b.c_, r)) return Poly(std::move(r));
    }
    std::vector<FT> r(a.c_.size() + b.c_.size() - 1, FT(0));
    for (std::size_t i = 0; i < a.c_.size(); ++i)
      for (std::size_t j = 0; j < b.c_.size(); ++j) r[i + j] += a.c_[i] * b.c_[j];
    return Poly(std::move(r));
  }
  friend bool operator==(const Poly& a, const Poly& b) { return a.c_ == b.c_; }
  friend bool operator!=(const Poly& a, const Poly& b) { return !(a == b); }

private:
  Poly& add(const Poly& o, bool subtract) {
    if (o.c_.size() > c_.size()) c_.resize(o.c_.size(), FT(0));
    bool done = false;
    if constexpr (std::is_same_v<FT, mpq_class>) done = detail::integer_add(c_, o.c_, subtract);
    if (!done)
      for (std::size_t i = 0; i < o.c_.size(); ++i) subtract ? c_[i] -= o.c_[i] : c_[i] += o.c_[i];
    trim();
    return *this;
  }
  void trim() {
    while (!c_.empty() && c_.back() == FT(0)) c_.pop_back();
  }
  std::vector<FT> c_;
};

// Compiled once in src/kernel/poly_instances.cpp (Poly<Mpfr_number>: see
// float_kernel.hpp).
extern template class Poly<mpq_class>;
extern template class Poly<double>;

}  // namespace kvd
