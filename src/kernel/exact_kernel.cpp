#include "kvd/kernel/exact_kernel.hpp"

#include <vector>

#include "kvd/detail/kernel/descartes.hpp"
#include "interval.hpp"

namespace kvd {

namespace {

int three_way(const mpq_class& a, const mpq_class& b) {
  const int c = cmp(a, b);
  return (c > 0) - (c < 0);
}

// Whether the algebraic (non-rational) value x is a root of g, where g divides
// x's defining polynomial: g then has at most x as root in x's interval and is
// non-zero at its ends, so a sign change of g there decides.
bool is_root_of_divisor(const zpoly::ZPoly& g, const Exact_time& x) {
  return zpoly::sign_at(g, x.lower()) != zpoly::sign_at(g, x.upper());
}

// Whether two algebraic values with overlapping intervals are equal.
bool equal_algebraic(const Exact_time& a, const Exact_time& b) {
  const zpoly::ZPoly g = zpoly::gcd(a.polynomial(), b.polynomial());
  if (zpoly::degree(g) < 1) return false;
  if (!is_root_of_divisor(g, a) || !is_root_of_divisor(g, b)) return false;
  // Both are roots of g, and the only roots of g in the union of their
  // (overlapping) intervals. g is square-free and non-zero at the ends of the
  // union, so the roots coincide exactly when g changes sign across the union.
  const mpq_class& lo = a.lower() < b.lower() ? a.lower() : b.lower();
  const mpq_class& hi = a.upper() > b.upper() ? a.upper() : b.upper();
  return zpoly::sign_at(g, lo) != zpoly::sign_at(g, hi);
}

// The sign-changing roots of the quadratic q in increasing order, in closed
// form: none when D <= 0 (no real root, or a double one where q keeps its
// sign, so q needs no square-free part); else (-b -+ sqrt(D)) / 2a, rational
// when D is a square, otherwise each isolated by the integer square root
// s = floor(sqrt(D)), with s < sqrt(D) < s + 1 (the ends are rational, so
// not roots, and the two intervals are disjoint since s >= 1).
class Quadratic_roots {
public:
  explicit Quadratic_roots(const zpoly::ZPoly& q) : q_(q) {
    const int sa = sgn(q[2]);  // roots and their order are those of sa * q
    a_ = sa * q[2], b_ = sa * q[1];
    d_ = b_ * b_ - 4 * a_ * (sa * q[0]);
    if (d_ > 0) mpz_sqrt(s_.get_mpz_t(), d_.get_mpz_t());
  }
  std::size_t size() const { return d_ > 0 ? 2 : 0; }
  // The smaller root for i = 0; made only when asked.
  Exact_time operator[](std::size_t i) const {
    const mpz_class n = i == 0 ? mpz_class(-b_ - s_) : mpz_class(-b_ + s_);
    if (s_ * s_ == d_) return Exact_time::of_canonical(ratio(n));
    return i == 0 ? Exact_time::algebraic(q_, ratio(n - 1), ratio(n)) : Exact_time::algebraic(q_, ratio(n), ratio(n + 1));
  }

private:
  mpq_class ratio(const mpz_class& n) const {
    mpq_class r(n, 2 * a_);
    r.canonicalize();
    return r;
  }
  const zpoly::ZPoly& q_;
  mpz_class a_, b_, d_, s_;
};

// Whether the root of c0 + c1 t (c1 != 0) is greater than a. With
// c0 = n0/d0, c1 = n1/d1 and a = an/ad (positive denominators),
// X = n0 d1 ad + n1 d0 an = d0 d1 ad p(a), and the root is after a when
// X and n1 have opposite signs.
bool root_after(const mpq_class& c0, const mpq_class& c1, const mpq_class& a) {
  thread_local mpz_class x, y;  // scratch: no allocation once grown
  mpz_mul(x.get_mpz_t(), c0.get_num_mpz_t(), c1.get_den_mpz_t());
  mpz_mul(x.get_mpz_t(), x.get_mpz_t(), a.get_den_mpz_t());
  mpz_mul(y.get_mpz_t(), c1.get_num_mpz_t(), c0.get_den_mpz_t());
  mpz_mul(y.get_mpz_t(), y.get_mpz_t(), a.get_num_mpz_t());
  x += y;
  return sgn(x) == -sgn(c1.get_num());
}

}  // namespace

int Exact_kernel::compare(const Time& a, const Time& b) const {
  if (filter_ && !(a.is_rational() && b.is_rational())) {
    // Both narrowed to a relative width of about 2^-50 (kept for later calls).
    const auto x = filter::enclose(a), y = filter::enclose(b);
    if (x && y && (x->upper() < y->lower() || y->upper() < x->lower())) {
      ++statistics_->compare.filter;
      return x->upper() < y->lower() ? -1 : 1;
    }
  }
  if (!(a.is_rational() && b.is_rational())) ++statistics_->compare.exact;
  bool known_distinct = false;
  for (;;) {
    if (a.is_rational() && b.is_rational()) return three_way(a.rational(), b.rational());
    if (b.is_rational()) return a.compare_refining(b.rational());
    if (a.is_rational()) return -b.compare_refining(a.rational());
    if (a.upper() <= b.lower()) return -1;
    if (b.upper() <= a.lower()) return 1;
    if (!known_distinct) {
      if (equal_algebraic(a, b)) return 0;
      known_distinct = true;
    }
    // Distinct numbers: refining separates them. A refinement may land on a
    // root and turn a value rational, hence the re-dispatch each round.
    a.refine();
    b.refine();
  }
}

int Exact_kernel::sign_at(const Poly& p, const Time& t) const {
  if (filter_) {
    if (const int s = filter::sign_at(p, t)) {
      ++statistics_->sign_at.filter;
      return s;
    }
  }
  ++statistics_->sign_at.exact;
  if (t.is_rational())  // integer coefficients (most, kvd/kernel/poly.hpp) are read in place
    if (const auto s = zpoly::sign_at_integral(p, t.rational())) return *s;
  const zpoly::ZPoly z = zpoly::to_zpoly(p);  // a positive multiple: same signs
  if (z.empty()) return 0;
  if (t.is_rational()) return zpoly::sign_at(z, t.rational());
  const zpoly::ZPoly g = zpoly::gcd(z, t.polynomial());
  if (zpoly::degree(g) >= 1 && is_root_of_divisor(g, t)) return 0;
  // p(t) != 0: shrink t's interval until p has no root in it.
  while (!t.is_rational() && zpoly::descartes_bound(z, t.lower(), t.upper()) != 0) t.refine();
  if (t.is_rational()) return zpoly::sign_at(z, t.rational());
  return zpoly::sign_at(z, (t.lower() + t.upper()) / 2);
}

int Exact_kernel::sign_after(const Poly& p, const Time& t) const {
  for (Poly d = p; !d.is_zero(); d = d.derivative()) {
    const int s = sign_at(d, t);
    if (s != 0) return s;
  }
  return 0;
}

std::optional<Exact_time> Exact_kernel::next_root(const Poly& p, const Time& after) const {
  if (p.degree() == 1) {  // most certificates of linear motions: no integer conversion
    const mpq_class &c0 = p.coefficients()[0], &c1 = p.coefficients()[1];
    const auto root = [&] {
      mpq_class r;
      mpq_div(r.get_mpq_t(), c0.get_mpq_t(), c1.get_mpq_t());
      mpq_neg(r.get_mpq_t(), r.get_mpq_t());  // in place: no temporary
      return Exact_time::of_canonical(std::move(r));
    };
    // Against a rational, decided on integers before any gcd.
    if (after.is_rational()) return root_after(c0, c1, after.rational()) ? std::optional(root()) : std::nullopt;
    Exact_time r = root();
    if (r.rational() <= after.lower()) return std::nullopt;
    if (r.rational() >= after.upper() || after.compare_refining(r.rational()) < 0) return r;
    return std::nullopt;
  }
  const zpoly::ZPoly z = zpoly::to_zpoly(p);
  const zpoly::ZPoly q = zpoly::degree(z) == 2 ? z : zpoly::odd_part(z);
  if (zpoly::degree(q) < 1) return std::nullopt;
  // The first root r of q (every root simple, a sign change) with r > after.
  // Roots made one at a time: a later one only when an earlier one is not after.
  const auto first_after = [&](const auto& ascending) -> std::optional<Exact_time> {
    for (std::size_t i = 0; i < ascending.size(); ++i) {
      const Exact_time r = ascending[i];
      if (after.upper() < r.lower()) return r;  // the intervals decide, with no refinement
      if (r.upper() <= after.lower()) continue;
      // Against a rational, one exact sign of r's polynomial decides.
      if ((after.is_rational() ? r.compare_refining(after.rational()) : compare(r, after)) > 0) return r;
    }
    return std::nullopt;
  };
  if (zpoly::degree(q) == 1) return first_after(std::vector{Exact_time(mpq_class(-q[0], q[1]))});
  if (zpoly::degree(q) == 2) return first_after(Quadratic_roots(q));
  const mpq_class bound = zpoly::root_bound(q);
  const mpq_class lo = after.lower();  // a copy: comparing with `after` may refine it
  if (!(lo < bound)) return std::nullopt;
  std::optional<Exact_time> found;
  isolate_real_roots(q, lo, bound, [&](const Exact_time& r) {
    if (!after.is_rational() && compare(r, after) <= 0) return false;
    found = r;
    return true;
  });
  return found;
}

}  // namespace kvd
