#include "segment_filter.hpp"

#include <cmath>

#include "kvd/detail/segments/segment_factors.hpp"

namespace kvd::segments::detail {

namespace {

// Coordinates at t of magnitude at most 2^100 keep every factor below 2^810
// (the deepest, order_at's, is a dot of a line with the wedge of a line and a
// crossing's vertical: 2^201 * 2^605 * 3), so no bound is infinite and no
// NaN arises.
constexpr double max_coordinate = 0x1p100;

std::optional<std::array<std::vector<filter::Interval>, 3>> enclose(const std::array<Poly<mpq_class>, 3>& p) {
  std::array<std::vector<filter::Interval>, 3> c;
  for (std::size_t i = 0; i < 3; ++i) {
    auto x = filter::enclose(p[i]);
    if (!x) return std::nullopt;
    c[i] = std::move(*x);
  }
  return c;
}

}  // namespace

Segment_filter::Segment_filter(const std::vector<std::array<Poly<mpq_class>, 3>>& endpoints)
    : evaluated_(endpoints.size(), 0), enclosed_(endpoints.size(), false), at_(endpoints.size()) {
  for (const auto& p : endpoints) coefficients_.push_back(enclose(p));
}

void Segment_filter::refresh(std::size_t e, const std::array<Poly<mpq_class>, 3>& p) {
  coefficients_[e] = enclose(p);
  evaluated_[e] = 0;
}

bool Segment_filter::at(std::size_t e) const {
  if (evaluated_[e] == epoch_) return enclosed_[e];
  evaluated_[e] = epoch_;
  enclosed_[e] = false;
  if (!coefficients_[e]) return false;
  for (std::size_t c = 0; c < 3; ++c) {
    const auto v = filter::evaluate((*coefficients_[e])[c], *ti_);
    if (!v || !(std::fabs(v->lower()) <= max_coordinate && std::fabs(v->upper()) <= max_coordinate)) return false;
    at_[e][c] = *v;
  }
  enclosed_[e] = true;
  return true;
}

int Segment_filter::sign(const Segment_certificate_key& key, const Exact_time& t) const {
  if (epoch_ == 0 || t.lower() != lo_ || t.upper() != hi_) {
    ti_ = filter::enclose(t);  // GMP converts (and may refine t): outside the rounding scope
    lo_ = t.lower();
    hi_ = t.upper();
    ++epoch_;
  }
  if (!ti_) return 0;
  const auto segments = named_segments(key);
  const filter::Rounding_scope rounding;
  for (const std::size_t s : segments)
    for (const std::size_t e : {2 * s, 2 * s + 1})
      if (!at(e)) return 0;
  int sign = 1;
  for (const filter::Interval& f : factors_of(key, View<filter::Interval>(at_, nullptr))) {
    const int s = filter::sign(f);
    if (s == 0) return 0;
    sign *= s;
  }
  return sign;
}

}  // namespace kvd::segments::detail
