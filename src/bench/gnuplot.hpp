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

// A plot of lines against the number of triangles, log scale in x: one
// series per data column after the first (NaN where missing).
struct Line_plot {
  std::string svg, data;  // the plot written, and the data read
  std::string title, ylabel;
  std::vector<std::string> series;  // the titles of data columns 2, 3, ...
  std::vector<std::size_t> sizes;   // the x tics, increasing
  bool log_y = true;
  std::optional<double> reference;  // a dashed horizontal line, with its title
  std::string reference_title;
};
std::string gnuplot_script(const Line_plot& p);

}  // namespace kvd::bench
