// Animations of a run (kvd animate): frames painted back to front with the
// tree in force, sampled evenly in time, plus a held frame just after every
// batch with the failing certificates' features marked in red and named.
// Every batch of the run appears. Written as one SVG (the frames shown in
// turn by SMIL) or, through ffmpeg, as MP4 or GIF from cairo's PNG frames.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kvd/query/render.hpp"
#include "recorded_run.hpp"

namespace kvd::view {

struct Animation_options {
  std::array<mpq_class, 3> view;  // the camera's eye, looking at the scene's centre at the start
  int fps = 10;
  int sampled = 80;  // frames sampled evenly over the run's span
  int hold = 5;      // frames each batch's picture is held for
  query::Render_options render;
};

struct Animation_frame {
  mpq_class time;                     // the instant drawn
  std::optional<std::size_t> batch;   // the batch it comes just after, for a held frame
  std::vector<query::Painted_polygon> picture;
  query::Overlay overlay;
  int repeat = 1;  // frames it lasts
};

// A rational in (a, b), within `within` of a where b allows: the instant of
// the frame held after a batch at a, before the next failure at b.
mpq_class just_after(const Exact_time& a, const Exact_time& b, const mpq_class& within);

// The instant drawn for the interval after a batch at a, up to the next
// failure b (none: the run has none left), never past `end` (the time
// limit, if any), even when b lies beyond it. A batch at `end` itself is
// drawn there: the tree at an instant is the one in force just after it.
mpq_class drawn_after(const Exact_time& a, const std::optional<Exact_time>& b, const std::optional<mpq_class>& end,
                      const mpq_class& within);

// The frames in time order, framed together so that the camera stays still.
// Calls progress(done, of) after each frame.
std::vector<Animation_frame> animation_frames(const Recorded_run& run, const Animation_options& options,
                                              const std::function<void(std::size_t, std::size_t)>& progress = {});

// One picture of a SMIL film: its SVG elements, the frames it lasts, and
// the batch it is held after, if it is.
struct Smil_frame {
  std::string elements;
  int repeat = 1;
  std::optional<std::size_t> batch;
};

// One SVG document of width x height pixels showing the frames in turn at
// fps, looping (SMIL), after `head` (elements the frames share, such as a
// <style>). A viewer without SMIL shows the first frame.
std::string smil_svg(const std::vector<Smil_frame>& frames, int width, int height, int fps,
                     const std::string& head = "");

// One SVG document showing the frames in turn, looping (SMIL).
std::string animated_svg(const std::vector<Animation_frame>& frames, const Animation_options& options);

enum class Video { mp4, gif };

// MP4 (H.264) or GIF through ffmpeg, as bytes; throws std::runtime_error
// when ffmpeg is missing or fails.
std::string encoded_video(const std::vector<Animation_frame>& frames, const Animation_options& options, Video kind);

}  // namespace kvd::view
