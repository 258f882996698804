// An exact instant of the exact kernel: a rational, or a real algebraic
// number given by a square-free integer polynomial and an isolating interval.
//
// Invariant of an algebraic value: the defining polynomial p is square-free,
// has exactly one root in the open interval (lo, hi), and p(lo), p(hi) are
// non-zero (so the root is where p changes sign). Refinement halves the
// interval; when a midpoint turns out to be the root, the value becomes
// rational. Copies share one representation, so a refinement done for one
// comparison helps every copy. Not thread-safe: share a Time between threads
// only after copying it with `Exact_time::detached`.
#pragma once

#include <gmpxx.h>

#include <memory>
#include <string>
#include <utility>

#include "kvd/detail/kernel/zpoly.hpp"

namespace kvd {

class Exact_time {
public:
  Exact_time() : Exact_time(mpq_class(0)) {}
  explicit Exact_time(const mpq_class& r);
  // The same from an r that is already canonical, as every result of GMP's
  // rational arithmetic is: no gcd and no copy.
  static Exact_time of_canonical(mpq_class&& r);
  // p square-free with exactly one root in (lo, hi) and p(lo) p(hi) < 0.
  static Exact_time algebraic(zpoly::ZPoly p, const mpq_class& lo, const mpq_class& hi);

  bool is_rational() const { return rep_->rational; }
  // The value, when is_rational().
  const mpq_class& rational() const { return rep_->lo; }
  // The defining polynomial; t*den - num for a rational.
  const zpoly::ZPoly& polynomial() const;
  const mpq_class& lower() const { return rep_->lo; }
  const mpq_class& upper() const { return rep_->hi; }

  // Halves the isolating interval (no effect on a rational).
  void refine() const;
  // Learns from a rational probe r inside (lo, hi): returns the comparison
  // of this value with r and shrinks the interval to the side found.
  int compare_refining(const mpq_class& r) const;
  // A deep copy that shares nothing.
  Exact_time detached() const;

  double to_double() const;
  // An isolating interval that depends on the value and its polynomial
  // only, not on how far comparisons have refined it: the dyadic interval
  // [m/2^k, (m+1)/2^k] holding the root, for the least k >= 0 at which
  // Descartes' rule counts exactly one root of p in it and p vanishes at
  // neither end. [r, r] for a rational r. (Refines the shared interval.)
  std::pair<mpq_class, mpq_class> canonical_interval() const;
  // A copy sharing nothing, its interval canonical_interval(): what is
  // computed from it by refining depends on the value only.
  Exact_time canonical() const;
  // "7/3" for a rational, "root of [c0, c1, ...] in (lo, hi)" otherwise,
  // with the canonical interval: the same text however the value was
  // compared before.
  std::string to_string() const;

private:
  struct Rep {
    zpoly::ZPoly p;      // defining polynomial; for a rational, made when first asked
    mpq_class lo, hi;    // lo == hi == value for a rational
    int sign_hi = 0;     // sign of p(hi)
    bool rational = true;
    void become_rational(mpq_class r);
  };
  struct Of_rep {};  // a tag: 0 must not convert to a representation
  Exact_time(Of_rep, std::shared_ptr<Rep> rep) : rep_(std::move(rep)) {}
  std::shared_ptr<Rep> rep_;
};

}  // namespace kvd
