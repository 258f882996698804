// The report of kvd bench aeg: CSV, Markdown and the plots.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "aeg.hpp"
#include "gnuplot.hpp"
#include "report.hpp"

namespace kvd::bench::aeg_suite {

namespace {

// `digits` significant digits: the rates span several decades.
std::string significant(double x, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string ratio(double a, double b, int digits) { return b > 0 ? cli::fixed(a / b, digits) : ""; }

std::string label(const Kinetic_row& r) {
  if (r.family == "rotating") return r.crossings == "linear" ? "rotating" : "rotating, long segments";
  return r.crossings == "linear" ? "random, linear motion" : "random, long segments, linear motion";
}

const Static_row* find(const std::vector<Static_row>& rows, std::size_t n, const std::string& crossings) {
  for (const Static_row& r : rows)
    if (r.n == n && r.crossings == crossings) return &r;
  return nullptr;
}

const Kinetic_row* find(const std::vector<Kinetic_row>& rows, std::size_t n, std::size_t m) {
  for (const Kinetic_row& r : rows)
    if (r.family == "random" && r.crossings == "linear" && r.n == n && r.m == m) return &r;
  return nullptr;
}

std::string value_or_nan(const Kinetic_row* r, double Kinetic_row::*ms, bool Kinetic_row::*run) {
  return r && r->*run ? cli::approx(r->*ms) : "NaN";
}

// A reference update's cell: empty (CSV) or a dash (Markdown) where it did not run.
std::string cell(bool run, const std::string& value, const char* none) { return run ? value : none; }

// Theorem 2.3's size bound, n log2 n + k.
double size_bound(std::size_t n, std::size_t k) {
  return static_cast<double>(n) * std::log2(static_cast<double>(n)) + static_cast<double>(k);
}

}  // namespace

double Static_row::size_over_bound() const {
  const double bound = size_bound(n, k);
  return bound > 0 ? static_cast<double>(counts.nodes) / bound : 0;
}

double Static_row::height_over_log() const {
  return n > 1 ? static_cast<double>(counts.height) / std::log2(static_cast<double>(n)) : 0;
}

double Kinetic_row::rate(std::size_t event) const {
  const double per = event == static_cast<std::size_t>(segments::Segment_event::flip) ? static_cast<double>(m)
                                                                                       : static_cast<double>(m * n);
  return time > 0 && per > 0 ? static_cast<double>(events[event]) / time / per : 0;
}

std::string csv(const std::vector<Static_row>& statics, const std::vector<Kinetic_row>& kinetics) {
  const std::string header =
      "part,family,crossings,n,m,k,nodes,leaves,vertex_cuts,intersection_cuts,edge_cuts,height,size_over_bound,"
      "height_over_log2n,build_exact_ms,build_double_ms,build_ratio,batches,failures,changed_batches,vertex,edge,"
      "intersection,flip,time,vertex_per_mn,edge_per_mn,intersection_per_mn,flip_per_m,local_mean_ms,local_max_ms,"
      "subtree_mean_ms,subtree_max_ms,rebuild_mean_ms,rebuild_max_ms,subtree_ratio,rebuild_ratio,nodes_rebuilt_median,"
      "subtree_nodes_median,frontier_share,same,nodes_at_start,certificates,aeg_transient,aeg_certificates,flip_batches,flip_whole,"
      "flip_local_mean_ms,flip_local_max_ms,flip_subtree_mean_ms,flip_subtree_max_ms,flip_nodes_median,"
      "flip_subtree_nodes_median,other_local_mean_ms,flip_nodes_max,flip_subtree_nodes_max\n";
  std::string out = header;
  for (const Static_row& r : statics) {
    const segments::Bsp_counts& c = r.counts;
    std::string row = "static,random," + r.crossings + "," + std::to_string(r.n) + ",0," + std::to_string(r.k) + "," +
           std::to_string(c.nodes) + "," + std::to_string(c.leaves) + "," + std::to_string(c.vertex_cuts) + "," +
           std::to_string(c.intersection_cuts) + "," + std::to_string(c.edge_cuts) + "," + std::to_string(c.height) +
           "," + significant(r.size_over_bound(), 6) + "," + significant(r.height_over_log(), 6) + "," +
           cli::fixed(r.build_exact_ms, 3) + "," + cli::fixed(r.build_double_ms, 3) + "," +
           ratio(r.build_exact_ms, r.build_double_ms, 3);
    // The kinetic columns empty: as many fields as the header's.
    const auto commas = [](const std::string& x) { return std::count(x.begin(), x.end(), ','); };
    out += row + std::string(static_cast<std::size_t>(commas(header) - commas(row)), ',') + "\n";
  }
  for (const Kinetic_row& r : kinetics) {
    out += "kinetic," + r.family + "," + r.crossings + "," + std::to_string(r.n) + "," + std::to_string(r.m) + "," +
           std::to_string(r.k) + ",,,,,,,,,,,," + std::to_string(r.batches) + "," + std::to_string(r.failures) + "," +
           std::to_string(r.changed);
    for (std::size_t e : r.events) out += "," + std::to_string(e);
    out += "," + significant(r.time, 6);
    for (std::size_t e = 0; e < r.events.size(); ++e) out += "," + significant(r.rate(e), 6);
    const bool m = r.subtree_run, b = r.rebuild_run;
    out += "," + cli::fixed(r.local_mean_ms, 3) + "," + cli::fixed(r.local_max_ms, 3) + "," +
           cell(m, cli::fixed(r.subtree_mean_ms, 3), "") + "," + cell(m, cli::fixed(r.subtree_max_ms, 3), "") + "," +
           cell(b, cli::fixed(r.rebuild_mean_ms, 3), "") + "," + cell(b, cli::fixed(r.rebuild_max_ms, 3), "") + "," +
           cell(m, ratio(r.subtree_mean_ms, r.local_mean_ms, 3), "") + "," +
           cell(b, ratio(r.rebuild_mean_ms, r.local_mean_ms, 3), "") + "," + cli::fixed(r.nodes_rebuilt_median, 1) +
           "," + cell(m, cli::fixed(r.subtree_nodes_median, 1), "") + "," + cli::fixed(r.frontier_share, 3) + "," +
           cell(m || b, r.same ? "yes" : "no", "") + "," + std::to_string(r.nodes) + "," +
           std::to_string(r.certificates) + "," + std::to_string(r.aeg.transient) + "," + std::to_string(r.aeg.total()) +
           "," + std::to_string(r.flip_batches) + "," + std::to_string(r.flip_whole) + "," +
           cli::fixed(r.flip_local_mean_ms, 3) + "," +
           cli::fixed(r.flip_local_max_ms, 3) + "," + cell(m, cli::fixed(r.flip_subtree_mean_ms, 3), "") + "," +
           cell(m, cli::fixed(r.flip_subtree_max_ms, 3), "") + "," + cli::fixed(r.flip_nodes_median, 1) + "," +
           cell(m, cli::fixed(r.flip_subtree_nodes_median, 1), "") + "," + cli::fixed(r.other_local_mean_ms, 3) + "," +
           cli::fixed(r.flip_nodes_max, 0) + "," + cell(m, cli::fixed(r.flip_subtree_nodes_max, 0), "") + "\n";
  }
  return out;
}

std::string markdown(const Config& c, const std::vector<Static_row>& statics, const std::vector<Kinetic_row>& kinetics,
                     bool plotted) {
  std::string out =
      "## Static BSP against Theorem 2.3\n\n"
      "`kvd generate segments-random --n N --crossings linear|quadratic --moving 0 --seed 1`, the tree at t = 0: "
      "short segments (length 1/ceil(sqrt(n)) of the box: k = O(n)) and long ones (half the box: k = Θ(n²)), the "
      "long ones only up to " +
      std::to_string(c.quadratic_up_to) +
      " segments (`--quadratic-up-to`: their trees grow as n², and so does the time of a build). *k*: the pairs "
      "crossing, counted exactly; *height*: nodes on the longest root-to-leaf path. The paper bounds the expected "
      "size by O(n log n + k) and the depth by O(log n): the two quotients, nodes / (n log2 n + k) and height / "
      "log2 n, must stay bounded as n grows. *Build*: from the scene to the tree, the predicates included; the "
      "exact and the double builds interleaved and repeated " +
      std::to_string(c.repeats) + " times, medians, ms.\n\n"
      "| crossings | n | k | nodes | vertex cuts | intersection cuts | edge cuts | height | nodes / (n log2 n + k) | "
      "height / log2 n | build: exact | double | exact / double |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Static_row& r : statics) {
    const segments::Bsp_counts& k = r.counts;
    out += "| " + r.crossings + " | " + std::to_string(r.n) + " | " + std::to_string(r.k) + " | " +
           std::to_string(k.nodes) + " | " + std::to_string(k.vertex_cuts) + " | " +
           std::to_string(k.intersection_cuts) + " | " + std::to_string(k.edge_cuts) + " | " +
           std::to_string(k.height) + " | " + cli::fixed(r.size_over_bound(), 2) + " | " +
           cli::fixed(r.height_over_log(), 2) + " | " + cli::fixed(r.build_exact_ms, 1) + " | " +
           cli::fixed(r.build_double_ms, 1) + " | " + ratio(r.build_exact_ms, r.build_double_ms, 1) + " |\n";
  }
  out += "\n## Kinetic BSP against Lemmas 3.2-3.6\n\n"
         "`kvd generate segments-random --n N --moving M --seed 1` (short segments, linear motion) with m = n and "
         "n/2 moving, the same with `--crossings quadratic` (long segments: k = Θ(n²)) up to " +
         std::to_string(c.kinetic_quadratic_up_to) +
         " segments (`--kinetic-quadratic-up-to`), and `kvd generate segments-rotating --n N --seed 1`, short and long "
         "(`--crossings quadratic`) segments (every "
         "segment turning about its "
         "midpoint, through vertical at most once). The exact kinetic BSP without validation, with the local "
         "update (the frontier replay where it applies), the subtree update (the failures' topmost subtrees "
         "replayed whole: the local update before the frontier replay) and rebuilding the tree, batch by batch in "
         "turn: the random scenes up to the batch holding "
         "the " +
         std::to_string(c.events) +
         "th certificate failure, the rotating ones over their whole span (the long ones not rebuilt: they have thousands of "
         "batches). *Failures*: the certificates that failed, "
         "by the event each is (vertex / edge / intersection / flip; the x orders of a turning segment's points "
         "count with its flip, so a flip is O(k_i + 1) failures); *changed*: the batches that changed the tree; "
         "*time*: from the start to the last batch, or to the span's end when the run reached it. The paper bounds "
         "the events over a span by O(mn²) vertex, O(mnλ(n)) edge, O(mn) intersection and O(m) flip events: the "
         "rate columns are the failures of a kind per unit of time, over m·n (flips: over m), so the intersection "
         "rate must stay bounded, the flip rate too where k/n does, as n grows and the vertex and edge rates may grow at most about "
         "linearly. *Update*: the tree and its certificates made just after a batch, and the queue up to its next minimum, ms per batch; subtree / local "
         "and rebuild / local of the means; *nodes made again*: median per batch, local / subtree; *frontier*: "
         "the share of the failures' topmost nodes the local update handled by the frontier replay (a flip's remade as "
         "frontier nodes included). *Same*: the "
         "updates had the same batches (times and failing certificates) and end in the same tree. The subtree update "
         "runs up to " + std::to_string(c.subtree_up_to) + " segments and the rebuild up to " +
         std::to_string(c.rebuild_up_to) + " (`--subtree-up-to`, `--rebuild-up-to`; —: not run).\n\n"
         "| scene | n | m | k | batches (changed) | failures: vertex / edge / intersection / flip | time | vertex / mn "
         "| edge / mn | intersection / mn | flip / m | local: mean | max | subtree: mean | max | rebuild: mean | max "
         "| subtree / local | rebuild / local | nodes made again | frontier | same |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const Kinetic_row& r : kinetics) {
    out += "| " + label(r) + " | " + std::to_string(r.n) + " | " + std::to_string(r.m) + " | " +
           std::to_string(r.k) + " | " + std::to_string(r.batches) + " (" + std::to_string(r.changed) + ") | ";
    for (std::size_t e = 0; e < r.events.size(); ++e) out += (e ? " / " : "") + std::to_string(r.events[e]);
    out += " | " + significant(r.time, 3);
    for (std::size_t e = 0; e < r.events.size(); ++e) out += " | " + significant(r.rate(e), 3);
    const bool m = r.subtree_run, b = r.rebuild_run;
    out += " | " + cli::fixed(r.local_mean_ms, 2) + " | " + cli::fixed(r.local_max_ms, 1) + " | " +
           cell(m, cli::fixed(r.subtree_mean_ms, 2), "—") + " | " + cell(m, cli::fixed(r.subtree_max_ms, 1), "—") +
           " | " + cell(b, cli::fixed(r.rebuild_mean_ms, 2), "—") + " | " +
           cell(b, cli::fixed(r.rebuild_max_ms, 1), "—") + " | " +
           cell(m, ratio(r.subtree_mean_ms, r.local_mean_ms, 2), "—") + " | " +
           cell(b, ratio(r.rebuild_mean_ms, r.local_mean_ms, 2), "—") + " | " + cli::fixed(r.nodes_rebuilt_median, 0) +
           " / " + cell(m, cli::fixed(r.subtree_nodes_median, 0), "—") + " | " + cli::fixed(r.frontier_share, 2) +
           " | " + cell(m || b, r.same ? "yes" : "**no**", "—") + " |\n";
  }
  out += "\n## Certificates against Lemma 3.1\n\n"
         "The same scenes at their start. *Kept*: the certificates the kinetic BSP keeps, every sign its "
         "construction decides. *Paper's*: the set of section 3.1 for the same tree, computed by "
         "`aeg_certificate_counts`: one per transient node (a child of a point cut with no point cut below: its "
         "cell collapses), one per endpoint (the segment just above or below it changes) and one per segment (it "
         "flips). Lemma 3.1 bounds the paper's set by O(n + k): paper's / (n + k) must stay bounded. The kept set "
         "holds every sign of the construction, more than one per node.\n\n"
         "| scene | n | m | k | nodes | kept | paper's: transient / endpoints / flips | paper's | kept / paper's | kept "
         "/ (n log2 n + k) | paper's / (n + k) |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Kinetic_row& r : kinetics) {
    const double kept = static_cast<double>(r.certificates), paper = static_cast<double>(r.aeg.total());
    out += "| " + label(r) + " | " + std::to_string(r.n) + " | " + std::to_string(r.m) + " | " + std::to_string(r.k) +
           " | " + std::to_string(r.nodes) + " | " + std::to_string(r.certificates) + " | " +
           std::to_string(r.aeg.transient) + " / " + std::to_string(r.aeg.endpoints) + " / " +
           std::to_string(r.aeg.flips) + " | " + std::to_string(r.aeg.total()) + " | " + ratio(kept, paper, 2) +
           " | " + cli::fixed(kept / size_bound(r.n, r.k), 2) + " | " + cli::fixed(paper / static_cast<double>(r.n + r.k), 2) + " |\n";
  }
  out += "\n## Flip events against Lemma 3.6\n\n"
         "The scenes with flips, their batches holding a flip failure apart. A flip of s_i changes the subtrees of "
         "the cells of the tree before s_i that s_i crosses (section 3.1.4): the paper's update costs O(k_i log n), "
         "and O(1) in its augmented BSP (ternary nodes and the marked endpoint), which the runs here do not keep as "
         "their tree. The local update remakes each topmost node that is the turning segment's first cut on its path, and below which "
         "every failing certificate is the x order of two points of a turning segment, as the frontier "
         "replay remakes a node (its cuts again, the later segments' subtrees moved where their arrivals did not "
         "change); the subtree update replays those nodes' subtrees whole. *Whole*: the topmost nodes of the flip "
         "batches that the local update still replayed whole (with another failure below them, or below the "
         "segment's first cut); *update*: ms per batch with a flip; "
         "*nodes made again*: median and max over the flip batches; *other batches*: the local update's mean over the "
         "batches without a flip.\n\n"
         "| scene | n | k | flip batches | whole | local: mean | max | subtree: mean | max | subtree / local | nodes made "
         "again, median: local / subtree | max: local / subtree | other batches: local mean | flip / other |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Kinetic_row& r : kinetics) {
    if (r.flip_batches == 0) continue;
    const bool m = r.subtree_run;
    out += "| " + label(r) + " | " + std::to_string(r.n) + " | " + std::to_string(r.k) + " | " +
           std::to_string(r.flip_batches) + " | " + std::to_string(r.flip_whole) + " | " +
           cli::fixed(r.flip_local_mean_ms, 2) + " | " +
           cli::fixed(r.flip_local_max_ms, 1) + " | " + cell(m, cli::fixed(r.flip_subtree_mean_ms, 2), "—") + " | " +
           cell(m, cli::fixed(r.flip_subtree_max_ms, 1), "—") + " | " +
           cell(m, ratio(r.flip_subtree_mean_ms, r.flip_local_mean_ms, 2), "—") + " | " +
           cli::fixed(r.flip_nodes_median, 0) + " / " + cell(m, cli::fixed(r.flip_subtree_nodes_median, 0), "—") +
           " | " + cli::fixed(r.flip_nodes_max, 0) + " / " + cell(m, cli::fixed(r.flip_subtree_nodes_max, 0), "—") +
           " | " + cli::fixed(r.other_local_mean_ms, 2) + " | " + ratio(r.flip_local_mean_ms, r.other_local_mean_ms, 1) +
           " |\n";
  }
  if (plotted)
    out += "\n## Plot\n\nThe two quotients of the static trees, and the mean update per batch of the random "
           "scenes, against n.\n\n![the AEG BSP against its bounds](aeg.svg)\n";
  return out;
}

