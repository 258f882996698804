// The checks of a flight-plan change (kvd/detail/segments/motion_change.hpp).
#include "kvd/detail/segments/motion_change.hpp"

#include <stdexcept>
#include <string>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/kernel/zpoly.hpp"
#include "kvd/detail/scene/span_check.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

template <class K>
void check_motion_change(const K& k, const Segment_scene& scene, std::size_t segment, const Segment_motion& motion,
                         const typename K::Time& now, const std::optional<typename K::Time>& end) {
  if (segment >= scene.segments.size()) throw std::invalid_argument("set_motion: no segment " + std::to_string(segment));
  // The segment alone, before and after: a copy of the scene would cost
  // its size, and the change the segment's certificates.
  Segment_scene was, is;
  was.segments = {scene.segments[segment]};
  is.segments = was.segments;
  is.segments[0].motion = motion;
  using FT = typename K::FT;
  using P = typename K::Poly;
  for (const std::size_t e : {std::size_t{0}, std::size_t{1}}) {
    const auto a = was.endpoint(e), b = is.endpoint(e);
    const P w = poly_from_rational<FT>(b[2]);
    if (k.sign_at(w, now) == 0) throw std::invalid_argument("set_motion: W is zero now");
    if (const auto r = k.next_root(w, now); r && !(end && k.compare(*r, *end) > 0))
      throw std::invalid_argument("set_motion: W vanishes at t = " + k.to_string(*r) + ", inside the span");
    for (const std::size_t c : {0, 1})
      if (k.sign_at(poly_from_rational<FT>(a[c] * b[2] - b[c] * a[2]), now) != 0)
        throw std::invalid_argument("set_motion: the new motion moves endpoint " + std::to_string(e) +
                                    " away from where it is now");
  }
  // The endpoints meet where both cross differences vanish, the roots of
  // their gcd (as the scene reader checks a file's motions); now they are
  // apart, since the segment is where it was.
  const auto p = is.endpoint(0), q = is.endpoint(1);
  const zpoly::ZPoly g = scene::common_divisor({p[0] * q[2] - q[0] * p[2], p[1] * q[2] - q[1] * p[2]});
  if (zpoly::degree(g) >= 1)
    if (const auto r = k.next_root(poly_from_rational<FT>(zpoly::to_poly(g)), now); r && !(end && k.compare(*r, *end) > 0))
      throw std::invalid_argument("set_motion: the segment's endpoints coincide at t = " + k.to_string(*r) +
                                  ", inside the span");
}

#define KVD_INSTANTIATE_CHECK_MOTION_CHANGE(K)                                                                 \
  template void check_motion_change<K>(const K&, const Segment_scene&, std::size_t, const Segment_motion&, \
                                       const typename K::Time&, const std::optional<typename K::Time>&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_CHECK_MOTION_CHANGE)

}  // namespace kvd::segments
