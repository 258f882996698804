// The lists of types that src/ compiles the templates for, once each.
#pragma once

#include <gmpxx.h>

#include "kvd/kernel/mpfr_number.hpp"
#include "kvd/kernel/poly.hpp"

// X(FT) for the coefficient field of every kernel.
#define KVD_FOR_EACH_FIELD(X) \
  X(mpq_class)                \
  X(double)                   \
  X(kvd::Mpfr_number)

// X(R) for every ring the geometry runs over: the fields and their
// polynomials (positions at an instant, and motions).
#define KVD_FOR_EACH_RING(X) \
  KVD_FOR_EACH_FIELD(X)      \
  X(kvd::Poly<mpq_class>)    \
  X(kvd::Poly<double>)       \
  X(kvd::Poly<kvd::Mpfr_number>)

// X(R) for the rings of the symbolic perturbation: polynomials in ε whose
// coefficients are polynomials in t (DESIGN.md section 4, rule 4).
#define KVD_FOR_EACH_PERTURBED_RING(X)  \
  X(kvd::Poly<kvd::Poly<mpq_class>>)    \
  X(kvd::Poly<kvd::Poly<double>>)       \
  X(kvd::Poly<kvd::Poly<kvd::Mpfr_number>>)

// X(K) for every kernel.
#define KVD_FOR_EACH_KERNEL(X) \
  X(kvd::Exact_kernel)         \
  X(kvd::Double_kernel)        \
  X(kvd::Mpfr_kernel)
