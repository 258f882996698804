// A square-freeness certificate by reduction modulo primes.
//
// Let g = gcd(p, p') in Z[t], primitive. By Gauss's lemma g divides p in
// Z[t], so lc(g) divides lc(p); for a prime m not dividing lc(p), the
// reduction of g keeps its degree and divides the reductions of p and p'.
// Hence deg gcd(p mod m, p' mod m) >= deg g, and a constant gcd modulo m
// proves g constant: p is square-free. A non-constant gcd modulo m proves
// nothing (m may divide the discriminant), and the caller falls back to the
// exact gcd.
#include <cstdint>

#include "kvd/detail/kernel/zpoly.hpp"

namespace kvd::zpoly {

namespace {

using u64 = std::uint64_t;
using Residues = std::vector<u64>;

// Primes below 2^31, so that a product of two residues fits in 64 bits.
constexpr u64 primes[] = {2147483647u, 2147483629u, 2147483587u};

u64 power(u64 b, u64 e, u64 m) {
  u64 r = 1;
  for (; e; e >>= 1, b = b * b % m)
    if (e & 1) r = r * b % m;
  return r;
}

void trim(Residues& a) {
  while (!a.empty() && a.back() == 0) a.pop_back();
}

// The degree of gcd(a, b) over the field Z/m; -1 when both are zero.
int gcd_degree(Residues a, Residues b, u64 m) {
  trim(a);
  trim(b);
  while (!b.empty()) {
    // a <- a mod b
    const u64 inv = power(b.back(), m - 2, m);
    while (a.size() >= b.size()) {
      const u64 f = a.back() * inv % m;
      const std::size_t shift = a.size() - b.size();
      for (std::size_t j = 0; j < b.size(); ++j) a[shift + j] = (a[shift + j] + (m - f) * b[j]) % m;
      trim(a);
    }
    std::swap(a, b);
  }
  return static_cast<int>(a.size()) - 1;
}

}  // namespace

bool certainly_square_free(const ZPoly& p) {
  if (degree(p) <= 1) return true;
  for (const u64 m : primes) {
    Residues r(p.size()), d(p.size() - 1);
    for (std::size_t i = 0; i < p.size(); ++i) r[i] = mpz_fdiv_ui(p[i].get_mpz_t(), m);
    if (r.back() == 0) continue;  // m divides the leading coefficient
    for (std::size_t i = 1; i < p.size(); ++i) d[i - 1] = r[i] * (i % m) % m;
    if (gcd_degree(r, d, m) == 0) return true;
  }
  return false;
}

}  // namespace kvd::zpoly
