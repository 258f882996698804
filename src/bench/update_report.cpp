// The report of kvd bench update: CSV, Markdown, the fitted growth and the plot.
#include <algorithm>
#include <cmath>

#include "gnuplot.hpp"
#include "update.hpp"

namespace kvd::bench::update_suite {

namespace {

const char* const plotted_configurations[] = {"local", "reinsert", "local, double", "rebuild"};

std::string cell(const Run* r, double value(const Run&), int digits) {
  return r ? cli::fixed(value(*r), digits) : "";
}
double mean(const Run& r) { return r.costs.average; }
double median(const Run& r) { return r.costs.median; }
double max(const Run& r) { return r.costs.max; }
double touched(const Run& r) { return r.touched.median; }

// The points (N, value) of one configuration over the sizes that ran it.
std::vector<std::pair<double, double>> series(const std::vector<Size>& sizes, const std::string& configuration,
                                              double value(const Run&)) {
  std::vector<std::pair<double, double>> points;
  for (const Size& s : sizes)
    if (const Run* r = s.find(configuration)) points.emplace_back(static_cast<double>(s.triangles), value(*r));
  return points;
}

std::string exponent_cell(const std::vector<std::pair<double, double>>& points) {
  const auto a = growth_exponent(points);
  return a ? cli::fixed(*a, 2) : "";
}

}  // namespace

const Run* Size::find(const std::string& configuration) const {
  const auto it = std::ranges::find(runs, configuration, &Run::configuration);
  return it == runs.end() || !it->failure.empty() ? nullptr : &*it;
}

bool Size::same_tree() const {
  return std::ranges::all_of(runs, [&](const Run& r) { return !r.exact || r.structure == runs.front().structure; });
}

std::optional<double> growth_exponent(const std::vector<std::pair<double, double>>& points) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [x, y] : points) {
    if (x <= 0 || y <= 0) continue;
    const double lx = std::log(x), ly = std::log(y);
    n += 1, sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  const double d = n * sxx - sx * sx;
  if (n < 2 || d <= 0) return std::nullopt;
  return (n * sxy - sx * sy) / d;
}

std::string csv(const std::vector<Size>& sizes) {
  std::string out =
      "triangles,configuration,batches,mean_ms,median_ms,max_ms,tree_median_ms,certificates_made_median,"
      "nodes_recomputed_median,nodes_touched_median,nodes_changed_median,nodes_changed_mean,nodes_changed_max,"
      "below_10_share,peak_rss_mib,structure_hash,"
      "failure\n";
  for (const Size& s : sizes)
    for (const Run& r : s.runs) {
      if (!r.failure.empty()) {
        std::string quoted;
        for (char ch : r.failure) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        out += std::to_string(s.triangles) + ",\"" + r.configuration + "\",,,,,,,,,,,,,,,\"" + quoted + "\"\n";
        continue;
      }
      const bool local = r.configuration != "rebuild" && !r.configuration.starts_with("rebuild,");
      out += std::to_string(s.triangles) + ",\"" + r.configuration + "\"," + std::to_string(r.batches) + "," +
             cli::fixed(r.costs.average, 3) + "," + cli::fixed(r.costs.median, 3) + "," + cli::fixed(r.costs.max, 3) +
             "," + cli::fixed(r.costs.tree_median, 3) + "," + cli::fixed(r.recomputed.median, 1) + "," +
             cli::fixed(r.recomputed.nodes_median, 1) + "," +
             (local ? cli::fixed(r.touched.median, 1) + "," + cli::fixed(r.touched.changed_median, 1) + "," +
                          cli::fixed(r.touched.changed_mean, 1) + "," + cli::fixed(r.touched.changed_max, 0) + "," +
                          cli::fixed(r.touched.below_10_share, 3)
                    : std::string(",,,,")) +
             "," + cli::fixed(s.peak_rss_mib, 0) + "," + r.structure + ",\n";
    }
  return out;
}

