#include "kvd/detail/scene/span_check.hpp"

#include <sstream>

#include "kvd/detail/kernel/descartes.hpp"

namespace kvd::scene {

namespace {

// The first root of the integer polynomial z in (start, end].
std::optional<Exact_time> first_root(const zpoly::ZPoly& z, const Q& start, const std::optional<Q>& end) {
  if (zpoly::degree(z) < 1) return std::nullopt;
  const zpoly::ZPoly q = zpoly::square_free(z);
  // Every root lies in (-bound, bound): past it (and without an end) there is none.
  const Q hi = end ? *end : std::max<Q>(zpoly::root_bound(q), start + 1);
  std::optional<Exact_time> found;
  isolate_real_roots(q, start, hi, [&](const Exact_time& r) {
    found = r;
    return true;
  });
  if (!found && end && zpoly::sign_at(q, *end) == 0) found = Exact_time(*end);
  return found;
}

}  // namespace

std::optional<Exact_time> first_zero(const QPoly& p, const Q& start, const std::optional<Q>& end) {
  return first_root(zpoly::to_zpoly(p), start, end);
}

zpoly::ZPoly common_divisor(const std::vector<QPoly>& ps) {
  zpoly::ZPoly g;
  for (const QPoly& p : ps)
    if (!p.is_zero()) g = zpoly::gcd(g, zpoly::to_zpoly(p));
  return g;
}

std::optional<Exact_time> first_common_zero(const std::vector<QPoly>& ps, const Q& start,
                                            const std::optional<Q>& end) {
  return first_root(common_divisor(ps), start, end);
}

std::string instant_text(const Exact_time& t) {
  if (t.is_rational()) return " at t = " + t.to_string();
  std::ostringstream approx;
  approx.precision(17);
  approx << t.to_double();
  return " at t = " + t.to_string() + " (about " + approx.str() + ")";
}

std::string span_text(const std::optional<Q>& end) {
  return end ? "inside the time span" : "after the start time (the scene has no end)";
}

bool in_span(const Q& t, const Q& start, const std::optional<Q>& end) { return start <= t && (!end || t <= *end); }

std::string outside_span_text(const Q& start, const std::optional<Q>& end) {
  return "is outside the scene's time span [" + start.get_str() + ", " + (end ? end->get_str() : "no end") + "]";
}

}  // namespace kvd::scene
