// The data of a kvd view page (format kvd-view/1, read by web/viewer.js):
// the scene's triangles, the run's batches and motion changes with the
// features of each failing certificate, and for each interval of the run
// the tree in force (as entries of one hash-consed table, with the entries
// its batch changed), the scene's vertices and the plane of each site at a
// rational inside the interval; the page clips cuts and fragments to their
// cells from these. Exact times are strings; coordinates are integers in
// units of `unit` from `origin`, for drawing only.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "recorded_run.hpp"

namespace kvd::view {

struct Page_input {
  std::string title;  // the scene's file name
  const Recorded_run* run = nullptr;
  std::optional<nlohmann::json> diff;  // a kvd diff --json report of the same scene and events
  std::optional<std::array<double, 3>> view;
};

// Calls progress(done, of) after each interval.
nlohmann::json page_data(const Page_input& in, const std::function<void(std::size_t, std::size_t)>& progress = {});

// The page: web/viewer.html with three.js, its orbit controls, the viewer's
// script and style, and the data inlined, so that it works offline.
std::string page_html(const nlohmann::json& data);
// Whether this build has the page's assets (libjs-three is optional).
bool page_supported();

}  // namespace kvd::view
