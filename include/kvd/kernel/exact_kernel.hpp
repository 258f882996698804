// The exact kernel: GMP rationals, exact algebraic instants, exact signs.
//
// Nothing here depends on a tolerance. Zero is the exact zero; two instants
// are equal only when they are the same real number, which is decided with a
// gcd of their defining polynomials (see compare).
//
// Unless built with filter = false, every sign first goes through a certified
// interval filter (src/kernel/interval.hpp), which decides only when its
// interval excludes zero; exact arithmetic runs when it cannot. The answers
// are the same either way; statistics() counts which stage decided.
#pragma once

#include <gmpxx.h>

#include <memory>
#include <optional>
#include <string>

#include "kvd/kernel/exact_time.hpp"
#include "kvd/kernel/filter_statistics.hpp"
#include "kvd/kernel/poly.hpp"

namespace kvd {

class Exact_kernel {
public:
  using FT = mpq_class;
  using Poly = kvd::Poly<FT>;
  using Time = Exact_time;

  static constexpr const char* name = "exact";

  explicit Exact_kernel(bool filter = true) : filter_(filter), statistics_(std::make_shared<Filter_statistics>()) {}
  bool filtered() const { return filter_; }
  // Shared by copies of this kernel.
  Filter_statistics& statistics() const { return *statistics_; }

  int sign(const FT& x) const { return sgn(x); }
  Time time(const FT& x) const { return Time(x); }

  // Exact three-way comparison: -1, 0 or +1.
  int compare(const Time& a, const Time& b) const;
  // Sign of p at t, exactly.
  int sign_at(const Poly& p, const Time& t) const;
  // Sign of p on (t, t + delta) for small delta: the sign of the first
  // derivative of p that does not vanish at t; 0 only for p == 0.
  int sign_after(const Poly& p, const Time& t) const;
  // The smallest root of p strictly after `after` at which p changes sign
  // (a root of odd multiplicity), or none.
  std::optional<Time> next_root(const Poly& p, const Time& after) const;

  double to_double(const Time& t) const { return t.to_double(); }
  std::string to_string(const Time& t) const { return t.to_string(); }

private:
  bool filter_;
  std::shared_ptr<Filter_statistics> statistics_;
};

}  // namespace kvd