std::string markdown(const Config& c, const std::vector<Size>& sizes, bool plotted) {
  std::string out =
      "## Cost per batch against N\n\n"
      "`kvd generate uniform-scale --triangles N --seed 1` (all moving linearly), the first " +
      std::to_string(c.events) +
      " certificate failures, reduced set, no validation; one run per size and configuration, ms per batch "
      "(everything from the failure to the next queue minimum). *Local*: the update confined to the subtree of the "
      "failing signs, re-cutting only where the moving walls swept (`--update local`); *reinsert*: every piece of a "
      "moving site dragged out and inserted again from the root (`--update reinsert`). *Touched*: nodes an update "
      "re-cut, relinked, created or removed; *changed*: the larger of the number of cuts and fragments after the "
      "batch that no node had before and the number before that no node has after, the fewest nodes any update "
      "must write. Peak RSS is the process's after the size's runs (sizes run in increasing order).\n\n"
      "| triangles | batches | local: mean | median | max | reinsert: mean | median | double: mean | median | "
      "rebuild: mean | median | reinsert / local (mean) | rebuild / local (mean) | nodes touched (median), local | "
      "reinsert | nodes changed (median), local | mean | max | peak RSS MiB | same tree |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  const auto ratio = [](const Run* a, const Run* b) {
    return a && b && b->costs.average > 0 ? cli::fixed(a->costs.average / b->costs.average, 1) + "×" : std::string();
  };
  for (const Size& s : sizes) {
    const Run* local = s.find("local");
    const Run* reinsert = s.find("reinsert");
    const Run* dbl = s.find("local, double");
    const Run* rebuild = s.find("rebuild");
    out += "| " + std::to_string(s.triangles) + " | " + (local ? std::to_string(local->batches) : "") + " | " +
           cell(local, mean, 2) + " | " + cell(local, median, 2) + " | " + cell(local, max, 1) + " | " +
           cell(reinsert, mean, 2) + " | " + cell(reinsert, median, 2) + " | " + cell(dbl, mean, 2) + " | " +
           cell(dbl, median, 2) + " | " + cell(rebuild, mean, 2) + " | " + cell(rebuild, median, 2) + " | " +
           ratio(reinsert, local) + " | " + ratio(rebuild, local) + " | " + cell(local, touched, 1) + " | " +
           cell(reinsert, touched, 1) + " | " +
           (local ? cli::fixed(local->touched.changed_median, 1) + " | " + cli::fixed(local->touched.changed_mean, 1) +
                        " | " + cli::fixed(local->touched.changed_max, 0)
                  : std::string(" |  | ")) +
           " | " +
           cli::fixed(s.peak_rss_mib, 0) + " | " + (s.same_tree() ? "yes" : "**no**") + " |\n";
  }
  for (const Size& s : sizes)
    for (const Run& r : s.runs)
      if (!r.failure.empty())
        out += "\n" + std::to_string(s.triangles) + " triangles, " + r.configuration + ": did not start (" + r.failure +
               ").\n";
  out += "\n## Growth in N\n\n"
         "The exponent a of a fitted c·N^a (least squares on log-log, over the sizes each configuration ran).\n\n"
         "| configuration | mean per batch | median per batch | nodes touched (median) |\n|---|---:|---:|---:|\n";
  for (const char* conf : plotted_configurations)
    out += std::string("| ") + conf + " | " + exponent_cell(series(sizes, conf, mean)) + " | " +
           exponent_cell(series(sizes, conf, median)) + " | " +
           (std::string(conf) != "rebuild" ? exponent_cell(series(sizes, conf, touched)) : std::string()) +
           " |\n";
  out += "\n## Certificate upkeep\n\n"
         "Certificates kept where the tree did not change, against every certificate made again after each batch "
         "(`--upkeep all`, the reference); medians, ms per batch.\n\n"
         "| triangles | local | rebuild | local, `--upkeep all` | rebuild, `--upkeep all` | certificates made per batch "
         "(nodes), local | the same, `--upkeep all` |\n|---:|---:|---:|---:|---:|---:|---:|\n";
  const auto made = [](const Run* r) {
    return r ? cli::fixed(r->recomputed.median, 0) + " (" + cli::fixed(r->recomputed.nodes_median, 0) + ")"
             : std::string();
  };
  for (const Size& s : sizes) {
    const Run* all = s.find("local, --upkeep all");
    if (!all) continue;
    out += "| " + std::to_string(s.triangles) + " | " + cell(s.find("local"), median, 2) + " | " +
           cell(s.find("rebuild"), median, 2) + " | " + cell(all, median, 2) + " | " +
           cell(s.find("rebuild, --upkeep all"), median, 2) + " | " + made(s.find("local")) + " | " + made(all) +
           " |\n";
  }
  if (plotted)
    out += "\n## Plot\n\nMean update per batch against the number of triangles, log-log.\n\n"
           "![mean update per batch against N](update.svg)\n";
  return out;
}

std::string plot_data(const std::vector<Size>& sizes) {
  std::string out = "# N, then the mean ms per batch of local, reinsert, local double, rebuild (NaN: not run)\n";
  for (const Size& s : sizes) {
    out += std::to_string(s.triangles);
    for (const char* conf : plotted_configurations) {
      const Run* r = s.find(conf);
      out += " " + (r ? cli::approx(r->costs.average) : std::string("NaN"));
    }
    out += "\n";
  }
  return out;
}

std::string gnuplot_script(const Config& c) {
  Line_plot p;
  p.svg = c.out + "/update.svg";
  p.data = c.out + "/update-plot.dat";
  p.title = "Mean update per batch, uniform-scale, all moving, one run";
  p.ylabel = "ms per batch (log)";
  p.series.assign(std::begin(plotted_configurations), std::end(plotted_configurations));
  p.sizes = c.sizes;
  return bench::gnuplot_script(p);
}

}  // namespace kvd::bench::update_suite
