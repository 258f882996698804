// The kernels every TEMPLATE_TEST_CASE runs over, and small helpers.
#pragma once

#include <initializer_list>
#include <vector>

#include "kvd/kernel/kernel.hpp"

#define KVD_ALL_KERNELS kvd::Exact_kernel, kvd::Double_kernel, kvd::Mpfr_kernel

namespace kvd::test {

// A polynomial with integer coefficients c0, c1, ... in kernel K.
template <class K>
typename K::Poly poly(std::initializer_list<long> c) {
  std::vector<typename K::FT> v;
  for (long x : c) v.push_back(typename K::FT(x));
  return typename K::Poly(std::move(v));
}

// The product of (t - r) over the given integer roots.
template <class K>
typename K::Poly with_roots(std::initializer_list<long> roots) {
  typename K::Poly p = poly<K>({1});
  for (long r : roots) p *= poly<K>({-r, 1});
  return p;
}

// The rational n/d in canonical form (mpq_class(n, d) does not reduce, and
// GMP's arithmetic requires canonical operands).
inline mpq_class q(long n, long d) {
  mpq_class r(n, d);
  r.canonicalize();
  return r;
}

// The sign-changing roots of p after `from`, in increasing order, by the
// chain next_root(p, from), next_root(p, that root), ...
inline std::vector<Exact_time> sign_changing_roots(const Poly<mpq_class>& p, const mpq_class& from) {
  const Exact_kernel k;
  std::vector<Exact_time> r;
  Exact_time t(from);
  while (auto n = k.next_root(p, t)) r.push_back(t = *n);
  return r;
}

template <class K>
typename K::Time at(const K& k, long v) {
  return k.time(typename K::FT(v));
}

}  // namespace kvd::test
