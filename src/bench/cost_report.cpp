// The report of kvd bench cost: CSV, Markdown and the plot of the exact /
// double ratios against N.
#include "cost.hpp"
#include "gnuplot.hpp"
#include "report.hpp"

namespace kvd::bench::cost_suite {

namespace {

std::string ratio(double a, double b) { return b > 0 ? cli::fixed(a / b, 2) : ""; }
std::string ms(double x, int digits, const Size& s) { return s.double_failure.empty() ? cli::fixed(x, digits) : ""; }

long decided(const Stage_counts& c) { return c.filter + c.exact + c.after + c.perturbation; }
std::string share(long part, long whole) {
  return whole ? cli::fixed(100.0 * static_cast<double>(part) / static_cast<double>(whole), 1) + "%" : "";
}
std::string stages(const Stage_counts& c) { return std::to_string(c.filter) + " / " + std::to_string(c.exact); }

std::string csv_counts(const Stage_counts& c) {
  return std::to_string(c.filter) + "," + std::to_string(c.exact) + "," + std::to_string(c.after) + "," +
         std::to_string(c.perturbation);
}
std::string csv_stages(const Filter_statistics& f) {
  return csv_counts(f.classify) + "," + std::to_string(f.sign_at.filter) + "," + std::to_string(f.sign_at.exact) +
         "," + std::to_string(f.compare.filter) + "," + std::to_string(f.compare.exact) + "," +
         std::to_string(f.walk.filter) + "," + std::to_string(f.walk.exact);
}
std::string csv_stage_header(const std::string& run) {
  std::string out;
  for (const char* q : {"classify_filter", "classify_exact", "classify_after", "classify_perturbation",
                        "sign_at_filter", "sign_at_exact", "compare_filter", "compare_exact", "walk_filter",
                        "walk_exact"})
    out += "," + run + "_" + q;
  return out;
}

}  // namespace

std::string csv(const std::vector<Size>& sizes) {
  std::string out = "triangles,nodes,build_exact_ms,build_unfiltered_ms,build_double_ms,build_ratio,events,batches,"
                    "event_exact_ms,event_double_ms,event_ratio" +
                    csv_stage_header("build") + csv_stage_header("simulate") +
                    ",polynomials,linear_polynomials,max_degree,next_root_us,double_failure\n";
  for (const Size& s : sizes) {
    std::string quoted;
    for (char ch : s.double_failure) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    out += std::to_string(s.triangles) + "," + std::to_string(s.nodes) + "," + cli::fixed(s.build_exact, 3) + "," +
           cli::fixed(s.build_unfiltered, 3) + "," + ms(s.build_double, 3, s) + "," +
           ratio(s.build_exact, s.build_double) + "," + std::to_string(s.events) + "," + std::to_string(s.batches) +
           "," + cli::fixed(s.event_exact, 4) + "," + ms(s.event_double, 4, s) + "," +
           ratio(s.event_exact, s.event_double) + "," + csv_stages(s.build_stages) + "," +
           csv_stages(s.simulate_stages) + "," + std::to_string(s.polynomials) + "," +
           std::to_string(s.linear_polynomials) + "," + std::to_string(s.max_degree) + "," +
           cli::fixed(s.next_root_us, 3) + ",\"" + quoted + "\"\n";
  }
  return out;
}

std::string markdown(const Config& c, const std::vector<Size>& sizes, bool plotted) {
  std::string out =
      "## Exact against double\n\n"
      "`kvd generate uniform-scale --triangles N --seed 1` (all moving linearly). The build of the KVD at the start, "
      "and the update time per certificate failure over the first " +
      std::to_string(c.events) +
      " failures (reduced set, no validation), as `kvd simulate` reports it: the tree, the certificates and the "
      "queue, and the record of the tree, but not taking the failures off the queue. The runs of a size are "
      "interleaved and repeated " +
      std::to_string(c.repeats) + " times; medians, ms.\n\n"
      "| triangles | tree nodes | build: exact | exact, no filter | double | exact / double | events (batches) | "
      "per event: exact | double | exact / double |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Size& s : sizes)
    out += "| " + std::to_string(s.triangles) + " | " + std::to_string(s.nodes) + " | " +
           cli::fixed(s.build_exact, 1) + " | " + cli::fixed(s.build_unfiltered, 1) + " | " +
           ms(s.build_double, 1, s) + " | " + ratio(s.build_exact, s.build_double) + " | " +
           std::to_string(s.events) + " (" + std::to_string(s.batches) + ") | " + cli::fixed(s.event_exact, 3) +
           " | " + ms(s.event_double, 3, s) + " | " + ratio(s.event_exact, s.event_double) + " |\n";
  for (const Size& s : sizes)
    if (!s.double_failure.empty())
      out += "\n" + std::to_string(s.triangles) + " triangles, double: did not start (" + s.double_failure + ").\n";
  out += "\n## Filter statistics\n\n"
         "Which stage of the exact kernel decided, in one exact build and in one exact simulation (its first build "
         "and certificates included; a build makes no certificates, hence no walks): a classification "
         "by the interval filter, by exact arithmetic after the filter could not tell, or, its value being zero, "
         "by the derivative or the perturbation rule; `sign_at`, the comparison of two algebraic instants, and the "
         "signs of the certificate walks (a wall's side, the order of two walls) by the filter / exactly.\n\n"
         "| triangles | run | classifications | by the filter | exactly | derivative | perturbation | filter share | "
         "sign_at: filter / exact | compare: filter / exact | walks: filter / exact |\n"
         "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Size& s : sizes)
    for (const auto& [run, f] : {std::pair{"build", &s.build_stages}, std::pair{"simulation", &s.simulate_stages}}) {
      const Stage_counts& k = f->classify;
      out += "| " + std::to_string(s.triangles) + " | " + run + " | " + std::to_string(decided(k)) + " | " +
             std::to_string(k.filter) + " | " + std::to_string(k.exact) + " | " + std::to_string(k.after) + " | " +
             std::to_string(k.perturbation) + " | " + share(k.filter, decided(k)) + " | " + stages(f->sign_at) +
             " | " + stages(f->compare) + " | " + stages(f->walk) + " |\n";
    }
  out += "\n## next_root on certificate polynomials\n\n"
         "Every distinct certificate polynomial the exact simulation put in force, asked for its first "
         "sign-changing root after the rational upper end of the instant it was made; microseconds per call "
         "(median of the repetitions, each looping over all the polynomials for at least 50 ms).\n\n"
         "| triangles | polynomials | of degree 1 | highest degree | µs per call |\n|---:|---:|---:|---:|---:|\n";
  for (const Size& s : sizes)
    out += "| " + std::to_string(s.triangles) + " | " + std::to_string(s.polynomials) + " | " +
           std::to_string(s.linear_polynomials) + " | " + std::to_string(s.max_degree) + " | " +
           cli::fixed(s.next_root_us, 3) + " |\n";
  if (plotted)
    out += "\n## Plot\n\nExact against double, build and per event, against the number of triangles.\n\n"
           "![exact / double against N](cost.svg)\n";
  return out;
}

std::string plot_data(const std::vector<Size>& sizes) {
  std::string out = "# N, then exact / double for the build and per event (NaN: double did not start)\n";
  for (const Size& s : sizes) {
    const bool ran = s.double_failure.empty() && s.build_double > 0 && s.event_double > 0;
    out += std::to_string(s.triangles) + " " + (ran ? cli::approx(s.build_exact / s.build_double) : "NaN") + " " +
           (ran ? cli::approx(s.event_exact / s.event_double) : "NaN") + "\n";
  }
  return out;
}

std::string gnuplot_script(const Config& c) {
  Line_plot p;
  p.svg = c.out + "/cost.svg";
  p.data = c.out + "/cost-plot.dat";
  p.title = "Exact against double, uniform-scale, all moving (medians of " + std::to_string(c.repeats) + ")";
  p.ylabel = "exact / double";
  p.series = {"build", "per event"};
  p.sizes = c.sizes;
  p.log_y = false;
  p.reference = 1.5;
  p.reference_title = "1.5";
  return bench::gnuplot_script(p);
}

}  // namespace kvd::bench::cost_suite
