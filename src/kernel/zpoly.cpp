#include "kvd/detail/kernel/zpoly.hpp"

#include <algorithm>
#include <cassert>
#include <cstdlib>

namespace kvd::zpoly {

int degree(const ZPoly& p) { return static_cast<int>(p.size()) - 1; }

void trim(ZPoly& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}

void make_primitive(ZPoly& p) {
  trim(p);
  if (p.empty()) return;
  mpz_class g = 0;
  for (const auto& c : p) {
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
    if (g == 1) return;
  }
  for (auto& c : p) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
}

ZPoly to_zpoly(const Poly<mpq_class>& p) {
  mpz_class l = 1;
  for (const auto& c : p.coefficients()) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  ZPoly r;
  r.reserve(p.coefficients().size());
  for (const auto& c : p.coefficients()) r.push_back(c.get_num() * (l / c.get_den()));
  make_primitive(r);
  return r;
}

Poly<mpq_class> to_poly(const ZPoly& p) {
  std::vector<mpq_class> c(p.begin(), p.end());
  return Poly<mpq_class>(std::move(c));
}

ZPoly derivative(const ZPoly& p) {
  ZPoly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * static_cast<unsigned long>(i));
  trim(d);
  return d;
}

ZPoly sub(const ZPoly& a, const ZPoly& b) {
  ZPoly r(std::max(a.size(), b.size()), mpz_class(0));
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] -= b[i];
  trim(r);
  return r;
}

