#include "kvd/segments/segment_crossings.hpp"

#include <algorithm>
#include <numeric>

namespace kvd::segments {

namespace {

struct Point2 {
  Q x, y;
};

int orientation(const Point2& a, const Point2& b, const Point2& c) {
  return sgn((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

bool cross_properly(const std::array<Point2, 2>& p, const std::array<Point2, 2>& q) {
  return orientation(p[0], p[1], q[0]) * orientation(p[0], p[1], q[1]) < 0 &&
         orientation(q[0], q[1], p[0]) * orientation(q[0], q[1], p[1]) < 0;
}

}  // namespace

std::size_t count_crossings(const Segment_scene& s, const Q& t) {
  const std::size_t n = s.segments.size();
  std::vector<std::array<Point2, 2>> seg(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < 2; ++k) {
      const Point3 p = s.endpoint_at(2 * i + k, t);
      seg[i][k] = {p[0] / p[2], p[1] / p[2]};
    }
  // Sweep in order of the left end: only segments whose x-ranges overlap can cross.
  std::vector<Q> left(n), right(n);
  for (std::size_t i = 0; i < n; ++i) {
    left[i] = std::min(seg[i][0].x, seg[i][1].x);
    right[i] = std::max(seg[i][0].x, seg[i][1].x);
  }
  std::vector<std::size_t> by_left(n);
  std::iota(by_left.begin(), by_left.end(), std::size_t(0));
  std::sort(by_left.begin(), by_left.end(), [&](std::size_t a, std::size_t b) { return left[a] < left[b]; });
  std::size_t count = 0;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n && left[by_left[b]] <= right[by_left[a]]; ++b)
      count += cross_properly(seg[by_left[a]], seg[by_left[b]]);
  return count;
}

}  // namespace kvd::segments
