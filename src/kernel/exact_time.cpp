#include "kvd/kernel/exact_time.hpp"

#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace kvd {

void Exact_time::Rep::become_rational(mpq_class r) {
  rational = true;
  hi = r;
  lo = std::move(r);
  p.clear();  // most rational instants are never asked for it
  sign_hi = 0;
}

Exact_time::Exact_time(const mpq_class& r) : rep_(std::make_shared<Rep>()) {
  mpq_class c = r;
  c.canonicalize();  // a non-canonical mpq would corrupt GMP's arithmetic
  rep_->become_rational(std::move(c));
}

Exact_time Exact_time::of_canonical(mpq_class&& r) {
  assert(sgn(r.get_den()) > 0 && gcd(r.get_num(), r.get_den()) == 1);
  Exact_time t(Of_rep{}, std::make_shared<Rep>());
  t.rep_->become_rational(std::move(r));
  return t;
}

const zpoly::ZPoly& Exact_time::polynomial() const {
  if (rep_->rational && rep_->p.empty()) rep_->p = {-rep_->lo.get_num(), rep_->lo.get_den()};
  return rep_->p;
}

Exact_time Exact_time::algebraic(zpoly::ZPoly p, const mpq_class& lo, const mpq_class& hi) {
  assert(zpoly::degree(p) >= 1 && lo < hi);
  if (zpoly::degree(p) == 1) {
    mpq_class r(-p[0], p[1]);
    r.canonicalize();  // the denominator may be negative
    return of_canonical(std::move(r));
  }
  Exact_time t(Of_rep{}, std::make_shared<Rep>());
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
  return Exact_time(Of_rep{}, std::make_shared<Rep>(*rep_));
}

namespace {

// The exact value of a finite double, or +-2^1024 for the infinities (the
// point past which round-to-nearest overflows).
mpq_class exact(double d) {
  if (std::isinf(d)) return mpq_class(mpz_class(d > 0 ? 1 : -1) << 1024);
  return mpq_class(d);
}

bool even(double d) {
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  return (bits & 1) == 0;
}

}  // namespace

double Exact_time::to_double() const {
  // First a close approximation: an interval of relative width 2^-60 (an
  // interval straddling zero is first split there).
  if (!rep_->rational && rep_->lo < 0 && rep_->hi > 0) compare_refining(0);
  for (int i = 0; i < 4000 && !rep_->rational; ++i) {
    const Rep& x = *rep_;
    mpq_class w = x.hi - x.lo;
    const mpq_class m = abs(x.lo) < abs(x.hi) ? mpq_class(abs(x.lo)) : mpq_class(abs(x.hi));
    w <<= 60;
    if (w <= m) break;
    refine();
  }
  double d = (rep_->rational ? rep_->lo : mpq_class((rep_->lo + rep_->hi) / 2)).get_d();
  // Then round to nearest, ties to even, by exact comparison with the
  // halfway points around d (a step or two at most).
  for (;;) {
    const double up = std::nextafter(d, HUGE_VAL), down = std::nextafter(d, -HUGE_VAL);
    const int above = compare_refining((exact(d) + exact(up)) / 2);
    if (above > 0 || (above == 0 && !even(d))) {
      d = up;
      if (std::isinf(d)) return d;
      continue;
    }
    const int below = compare_refining((exact(down) + exact(d)) / 2);
    if (below < 0 || (below == 0 && !even(d))) {
      d = down;
      if (std::isinf(d)) return d;
      continue;
    }
    return d;
  }
}

std::pair<mpq_class, mpq_class> Exact_time::canonical_interval() const {
  for (mpz_class scale = 1;; scale *= 2) {
    // The cell of width 1/scale holding the value: refine until (lo, hi)
    // lies in one cell (a value on a cell's end becomes rational).
    mpz_class m;
    for (;;) {
      if (rep_->rational) return {rep_->lo, rep_->lo};
      const mpq_class lo = rep_->lo * scale;
      mpz_fdiv_q(m.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());
      mpq_class end(m + 1, scale);
      end.canonicalize();
      if (rep_->hi <= end) break;
      compare_refining(end);
    }
    mpq_class a(m, scale), b(m + 1, scale);
    a.canonicalize();
    b.canonicalize();
    if (zpoly::sign_at(rep_->p, a) != 0 && zpoly::sign_at(rep_->p, b) != 0 && zpoly::descartes_bound(rep_->p, a, b) == 1)
      return {a, b};
  }
}

Exact_time Exact_time::canonical() const {
  const auto [lo, hi] = canonical_interval();
  if (rep_->rational) return Exact_time(lo);
  return algebraic(rep_->p, lo, hi);
}

std::string Exact_time::to_string() const {
  const auto [lo, hi] = canonical_interval();  // [r, r] for a rational
  if (rep_->rational) return rep_->lo.get_str();
  std::ostringstream os;
  os << "root of [";
  for (std::size_t i = 0; i < rep_->p.size(); ++i) os << (i ? ", " : "") << rep_->p[i].get_str();
  os << "] in (" << lo.get_str() << ", " << hi.get_str() << ")";
  return os.str();
}

}  // namespace kvd
