#include "kvd/detail/kernel/numeric_roots.hpp"

#include <cmath>

#include "kvd/kernel/mpfr_number.hpp"

namespace kvd {

namespace {

template <class FT>
int exact_sign(const FT& x) {
  return (x > FT(0)) - (x < FT(0));
}

template <class FT>
FT magnitude(const FT& x) {
  return x < FT(0) ? FT(-x) : x;
}

int precision_bits(double) { return 53; }
int precision_bits(const Mpfr_number& x) { return static_cast<int>(x.precision()); }

// p(a) and p(b) of opposite signs: bisect until the midpoint is no longer
// representable between them, or after 2p + 64 halvings (p the precision in
// bits): when the root is exactly zero the midpoints can approach it through
// the exponent range for ever (MPFR's is practically unbounded), and by then
// the interval is far below any meaningful time resolution.
template <class FT>
FT bisect(const Poly<FT>& p, FT a, FT b, int sign_a) {
  const int halvings = 2 * precision_bits(a) + 64;
  for (int i = 0; i < halvings; ++i) {
    FT m = (a + b) / FT(2);
    if (!(a < m && m < b)) return m;
    const int s = exact_sign(p(m));
    if (s == 0) return m;
    if (s == sign_a)
      a = std::move(m);
    else
      b = std::move(m);
  }
  return (a + b) / FT(2);
}

}  // namespace

template <class FT>
FT cauchy_bound(const Poly<FT>& p) {
  FT m(0);
  const FT lead = magnitude(p.leading());
  for (int i = 0; i < p.degree(); ++i) {
    FT r = magnitude(p[i]) / lead;
    if (r > m) m = r;
  }
  return m + FT(1);
}

template <class FT>
std::vector<FT> sign_change_roots(const Poly<FT>& p, const FT& lo, const FT& hi) {
  std::vector<FT> roots;
  if (p.degree() < 1 || !(lo < hi)) return roots;
  std::vector<FT> cuts{lo};
  for (auto& c : sign_change_roots(p.derivative(), lo, hi)) cuts.push_back(c);
  cuts.push_back(hi);
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const int sa = exact_sign(p(cuts[i]));
    const int sb = exact_sign(p(cuts[i + 1]));
    if (sa * sb < 0) roots.push_back(bisect(p, cuts[i], cuts[i + 1], sa));
  }
  return roots;
}

template std::vector<double> sign_change_roots(const Poly<double>&, const double&, const double&);
template std::vector<Mpfr_number> sign_change_roots(const Poly<Mpfr_number>&, const Mpfr_number&,
                                                    const Mpfr_number&);
template double cauchy_bound(const Poly<double>&);
template Mpfr_number cauchy_bound(const Poly<Mpfr_number>&);

}  // namespace kvd