std::string static_plot_data(const std::vector<Static_row>& statics) {
  std::string out = "# n, then nodes / (n log2 n + k) and height / log2 n, each for linear and quadratic crossings "
                    "(NaN: not run)\n";
  for (const Static_row& r : statics) {
    if (r.crossings != "linear") continue;
    const Static_row* q = find(statics, r.n, "quadratic");
    out += std::to_string(r.n) + " " + cli::approx(r.size_over_bound()) + " " +
           (q ? cli::approx(q->size_over_bound()) : "NaN") + " " + cli::approx(r.height_over_log()) + " " +
           (q ? cli::approx(q->height_over_log()) : "NaN") + "\n";
  }
  return out;
}

std::string kinetic_plot_data(const std::vector<Kinetic_row>& kinetics) {
  std::string out =
      "# n, then the mean ms per batch of local, subtree and rebuild with m = n, then of local and rebuild with "
      "m = n/2 (NaN: not run)\n";
  for (const Kinetic_row& r : kinetics) {
    if (r.family != "random" || r.crossings != "linear" || r.m != r.n) continue;
    const Kinetic_row* half = find(kinetics, r.n, r.n / 2);
    out += std::to_string(r.n) + " " + cli::approx(r.local_mean_ms) + " " +
           value_or_nan(&r, &Kinetic_row::subtree_mean_ms, &Kinetic_row::subtree_run) + " " +
           value_or_nan(&r, &Kinetic_row::rebuild_mean_ms, &Kinetic_row::rebuild_run) + " " +
           (half ? cli::approx(half->local_mean_ms) : "NaN") + " " +
           value_or_nan(half, &Kinetic_row::rebuild_mean_ms, &Kinetic_row::rebuild_run) + "\n";
  }
  return out;
}

