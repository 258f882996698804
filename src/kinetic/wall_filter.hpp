// The exact kernel's interval filter for the reduced certificates' walks
// (reduced_certificates.cpp): the signs of dot(plane, point) at the instant,
// and the order of two walls met along a walk, decided on certified
// intervals (src/kernel/interval.hpp) before any polynomial in t is built.
// A sign is 0 when the intervals cannot tell; the walk then builds the
// polynomials and decides exactly, so the certificates are the same.
#pragma once

#include <gmpxx.h>

#include <memory>
#include <optional>

#include "kvd/geometry/plucker.hpp"
#include "kvd/kernel/exact_time.hpp"
#include "kvd/kernel/poly.hpp"

namespace kvd::kinetic {

// Certified bounds on a value at the instant; none when it could not be
// enclosed (an instant the filter cannot enclose, or an overflow).
struct Bounds {
  double lo = 0, hi = 0;
};

class Wall_filter {
public:
  using P = Poly<mpq_class>;
  explicit Wall_filter(const Exact_time& t);
  ~Wall_filter();
  Wall_filter(const Wall_filter&) = delete;
  Wall_filter& operator=(const Wall_filter&) = delete;

  // The point, or direction, at the instant. Once per walk.
  void set_point(const Point4<P>& v, bool negate);
  void set_direction(const Point4<P>& d);
  // Bounds on dot(h, v) and dot(h, d) at the instant. h is kept by address
  // for the filter's lifetime (a plane of the classifier or of the walk's
  // own cache, which outlive it).
  std::optional<Bounds> at_point(const Plane4<P>& h);
  std::optional<Bounds> at_direction(const Plane4<P>& h);

  // The sign of every number in b, or 0.
  static int sign(const std::optional<Bounds>& b);
  // The sign of fb ga - fa gb, or 0.
  static int cross_sign(const std::optional<Bounds>& fa, const std::optional<Bounds>& ga,
                        const std::optional<Bounds>& fb, const std::optional<Bounds>& gb);

private:
  struct State;  // keeps Boost.Interval out of this header
  std::unique_ptr<State> state_;
};

}  // namespace kvd::kinetic