ZPoly mul(const ZPoly& a, const ZPoly& b) {
  if (a.empty() || b.empty()) return {};
  ZPoly r(a.size() + b.size() - 1, mpz_class(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

ZPoly div_exact(const ZPoly& a, const ZPoly& b) {
  assert(!b.empty());
  if (a.size() < b.size()) return {};
  ZPoly rem = a;
  ZPoly q(a.size() - b.size() + 1, mpz_class(0));
  const mpz_class& lb = b.back();
  for (std::size_t k = q.size(); k-- > 0;) {
    mpz_class c;
    mpz_divexact(c.get_mpz_t(), rem[k + b.size() - 1].get_mpz_t(), lb.get_mpz_t());
    q[k] = c;
    if (c != 0)
      for (std::size_t j = 0; j < b.size(); ++j) rem[k + j] -= c * b[j];
  }
  return q;
}

// Pseudo-remainder of a by b: lc(b)^(deg a - deg b + 1) a mod b.
static ZPoly pseudo_remainder(ZPoly a, const ZPoly& b) {
  const int db = degree(b);
  const mpz_class& lb = b.back();
  while (degree(a) >= db) {
    const int shift = degree(a) - db;
    const mpz_class la = a.back();
    for (auto& c : a) c *= lb;
    for (int j = 0; j <= db; ++j) a[static_cast<std::size_t>(shift + j)] -= la * b[static_cast<std::size_t>(j)];
    trim(a);
  }
  return a;
}

ZPoly gcd(ZPoly a, ZPoly b) {
  make_primitive(a);
  make_primitive(b);
  if (degree(a) < degree(b)) std::swap(a, b);
  while (!b.empty()) {
    ZPoly r = pseudo_remainder(a, b);
    make_primitive(r);
    a = std::move(b);
    b = std::move(r);
  }
  if (!a.empty() && a.back() < 0)
    for (auto& c : a) c = -c;
  if (degree(a) == 0) a = {mpz_class(1)};
  return a;
}

ZPoly square_free(const ZPoly& p) {
  if (certainly_square_free(p)) return p;
  return div_exact(p, gcd(p, derivative(p)));
}

ZPoly odd_part(const ZPoly& p0) {
  ZPoly p = p0;
  make_primitive(p);
  if (degree(p) <= 0 || certainly_square_free(p)) return p;
  ZPoly dp = derivative(p);
  ZPoly c = gcd(p, dp);
  if (degree(c) == 0) return p;  // already square-free
  // Yun: p = f1 f2^2 f3^3 ...; w runs through f_i f_{i+1} ..., g through f_i.
  ZPoly w = div_exact(p, c);
  ZPoly y = div_exact(dp, c);
  ZPoly z = sub(y, derivative(w));
  ZPoly odd{mpz_class(1)};
  for (int i = 1; degree(w) > 0; ++i) {
    ZPoly g = gcd(w, z);
    if (i % 2 == 1) odd = mul(odd, g);
    w = div_exact(w, g);
    y = div_exact(z, g);
    z = sub(y, derivative(w));
  }
  make_primitive(odd);
  return odd;
}

namespace {

// p(n/d) d^deg = sum c_i n^i d^(deg-i), Horner in (n, d); d > 0 keeps the
// sign. c(i) is the integer coefficient of t^i, of `size` coefficients.
template <class Coefficient>
int horner_sign(std::size_t size, const Coefficient& c, const mpq_class& x) {
  if (size == 0) return 0;
  const mpz_class& n = x.get_num();
  const mpz_class& d = x.get_den();
  mpz_class acc = c(size - 1);
  mpz_class dpow = 1;
  for (std::size_t k = size - 1; k-- > 0;) {
    dpow *= d;
    acc = acc * n + c(k) * dpow;
  }
  return sgn(acc);
}

}  // namespace

int sign_at(const ZPoly& p, const mpq_class& x) {
  return horner_sign(p.size(), [&](std::size_t i) -> const mpz_class& { return p[i]; }, x);
}

std::optional<int> sign_at_integral(const Poly<mpq_class>& p, const mpq_class& x) {
  const auto& c = p.coefficients();
  if (!std::ranges::all_of(c, [](const mpq_class& q) { return q.get_den() == 1; })) return std::nullopt;
  return horner_sign(c.size(), [&](std::size_t i) -> const mpz_class& { return c[i].get_num(); }, x);
}

ZPoly compose_linear(const ZPoly& p, const mpz_class& a, const mpz_class& b, const mpz_class& c) {
  // R_n = p_n; R_k = R_{k+1} (a + b t) + p_k c^(n-k); the result is R_0.
  if (p.empty()) return {};
  ZPoly r{p.back()};
  mpz_class cpow = 1;
  for (std::size_t k = p.size() - 1; k-- > 0;) {
    cpow *= c;
    ZPoly next(r.size() + 1, mpz_class(0));
    for (std::size_t i = 0; i < r.size(); ++i) {
      next[i] += r[i] * a;
      next[i + 1] += r[i] * b;
    }
    next[0] += p[k] * cpow;
    r = std::move(next);
  }
  trim(r);
  return r;
}

int variations(const ZPoly& p) {
  int v = 0, last = 0;
  for (const auto& c : p) {
    const int s = sgn(c);
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}

void taylor_shift_one(ZPoly& q) {
  const std::size_t n = q.size();
  for (std::size_t i = 0; i + 1 < n; ++i)
    for (std::size_t j = n - 1; j-- > i;) q[j] += q[j + 1];
}

int descartes_bound(const ZPoly& p, const mpq_class& lo, const mpq_class& hi) {
  // x = lo + (hi - lo) s maps s in (0,1) to (lo,hi); with lo = a/c, hi - lo = b/c:
  const mpz_class c = lo.get_den() * hi.get_den();
  const mpz_class a = lo.get_num() * hi.get_den();
  const mpz_class b = hi.get_num() * lo.get_den() - a;
  ZPoly q = compose_linear(p, a, b, c);
  // (1+t)^n q(1/(1+t)): reverse, then shift by one.
  q.resize(p.size(), mpz_class(0));  // keep degree n even if leading terms vanished
  std::reverse(q.begin(), q.end());
  taylor_shift_one(q);
  return variations(q);
}

mpq_class root_bound(const ZPoly& p) {
  assert(degree(p) >= 1);
  // Fujiwara: every root z has |z| <= 2 max_i |c_(n-i) / c_n|^(1/i). With
  // b(x) the bit length of |x|, |c_(n-i) / c_n| < 2^(b(c_(n-i)) - b(c_n) + 1),
  // so |z| < 2^(B + 1) for B the largest ceil((b(c_(n-i)) - b(c_n) + 1) / i).
  const long n = degree(p);
  const long lead_bits = static_cast<long>(mpz_sizeinbase(p.back().get_mpz_t(), 2));
  long exponent = 0;
  for (long i = 1; i <= n; ++i) {
    const mpz_class& c = p[static_cast<std::size_t>(n - i)];
    if (c == 0) continue;
    const long excess = static_cast<long>(mpz_sizeinbase(c.get_mpz_t(), 2)) - lead_bits + 1;
    if (excess > 0) exponent = std::max(exponent, (excess + i - 1) / i);
  }
  return mpq_class(mpz_class(1) << static_cast<mp_bitcnt_t>(exponent + 1));
}

}  // namespace kvd::zpoly