std::string gnuplot_script(const Config& c) {
  Line_plot size, height, update;
  for (Line_plot* p : {&size, &height, &update}) {
    p->xlabel = "segments (log)";
    p->log_y = p == &update;
    p->sizes = p == &update ? c.kinetic_sizes : c.sizes;
    p->data = c.out + (p == &update ? "/aeg-kinetic.dat" : "/aeg-static.dat");
  }
  size.title = "Static BSP: size against n log2 n + k (Theorem 2.3)";
  size.ylabel = "nodes / (n log2 n + k)";
  size.series = {"k = O(n)", "k = Θ(n²)"};
  height.title = "Static BSP: height against log2 n (Theorem 2.3)";
  height.ylabel = "height / log2 n";
  height.series = size.series;
  height.first_column = 4;
  size.key = height.key = "bottom right";  // the lines run high and flat
  update.title = "Kinetic BSP: mean update per batch, exact, first " + std::to_string(c.events) + " failures";
  update.ylabel = "ms per batch (log)";
  update.series = {"local, m = n", "subtree, m = n", "rebuild, m = n", "local, m = n/2", "rebuild, m = n/2"};
  return bench::gnuplot_script(c.out + "/aeg.svg", {size, height, update});
}

}  // namespace kvd::bench::aeg_suite
