// Exact checks that a scene stays well-formed over its whole time span, not
// only at the start: a Euclidean point must not reach infinity (its W
// vanishing) and a triangle must not flatten to a segment. Both are decided
// by exact real-root isolation, so a scene is rejected exactly when the event
// happens inside the span (the end included).
#pragma once

#include <optional>
#include <string>

#include "kvd/detail/kernel/zpoly.hpp"
#include "kvd/kernel/exact_time.hpp"
#include "kvd/scene/scene.hpp"

namespace kvd::scene {

// The first t in (start, end] (in (start, infinity) without an end) at which
// p(t) = 0, roots of even multiplicity included; nothing when p never
// vanishes there. p must not be the zero polynomial.
std::optional<Exact_time> first_zero(const QPoly& p, const Q& start, const std::optional<Q>& end);

// The gcd of the polynomials, whose real roots are the instants at which
// they all vanish together: primitive, in integers; zero when all are zero.
zpoly::ZPoly common_divisor(const std::vector<QPoly>& ps);

// The first t in (start, end] at which the polynomials all vanish together
// (the real roots of their gcd); nothing when they never do. Not all zero.
std::optional<Exact_time> first_common_zero(const std::vector<QPoly>& ps, const Q& start, const std::optional<Q>& end);

// How a rejection names an instant: " at t = 7/3", or " at t = root of [...]
// in (lo, hi) (about 1.4142135623730951)".
std::string instant_text(const Exact_time& t);
// How it names the span searched: "inside the time span", or "after the
// start time (the scene has no end)".
std::string span_text(const std::optional<Q>& end);

// Whether t lies in the span [start, end] (no end: from start on), and how
// a refusal of an instant outside it ends: "is outside the scene's time span
// [0, 10]" ("[0, no end]").
bool in_span(const Q& t, const Q& start, const std::optional<Q>& end);
std::string outside_span_text(const Q& start, const std::optional<Q>& end);

}  // namespace kvd::scene
