#include "interval.hpp"

#include <cmath>

namespace kvd::filter {

std::optional<Interval> enclose(const mpq_class& q) {
  const double d = q.get_d();  // truncated toward zero
  if (!(std::fabs(d) <= max_input)) return std::nullopt;
  const int c = cmp(q, d);
  if (c == 0) return Interval(d, d);
  return c > 0 ? Interval(d, std::nextafter(d, HUGE_VAL)) : Interval(std::nextafter(d, -HUGE_VAL), d);
}

std::optional<Interval> enclose(const Exact_time& t) {
  if (t.is_rational()) return enclose(t.rational());
  // Refinement is exact and shared by every copy of t, so it is paid once.
  for (int i = 0; i < 60 && !t.is_rational(); ++i) {
    mpq_class w = t.upper() - t.lower();
    w <<= 50;
    if (w <= abs(t.lower()) || w <= abs(t.upper())) break;
    t.refine();
  }
  if (t.is_rational()) return enclose(t.rational());
  const auto lo = enclose(t.lower()), hi = enclose(t.upper());
  if (!lo || !hi) return std::nullopt;
  return Interval(lo->lower(), hi->upper());
}

std::optional<std::vector<Interval>> enclose(const Poly<mpq_class>& p) {
  std::vector<Interval> r;
  r.reserve(p.coefficients().size());
  for (const mpq_class& c : p.coefficients()) {
    const auto x = enclose(c);
    if (!x) return std::nullopt;
    r.push_back(*x);
  }
  return r;
}

std::optional<Interval> evaluate(const std::vector<Interval>& p, const Interval& t) {
  Interval v(0.0, 0.0);
  for (auto c = p.rbegin(); c != p.rend(); ++c) {
    v = v * t + *c;
    if (!std::isfinite(v.lower()) || !std::isfinite(v.upper())) return std::nullopt;
  }
  return v;
}

int sign_at(const Poly<mpq_class>& p, const Exact_time& t) {
  const auto x = enclose(t);
  const auto c = enclose(p);
  if (!x || !c) return 0;
  const Rounding_scope upward;
  const auto v = evaluate(*c, *x);
  return v ? sign(*v) : 0;
}

}  // namespace kvd::filter
