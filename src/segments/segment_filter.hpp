// The exact kernel's interval filter for the segment predicates
// (segment_predicates.cpp, rule 2): the sign of a certificate's factors at an
// instant, by certified interval arithmetic on doubles (src/kernel/interval.hpp),
// decided only when no factor's interval holds zero, and then the exact sign.
// A construction that records certificates needs their polynomials anyway and
// does not ask it; a build without a recorder (kvd build, a validation's
// fresh build) does.
#pragma once

#include <array>
#include <cstdint>
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
  // Whether at_[e] holds endpoint e at the instant of ti_ (evaluated when
  // first asked there, as a sign names it); false when it has no
  // enclosure there.
  bool at(std::size_t e) const;

  std::vector<std::optional<Coefficients>> coefficients_;  // none: a coefficient beyond filter::max_input
  // The last instant asked, by its isolating interval, and its enclosure:
  // a construction asks thousands of signs at one instant, and the
  // enclosure and the endpoints' values there are computed once for them.
  // A refined interval is another key; the old enclosure stayed valid.
  mutable mpq_class lo_, hi_;
  mutable std::optional<filter::Interval> ti_;
  mutable std::uint64_t epoch_ = 0;                          // of ti_, counted from 1
  mutable std::vector<std::uint64_t> evaluated_;             // per endpoint: the epoch at_ holds, 0 none
  mutable std::vector<bool> enclosed_;                       // per endpoint: whether it had an enclosure then
  mutable std::vector<std::array<filter::Interval, 3>> at_;  // the endpoints at that instant
};

}  // namespace kvd::segments::detail
