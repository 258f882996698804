// The data of a kvd view page of a scene of moving segments (format
// kvd-segment-view/3, read by web/segments.js): an exact run of
// Kinetic_segment_bsp, its batches with each failing certificate's kind,
// features and event, and for each interval of the run (before the first
// batch, after each) the tree in force at a rational instant inside it (the
// trees as one table of distinct subtrees, tree_table.hpp), with what the
// page needs to draw it as kvd/segments/segment_svg.hpp
// does (segment_layout: the pixel positions of the endpoints, a static
// one's written once, and of the crossings cut
// through, the caption) and the segments a batch's failing
// certificates name, which it marks. Every interval's tree is
// compared with a fresh build at its instant: a difference is a failed
// validation, and no data is made.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include "kvd/segments/segment_scene.hpp"

namespace kvd::view {

struct Segment_page_options {
  std::optional<mpq_class> until;  // process every batch at a time <= until
  std::size_t max_events = 100;    // stop after the batch holding the N-th failure
  int size = 640;                  // the pictures' width in pixels
};

// The run's tree differed from a fresh build at an interval's instant.
struct Segment_page_invalid : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Calls run_progress(batches, failures) after each batch and
// draw_progress(done, of) after each interval drawn. "stopped" in the data
// is "limit" (options.until), "events" (options.max_events) or "exhausted",
// as kvd simulate says.
nlohmann::json segment_page_data(const segments::Segment_scene& s, const std::string& title,
                                 const Segment_page_options& options,
                                 const std::function<void(std::size_t, std::size_t)>& run_progress = {},
                                 const std::function<void(std::size_t, std::size_t)>& draw_progress = {});

// The page: web/segments.html with its script, style and the data inlined.
std::string segment_page_html(const nlohmann::json& data);

}  // namespace kvd::view
