#include "kvd/kernel/exact_time.hpp"

#include <cassert>
#include <mpfr.h>

#include <cmath>
#include <sstream>

namespace kvd {

void Exact_time::Rep::become_rational(const mpq_class& r) {
  rational = true;
  lo = hi = r;
  p = {-r.get_num(), r.get_den()};
  sign_hi = 0;
}

Exact_time::Exact_time(const mpq_class& r) : rep_(std::make_shared<Rep>()) {
  rep_->become_rational(r);
}

Exact_time Exact_time::algebraic(zpoly::ZPoly p, const mpq_class& lo, const mpq_class& hi) {
  assert(zpoly::degree(p) >= 1 && lo < hi);
  if (zpoly::degree(p) == 1) {
    mpq_class r(-p[0], p[1]);
    r.canonicalize();  // the denominator may be negative
    return Exact_time(r);
  }
  Exact_time t;
  t.rep_->p = std::move(p);
  t.rep_->lo = lo;
  t.rep_->hi = hi;
  t.rep_->sign_hi = zpoly::sign_at(t.rep_->p, hi);
  t.rep_->rational = false;
  assert(t.rep_->sign_hi != 0 && zpoly::sign_at(t.rep_->p, lo) == -t.rep_->sign_hi);
  return t;
}

int Exact_time::compare_refining(const mpq_class& r) const {
  Rep& x = *rep_;
  if (x.rational) return cmp(x.lo, r) > 0 ? 1 : (cmp(x.lo, r) < 0 ? -1 : 0);
  if (r <= x.lo) return 1;
  if (r >= x.hi) return -1;
  const int s = zpoly::sign_at(x.p, r);
  if (s == 0) {
    x.become_rational(r);
    return 0;
  }
  if (s == x.sign_hi) {  // the sign change lies in (lo, r)
    x.hi = r;
    return -1;
  }
  x.lo = r;
  return 1;
}

void Exact_time::refine() const {
  if (rep_->rational) return;
  compare_refining((rep_->lo + rep_->hi) / 2);
}

Exact_time Exact_time::detached() const {
  Exact_time t;
  *t.rep_ = *rep_;
  return t;
}

double Exact_time::to_double() const {
  // Refine until the interval is far below double resolution (relative 2^-60);
  // the cap only matters for values below double range.
  for (int i = 0; i < 4000 && !rep_->rational; ++i) {
    const Rep& x = *rep_;
    if (sgn(x.lo) == sgn(x.hi) && sgn(x.lo) != 0) {
      mpq_class w = x.hi - x.lo;
      mpq_class m = abs(x.lo) < abs(x.hi) ? mpq_class(abs(x.lo)) : mpq_class(abs(x.hi));
      mpz_class scale = 1;
      scale <<= 60;
      if (w * scale <= m) break;
    }
    refine();
  }
  // Round to nearest (mpq_class::get_d truncates).
  const mpq_class v = rep_->rational ? rep_->lo : mpq_class((rep_->lo + rep_->hi) / 2);
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, v.get_mpq_t(), MPFR_RNDN);
  const double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return d;
}

std::string Exact_time::to_string() const {
  if (rep_->rational) return rep_->lo.get_str();
  std::ostringstream os;
  os << "root of [";
  for (std::size_t i = 0; i < rep_->p.size(); ++i) os << (i ? ", " : "") << rep_->p[i].get_str();
  os << "] in (" << rep_->lo.get_str() << ", " << rep_->hi.get_str() << ")";
  return os.str();
}

}  // namespace kvd
