// Integer polynomials (Z[t]) for the exact kernel's real-root machinery.
//
// A rational polynomial enters this layer through `to_zpoly`, which multiplies
// it by a positive rational: the integer polynomial has the same roots and the
// same sign as the original at every point, which is what sign_at and
// sign_after need.
#pragma once

#include <gmpxx.h>

#include <optional>
#include <vector>

#include "kvd/kernel/poly.hpp"

namespace kvd::zpoly {

using ZPoly = std::vector<mpz_class>;  // c0 + c1 t + ..., trimmed (last entry non-zero)

// A positive multiple of p with integer coefficients and content 1 (same signs
// as p everywhere).
ZPoly to_zpoly(const Poly<mpq_class>& p);
Poly<mpq_class> to_poly(const ZPoly& p);

int degree(const ZPoly& p);
void trim(ZPoly& p);
// Divides by the content; keeps the sign of the values.
void make_primitive(ZPoly& p);
ZPoly derivative(const ZPoly& p);
ZPoly sub(const ZPoly& a, const ZPoly& b);
ZPoly mul(const ZPoly& a, const ZPoly& b);
// a / b where b divides a in Q[t] and b is primitive (so the quotient is in Z[t]).
ZPoly div_exact(const ZPoly& a, const ZPoly& b);
// Primitive gcd with positive leading coefficient; gcd(0, 0) = 0.
ZPoly gcd(ZPoly a, ZPoly b);
// True only if p has no repeated root: a constant gcd(p, p') modulo a prime
// (src/kernel/zpoly_modular.cpp). False proves nothing.
bool certainly_square_free(const ZPoly& p);
// p / gcd(p, p'): every root of p, each simple.
ZPoly square_free(const ZPoly& p);
// The product of the factors of odd multiplicity (Yun's square-free
// decomposition): exactly the roots where p changes sign, each simple.
ZPoly odd_part(const ZPoly& p);

// Sign of p(x) for a rational x, computed with integers only.
int sign_at(const ZPoly& p, const mpq_class& x);
// The same for a rational polynomial whose coefficients are all integers
// (checked: none when one is not), read in place with no conversion.
std::optional<int> sign_at_integral(const Poly<mpq_class>& p, const mpq_class& x);
// c^n p((a + b t) / c), n = degree(p): the substitution used by Descartes' rule.
ZPoly compose_linear(const ZPoly& p, const mpz_class& a, const mpz_class& b, const mpz_class& c);
// The sign variations of the coefficients, zeros skipped.
int variations(const ZPoly& p);
// In place: p(t) -> p(t + 1) (Taylor shift, O(n^2) additions).
void taylor_shift_one(ZPoly& p);
// Descartes' bound on the number of roots in the open interval (lo, hi): the
// sign variations of (1+t)^n p((lo + hi t) / (1 + t)). Exact when 0 or 1; zero
// proves there is no root there.
int descartes_bound(const ZPoly& p, const mpq_class& lo, const mpq_class& hi);
// A rational strictly larger than the absolute value of every complex root
// (Fujiwara's bound, rounded up to a power of two).
mpq_class root_bound(const ZPoly& p);

}  // namespace kvd::zpoly
