#include "kvd/kinetic/collision.hpp"

#include <algorithm>

namespace kvd::kinetic {

mpq_class simplest_rational(const mpq_class& lo, const mpq_class& hi) {
  if (lo <= 0 && hi >= 0) return 0;
  if (hi < 0) return -simplest_rational(-hi, -lo);
  // 0 < lo <= hi: an integer inside is the answer; otherwise lo and hi share
  // their integer part n and the answer is n + 1 / (simplest in the
  // reciprocals of the fractional parts).
  mpz_class n;
  mpz_cdiv_q(n.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());
  if (n <= hi) return mpq_class(n);
  n -= 1;
  mpq_class r = n + 1 / simplest_rational(1 / (hi - n), 1 / (lo - n));
  r.canonicalize();
  return r;
}

mpq_class reversal_time(const Exact_time& a, const Exact_time& c) {
  for (;;) {
    const mpq_class g = c.lower() - a.upper();
    if (g > 0 && 64 * (c.upper() - c.lower()) <= g) return simplest_rational(c.lower() - g / 16, c.lower() - g / 64);
    a.refine();
    c.refine();
  }
}

std::vector<std::size_t> contact_objects(const scene::Scene& s, const tree::Contact& c) {
  using SP = symbolic::Symbolic_plane;
  const std::size_t site = c.site.kind == SP::Kind::T   ? s.triangle_object[c.site.id]
                           : c.site.kind == SP::Kind::E ? s.edge_object[c.site.id]
                                                        : s.vertex_object[c.site.id];
  std::vector<std::size_t> out{site, s.triangle_object[c.triangle]};
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace kvd::kinetic
