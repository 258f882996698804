// The independent reference for real roots: CGAL's Algebraic_kernel_d_1.
//
// Used only by tests and benchmarks, never by the library: the exact kernel
// has its own isolator, and this is what it is checked against. CGAL's
// algebraic kernel compiles slowly, so it lives in one translation unit
// (cgal_roots.cpp) behind this interface.
#pragma once

#include <gmpxx.h>

#include <memory>
#include <optional>
#include <vector>

namespace kvd::oracle {

class Cgal_roots {
public:
  // All real roots of the non-zero integer polynomial c0 + c1 t + ...,
  // increasing, with their multiplicities.
  explicit Cgal_roots(const std::vector<mpz_class>& coefficients);
  ~Cgal_roots();
  Cgal_roots(Cgal_roots&&) noexcept;
  Cgal_roots& operator=(Cgal_roots&&) noexcept;

  std::size_t size() const;
  int multiplicity(std::size_t i) const;
  // Root i compared with the rational r: -1, 0 or +1.
  int compare(std::size_t i, const mpq_class& r) const;
  // Root i compared with the unique root of the square-free q in (lo, hi).
  int compare(std::size_t i, const std::vector<mpz_class>& q, const mpq_class& lo,
              const mpq_class& hi) const;
  // The sign of the integer polynomial f at root i.
  int sign_at(std::size_t i, const std::vector<mpz_class>& f) const;
  // The first root of odd multiplicity greater than r, by CGAL's comparisons.
  std::optional<std::size_t> next_sign_change_after(const mpq_class& r) const;
  // The first root of odd multiplicity greater than root j.
  std::optional<std::size_t> next_sign_change_after_root(std::size_t j) const;
  // A double approximation of root i.
  double to_double(std::size_t i) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace kvd::oracle
