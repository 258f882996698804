// The checks of a flight-plan change of a segment scene, shared by both
// kinetic runs (Kinetic_segment_bsp::set_motion, Aeg_kinetic_bsp::set_motion).
#pragma once

#include <cstddef>
#include <optional>

#include "kvd/segments/segment_scene.hpp"

namespace kvd::segments {

// Throws std::invalid_argument, naming what is wrong, unless segment
// `segment` of `scene` exists and `motion` puts it where it is at `now`, with
// W nonzero at now and, up to `end` (none: unbounded), after it.
template <class K>
void check_motion_change(const K& k, const Segment_scene& scene, std::size_t segment, const Segment_motion& motion,
                         const typename K::Time& now, const std::optional<typename K::Time>& end);

}  // namespace kvd::segments
