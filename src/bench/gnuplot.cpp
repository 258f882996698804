#include "gnuplot.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "cli.hpp"
#include "report.hpp"

namespace kvd::bench {

bool run_gnuplot(const std::string& suite, const std::string& script_path, const std::string& script,
                 const std::vector<std::string>& outputs) {
  const std::string who = "kvd bench " + suite;
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
    std::cerr << who << ": gnuplot not found (apt-get install gnuplot-nox): no plot\n";
    return false;
  }
  if (script_path.find('\'') != std::string::npos) throw cli::Usage_error(who + ": --out must not contain a quote");
  cli::write_atomically("bench " + suite, script_path, script);
  const std::string command = "gnuplot '" + script_path + "'";
  if (std::system(command.c_str()) != 0) {
    for (const std::string& o : outputs) std::filesystem::remove(o);
    std::cerr << who << ": gnuplot failed; the CSV and the tables are written\n";
    return false;
  }
  return true;
}

namespace {

std::string header(const std::string& svg, std::size_t height) {
  return "set terminal svg size 760," + std::to_string(height) + " dynamic font 'sans,12'\nset output '" + svg + "'\n";
}

// A plot's settings and its plot command, after the terminal and the output.
std::string panel(const Line_plot& p) {
  std::string tics;
  for (std::size_t n : p.sizes) tics += (tics.empty() ? "" : ", ") + std::to_string(n);
  // A margin of a quarter of a doubling either side: autoscale on a log axis
  // would round the range out to powers of ten.
  const std::string range = "[" + cli::fixed(static_cast<double>(p.sizes.front()) / 1.2, 1) + ":" +
                            cli::fixed(static_cast<double>(p.sizes.back()) * 1.2, 1) + "]";
  std::string out = std::string("set datafile missing 'NaN'\n") +
                    (p.log_y ? "set logscale xy\n" : "set logscale x\nset yrange [0:*]\n") +
                    "set xtics (" + tics + ")\n"
                    "set xrange " + range + "\n"
                    "set grid\n"
                    "set key " + p.key + "\n"
                    "set title '" + p.title + "'\n"
                    "set xlabel '" + p.xlabel + "'\n"
                    "set ylabel '" + p.ylabel + "'\n"
                    "plot";
  for (std::size_t i = 0; i < p.series.size(); ++i)
    out += std::string(i ? "," : "") + " '" + p.data + "' using 1:" +
           std::to_string(p.first_column + static_cast<int>(i)) + " with linespoints pt " + std::to_string(i + 1) +
           " ps 1.2 title '" + p.series[i] + "'";
  if (p.reference) out += ", " + cli::approx(*p.reference) + " with lines dt 2 lc 'gray' title '" + p.reference_title + "'";
  return out + "\n";
}

}  // namespace

std::string gnuplot_script(const Line_plot& p) {
  return header(p.svg, 480) + panel(p);
}

std::string gnuplot_script(const std::string& svg, const std::vector<Line_plot>& panels) {
  std::string out = header(svg, 420 * panels.size()) + "set multiplot layout " + std::to_string(panels.size()) + ",1\n";
  // Settings outlive a panel: each starts from linear axes and autoscale.
  for (const Line_plot& p : panels) out += "unset logscale\nset autoscale y\n" + panel(p);
  return out + "unset multiplot\n";
}

}  // namespace kvd::bench
