// Counting the crossings of a segment scene at an instant, exactly.
#pragma once

#include <cstddef>

#include "kvd/segments/segment_scene.hpp"

namespace kvd::segments {

// The number of pairs of segments that cross properly at time t: each has one
// endpoint strictly on either side of the other's line. Touching at an
// endpoint and collinear overlaps are not proper crossings. Every pair whose
// x-ranges overlap is tested, so this is quadratic in the worst case.
std::size_t count_crossings(const Segment_scene& s, const Q& t);

}  // namespace kvd::segments
