#include "kvd/segments/segment_scene.hpp"

#include <algorithm>

#include "kvd/detail/scene/priority.hpp"

namespace kvd::segments {

void Segment_scene::derive() {
  priority_order = order ? *order : scene::shuffled_ids(segments.size(), seed);
  rank.assign(segments.size(), 0);
  for (std::size_t i = 0; i < priority_order.size(); ++i) rank[priority_order[i]] = i;
}

bool Segment_scene::is_moving(std::size_t s) const {
  for (std::size_t k = 0; k < 2; ++k)
    for (const QPoly& c : endpoint(2 * s + k))
      if (c.degree() > 0) return true;
  return false;
}

std::size_t Segment_scene::moving_count() const {
  std::size_t n = 0;
  for (std::size_t s = 0; s < segments.size(); ++s) n += is_moving(s);
  return n;
}

int Segment_scene::max_motion_degree() const {
  int d = 0;
  for (std::size_t e = 0; e < endpoint_count(); ++e)
    for (const QPoly& c : endpoint(e)) d = std::max(d, c.degree());
  return d;
}

Motion_point3 Segment_scene::endpoint(std::size_t e) const {
  const Segment& s = segments[e / 2];
  const Point3& r = s.rest[e % 2];
  switch (s.motion.kind) {
    case Segment_motion::Kind::none: return {QPoly(r[0]), QPoly(r[1]), QPoly(r[2])};
    case Segment_motion::Kind::translation:
      return {QPoly(r[0]) + s.motion.translation[0] * r[2], QPoly(r[1]) + s.motion.translation[1] * r[2], QPoly(r[2])};
    case Segment_motion::Kind::matrix: {
      Motion_point3 p;
      for (std::size_t i = 0; i < 3; ++i)
        p[i] = s.motion.matrix[i][0] * r[0] + s.motion.matrix[i][1] * r[1] + s.motion.matrix[i][2] * r[2];
      return p;
    }
    case Segment_motion::Kind::endpoints: return s.motion.endpoints[e % 2];
  }
  return {};
}

Point3 Segment_scene::endpoint_at(std::size_t e, const Q& t) const {
  const Motion_point3 p = endpoint(e);
  return {p[0](t), p[1](t), p[2](t)};
}

}  // namespace kvd::segments
