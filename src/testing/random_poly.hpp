// Deterministic random integer polynomials for tests and benchmarks, including
// the hard families of root isolation: repeated factors and root clusters.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <vector>

#include "kvd/detail/kernel/zpoly.hpp"

namespace kvd::testing {

class Random_polys {
public:
  explicit Random_polys(std::uint64_t seed);

  // A uniformly random integer in [0, n).
  unsigned long below(unsigned long n);
  // A random signed integer of at most `bits` bits.
  mpz_class integer(unsigned long bits);
  // A random rational with numerator and denominator of at most `bits` bits.
  mpq_class rational(unsigned long bits);

  // Degree exactly `degree`, coefficients of at most `bits` bits.
  zpoly::ZPoly dense(int degree, unsigned long bits);
  // f1 * f2^2 * f3^3 with random factors, the three together of degree at most
  // `max_degree`: roots of multiplicity 1, 2 and 3.
  zpoly::ZPoly repeated_factors(int max_degree, unsigned long bits);
  // prod_i (2^shift t - a - i) for i < count, times a random factor: `count`
  // rational roots 2^-shift apart (shift = 110 puts them 7.7e-34 apart).
  zpoly::ZPoly cluster(int count, unsigned long shift, int extra_degree, unsigned long bits);
  // A polynomial of degree at most `max_degree` with the rational root r.
  zpoly::ZPoly with_root(const mpq_class& r, int max_degree, unsigned long bits);

private:
  gmp_randclass gen_;
};

}  // namespace kvd::testing
