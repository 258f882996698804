// The exact kernel's interval filter for the segment predicates
// (segment_predicates.cpp, rule 2): the sign of a certificate's factors at an
// instant, by certified interval arithmetic on doubles (src/kernel/interval.hpp),
// decided only when no factor's interval holds zero, and then the exact sign.
// A construction that records certificates needs their polynomials anyway and
// does not ask it; a build without a recorder (kvd build, a validation's
// fresh build) does.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "../kernel/interval.hpp"
#include "kvd/segments/segment_predicates.hpp"

namespace kvd::segments::detail {

class Segment_filter {
public:
  // The endpoints' coordinates as polynomials in t, W > 0 on the span.
  explicit Segment_filter(const std::vector<std::array<Poly<mpq_class>, 3>>& endpoints);
  // Endpoint e moved (a flight-plan change).
  void refresh(std::size_t e, const std::array<Poly<mpq_class>, 3>& p);
  // The sign of the product of key's factors at t, or 0 when undecided.
  int sign(const Segment_certificate_key& key, const Exact_time& t) const;

private:
  using Coefficients = std::array<std::vector<filter::Interval>, 3>;
  std::vector<std::optional<Coefficients>> coefficients_;  // none: a coefficient beyond filter::max_input
  mutable std::vector<std::array<filter::Interval, 3>> at_;  // the named endpoints at the instant asked
};

}  // namespace kvd::segments::detail
