#include "wall_filter.hpp"

#include <array>
#include <unordered_map>

#include "../kernel/interval.hpp"

namespace kvd::kinetic {

using filter::Interval;
using Four = std::array<Interval, 4>;

struct Wall_filter::State {
  std::optional<Interval> t;
  std::optional<Four> point, direction;
  std::unordered_map<const Plane4<P>*, std::optional<Four>> planes;

  // The four polynomials at t; none when the instant could not be enclosed
  // or a value overflows.
  template <class Of>
  std::optional<Four> at(const Of& four) const {
    if (!t) return std::nullopt;
    // One power of two for the four: a positive scale of the whole point or
    // plane keeps the signs of its dots and of their cross products.
    const unsigned long shift = filter::shift_for(four.c);
    Four out;
    for (int k = 0; k < 4; ++k) {
      // Converts: outside the rounding scope. Within reach after the shift.
      const auto c = filter::enclose(four[k], shift).value();
      const filter::Rounding_scope upward;
      const auto v = filter::evaluate(c, *t);
      if (!v) return std::nullopt;
      out[static_cast<std::size_t>(k)] = *v;
    }
    return out;
  }

  std::optional<Bounds> dot(const Plane4<P>& h, const std::optional<Four>& x) {
    if (!x) return std::nullopt;
    auto it = planes.find(&h);
    if (it == planes.end()) it = planes.emplace(&h, at(h)).first;
    if (!it->second) return std::nullopt;
    const Four& a = *it->second;
    const filter::Rounding_scope upward;
    Interval s = a[0] * (*x)[0];
    for (std::size_t k = 1; k < 4; ++k) s += a[k] * (*x)[k];
    if (!std::isfinite(s.lower()) || !std::isfinite(s.upper())) return std::nullopt;
    return Bounds{s.lower(), s.upper()};
  }
};

Wall_filter::Wall_filter(const Exact_time& t) : state_(std::make_unique<State>()) { state_->t = filter::enclose(t); }
Wall_filter::~Wall_filter() = default;

void Wall_filter::set_point(const Point4<P>& v, bool negate) {
  state_->point = state_->at(v);
  if (negate && state_->point)
    for (auto& x : *state_->point) x = -x;
}
void Wall_filter::set_direction(const Point4<P>& d) { state_->direction = state_->at(d); }

std::optional<Bounds> Wall_filter::at_point(const Plane4<P>& h) { return state_->dot(h, state_->point); }
std::optional<Bounds> Wall_filter::at_direction(const Plane4<P>& h) { return state_->dot(h, state_->direction); }

int Wall_filter::sign(const std::optional<Bounds>& b) {
  if (!b) return 0;
  return b->lo > 0 ? 1 : (b->hi < 0 ? -1 : 0);
}

int Wall_filter::cross_sign(const std::optional<Bounds>& fa, const std::optional<Bounds>& ga,
                            const std::optional<Bounds>& fb, const std::optional<Bounds>& gb) {
  if (!fa || !ga || !fb || !gb) return 0;
  const auto i = [](const std::optional<Bounds>& b) { return Interval(b->lo, b->hi); };
  const filter::Rounding_scope upward;
  const Interval v = i(fb) * i(ga) - i(fa) * i(gb);
  if (!std::isfinite(v.lower()) || !std::isfinite(v.upper())) return 0;
  return filter::sign(v);
}

}  // namespace kvd::kinetic
