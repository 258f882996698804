#include "random_poly.hpp"

namespace kvd::testing {

Random_polys::Random_polys(std::uint64_t seed) : gen_(gmp_randinit_default) {
  gen_.seed(mpz_class(std::to_string(seed)));
}

unsigned long Random_polys::below(unsigned long n) { return mpz_class(gen_.get_z_range(n)).get_ui(); }

mpz_class Random_polys::integer(unsigned long bits) {
  mpz_class z = gen_.get_z_bits(1 + below(bits));
  return below(2) ? mpz_class(-z) : z;
}

mpq_class Random_polys::rational(unsigned long bits) {
  mpq_class q(integer(bits), mpz_class(gen_.get_z_bits(bits)) + 1);
  q.canonicalize();
  return q;
}

zpoly::ZPoly Random_polys::dense(int degree, unsigned long bits) {
  zpoly::ZPoly p;
  for (int i = 0; i <= degree; ++i) p.push_back(integer(bits));
  while (p.back() == 0) p.back() = integer(bits);
  return p;
}

zpoly::ZPoly Random_polys::repeated_factors(int max_degree, unsigned long bits) {
  // Degrees d1 + 2 d2 + 3 d3 <= max_degree, with d2, d3 >= 1 when room allows.
  const int d3 = max_degree >= 6 ? 1 + static_cast<int>(below(static_cast<unsigned long>(max_degree / 6))) : 1;
  const int d2 = 1 + static_cast<int>(below(static_cast<unsigned long>(std::max(1, (max_degree - 3 * d3) / 2))));
  const int rest = max_degree - 3 * d3 - 2 * d2;
  const int d1 = rest > 0 ? static_cast<int>(below(static_cast<unsigned long>(rest) + 1)) : 0;
  const zpoly::ZPoly f1 = d1 > 0 ? dense(d1, bits) : zpoly::ZPoly{1};
  const zpoly::ZPoly f2 = dense(d2, bits);
  const zpoly::ZPoly f3 = dense(d3, bits);
  return zpoly::mul(zpoly::mul(f1, zpoly::mul(f2, f2)), zpoly::mul(f3, zpoly::mul(f3, f3)));
}

zpoly::ZPoly Random_polys::cluster(int count, unsigned long shift, int extra_degree, unsigned long bits) {
  mpz_class scale = 1;
  scale <<= shift;
  const mpz_class a = integer(shift + 4);
  zpoly::ZPoly p = extra_degree > 0 ? dense(extra_degree, bits) : zpoly::ZPoly{1};
  for (int i = 0; i < count; ++i) p = zpoly::mul(p, {-(a + i), scale});
  return p;
}

zpoly::ZPoly Random_polys::with_root(const mpq_class& r, int max_degree, unsigned long bits) {
  const int rest = static_cast<int>(below(static_cast<unsigned long>(max_degree)));
  const zpoly::ZPoly f = rest > 0 ? dense(rest, bits) : zpoly::ZPoly{1};
  return zpoly::mul(f, {-r.get_num(), r.get_den()});
}

}  // namespace kvd::testing
