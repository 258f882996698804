// The plots of `kvd bench`: a gnuplot script written beside its data and run.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace kvd::bench {

// Writes `script` to `script_path` and runs gnuplot on it; whether it wrote
// the plots `outputs`. Without gnuplot on the PATH, or when it fails, says
// so on stderr as `kvd bench SUITE: ...`, leaves no plot behind, and returns
// false: the tables are written all the same.
bool run_gnuplot(const std::string& suite, const std::string& script_path, const std::string& script,
                 const std::vector<std::string>& outputs);

// A plot of lines against the number of triangles (or what `xlabel` names),
// log scale in x: one series per data column from `first_column` (NaN where
// missing).
struct Line_plot {
  std::string svg, data;  // the plot written, and the data read
  std::string title, ylabel;
  std::string xlabel = "triangles (log)";
  std::vector<std::string> series;  // the titles of data columns first_column, first_column + 1, ...
  int first_column = 2;
  std::vector<std::size_t> sizes;   // the x tics, increasing
  bool log_y = true;
  std::string key = "top left";  // where the legend goes
  std::optional<double> reference;  // a dashed horizontal line, with its title
  std::string reference_title;
};
std::string gnuplot_script(const Line_plot& p);
// The plots `panels` stacked in the one SVG `svg` (their own `svg` unused).
std::string gnuplot_script(const std::string& svg, const std::vector<Line_plot>& panels);

}  // namespace kvd::bench
