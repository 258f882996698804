// Films of the cylindrical BSP of moving segments (kvd animate on a
// kvd-segments/1 scene): an exact run of Kinetic_segment_bsp, frames sampled
// evenly over it plus one held just after every batch and captioned with its
// event kinds. Each frame draws the tree built afresh at its rational instant
// (kvd/segments/segment_svg.hpp), all in one view box; smil_svg with
// segments::segment_svg_style() as its head writes the film.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "animation.hpp"
#include "kvd/segments/segment_scene.hpp"

namespace kvd::view {

struct Segment_film_options {
  std::optional<mpq_class> until;  // process every batch at a time <= until
  std::size_t max_events = 100;    // stop after the batch holding the N-th failure
  int sampled = 80;                // frames sampled evenly over the run
  int hold = 5;                    // frames each batch's picture is held for
  int size = 640;                  // the picture's width in pixels
};

struct Segment_film {
  std::vector<Smil_frame> frames;
  int width = 0, height = 0;
  std::size_t batches = 0, failures = 0;
};

// The film of the run over the scene's span (or to `until`). Calls
// run_progress(batches, failures) after each batch and
// frame_progress(done, of) after each frame.
Segment_film segment_film(const segments::Segment_scene& s, const Segment_film_options& options,
                          const std::function<void(std::size_t, std::size_t)>& run_progress = {},
                          const std::function<void(std::size_t, std::size_t)>& frame_progress = {});

}  // namespace kvd::view
