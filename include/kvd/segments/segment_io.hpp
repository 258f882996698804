// Reading and writing scenes of moving segments (`kvd-segments/1`,
// SEGMENT_FORMAT.md).
//
// Every rejection throws kvd::scene::Scene_error with a message "SOURCE:
// /json/pointer: what was expected", as the triangle scene reader does.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "kvd/scene/scene_io.hpp"
#include "kvd/segments/segment_scene.hpp"

namespace kvd::segments {

struct Segment_load_options {
  // Replaces the file's priority (seed or explicit order) by this seed.
  std::optional<std::uint64_t> seed;
};

// The scene of a `kvd-segments/1` document, validated over its whole span
// and with its priority derived; `source` names it in messages.
Segment_scene read_segments(const std::string& text, const std::string& source,
                            const Segment_load_options& options = {});
// The same from a file, or from standard input for "-" (scene::read_input).
Segment_scene load_segments(const std::string& path, const Segment_load_options& options = {});
// A segment's motion alone, as a JSON text in the format's `motion` forms
// (SEGMENT_FORMAT.md; null: static), for a flight-plan change: rejections
// name `source` and the JSON place ("/translation/1"), as read_segments does.
// Whether the motion keeps the segment where it is is the run's to check
// (Kinetic_segment_bsp::set_motion).
Segment_motion read_segment_motion(const std::string& text, const std::string& source);
// The scene as a `kvd-segments/1` document, numbers as exact strings;
// read_segments(write_segments(s)) == s.
std::string write_segments(const Segment_scene& s);

// The top-level "format" string of a JSON document ("kvd-scene/1",
// "kvd-segments/1"), or "" when there is none or the text is not JSON: which
// reader to give the text to. Stops reading at that member.
std::string scene_format(const std::string& text);

}  // namespace kvd::segments
