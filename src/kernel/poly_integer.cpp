// Integer fast paths of Poly<mpq_class> (kvd/kernel/poly.hpp): the exact
// kernel's coordinates are integers (src/symbolic/scene_geometry.cpp), and so
// are the coefficients of the joins, meets and determinants built from them.
// Working on the numerators keeps every value canonical (denominator 1).
#include "kvd/kernel/poly.hpp"

#include <algorithm>

namespace kvd::detail {

namespace {

bool integral(const std::vector<mpq_class>& v) {
  return std::ranges::all_of(v, [](const mpq_class& c) { return mpz_cmp_ui(c.get_den_mpz_t(), 1) == 0; });
}

}  // namespace

bool integer_product(const std::vector<mpq_class>& a, const std::vector<mpq_class>& b, std::vector<mpq_class>& out) {
  if (!integral(a) || !integral(b)) return false;
  out.clear();
  out.resize(a.size() + b.size() - 1);  // zeros made, not copied: a copy allocates both limbs
  for (std::size_t k = 0; k < out.size(); ++k) {
    mpz_ptr sum = mpq_numref(out[k].get_mpq_t());  // the denominator stays 1
    const std::size_t first = k >= b.size() ? k - (b.size() - 1) : 0, last = std::min(k, a.size() - 1);
    // The first product sized at once, the others added to it.
    mpz_mul(sum, a[first].get_num_mpz_t(), b[k - first].get_num_mpz_t());
    for (std::size_t i = first + 1; i <= last; ++i) mpz_addmul(sum, a[i].get_num_mpz_t(), b[k - i].get_num_mpz_t());
  }
  return true;
}

bool integer_add(std::vector<mpq_class>& a, const std::vector<mpq_class>& b, bool subtract) {
  if (!integral(a) || !integral(b)) return false;
  for (std::size_t i = 0; i < b.size(); ++i) {
    mpz_ptr x = mpq_numref(a[i].get_mpq_t());
    if (subtract) mpz_sub(x, x, b[i].get_num_mpz_t());
    else mpz_add(x, x, b[i].get_num_mpz_t());
  }
  return true;
}

}  // namespace kvd::detail
