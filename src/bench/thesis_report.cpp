// The outputs of kvd bench thesis: thesis.csv, thesis.md (our values beside
// the thesis's) and the plots' data and gnuplot script.
#include <algorithm>
#include <functional>
#include <thread>
#include <tuple>
#include <utility>

#include "report.hpp"
#include "thesis.hpp"

namespace kvd::bench::thesis_suite {

namespace {

const char* const dash = "—";

std::string number(const std::optional<double>& v, int digits) { return v ? cli::fixed(*v, digits) : dash; }

std::string ratio(const std::optional<double>& a, const std::optional<double>& b, int digits) {
  return a && b && *b > 0 ? cli::fixed(*a / *b, digits) : dash;
}

// `ours`, then the thesis's value where it gives one.
std::string beside(const std::string& ours, const std::optional<std::string>& theirs) {
  return theirs ? ours + " / " + *theirs : ours;
}

std::string scene_name(const std::string& family, std::size_t size) { return family + " " + std::to_string(size); }

// A table whose columns are the sizes; a row is a label and its cell at each size.
using Cell = std::function<std::string(std::size_t size)>;
struct Row {
  std::string label;
  Cell cell;
};

std::string size_table(const std::string& corner, const std::vector<std::size_t>& sizes, const std::vector<Row>& rows) {
  std::string out = "| " + corner + " |";
  for (std::size_t n : sizes) out += " " + std::to_string(n) + " |";
  out += "\n|---|";
  for (std::size_t i = 0; i < sizes.size(); ++i) out += "---:|";
  out += "\n";
  for (const Row& row : rows) {
    out += "| " + row.label + " |";
    for (std::size_t n : sizes) out += " " + row.cell(n) + " |";
    out += "\n";
  }
  return out + "\n";
}

// A plain table: a header and rows of cells.
std::string table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::string out = "|";
  for (const std::string& h : header) out += " " + h + " |";
  out += "\n|---|";
  for (std::size_t i = 1; i < header.size(); ++i) out += "---:|";
  out += "\n";
  for (const auto& row : rows) {
    out += "|";
    for (const std::string& cell : row) out += " " + cell + " |";
    out += "\n";
  }
  return out + "\n";
}

class Report {
public:
  Report(const Config& c, const Results& r) : c_(c), r_(r) {}

  std::string introduction() const {
    std::string sizes, kernels;
    for (std::size_t n : c_.sizes) sizes += (sizes.empty() ? "" : ",") + std::to_string(n);
    for (const std::string& k : c_.kernels) kernels += (kernels.empty() ? "" : ",") + k;
    return "# The thesis's Figures 8.4–8.9, ours beside the thesis's\n\n"
           "`kvd bench thesis --sizes " + sizes + " --events " + std::to_string(c_.events) + " --simulate-up-to " +
           std::to_string(c_.simulate_up_to) + " --kernels " + kernels +
           "`: one run on this machine (" + std::to_string(std::thread::hardware_concurrency()) +
           " hardware threads). The scenes are `" + c_.data + "/<family>-<N>.json` (all triangles moving "
           "linearly) and, generated in memory as `kvd generate <family> --triangles N --moving F --seed 1` "
           "does, the same families with a tenth and with none of the triangles moving. Cells are *ours / "
           "thesis* where the thesis gives a value. The figures use the " + c_.reference() +
           " kernel; the thesis's times are from its 1999 machine, so compare ratios, not times. Our scenes "
           "are other random scenes of the thesis's kind (it gives neither its box, nor its triangle, nor its "
           "draws), so counts agree in size and growth, not exactly.\n\n";
  }

  std::string construction() const {
    std::string out = "## Construction statistics (Figure 8.4)\n\n"
                      "The KVD just after time 0, as `kvd build` builds it; construction is the classifier and "
                      "the build, the median of " + std::to_string(repetitions) +
                      ", in milliseconds (the thesis gives no times).\n\n";
    for (const std::string& f : families)
      out += size_table(f, c_.sizes,
                        {{"P-nodes", ours_thesis("8.4", f, "p_nodes", 0)},
                         {"E-nodes", ours_thesis("8.4", f, "e_nodes", 0)},
                         {"T-nodes", ours_thesis("8.4", f, "t_nodes", 0)},
                         {"total nodes", ours_thesis("8.4", f, "nodes", 0)},
                         {"height", ours_thesis("8.4", f, "height", 0)},
                         {"construction ms, ours", ours_thesis("8.4", f, "construction_ms", 1)}});
    return out;
  }

  std::string certificates() const {
    std::string out = "## Certificates at time 0 (Figure 8.5)\n\n"
                      "The reduced set of the tree at time 0 (`kvd simulate --events 0`); PP counts VV, IV and "
                      "II, and VT counts VT and TT, as the thesis does.\n\n";
    for (const std::string& f : families)
      out += size_table(f, c_.sizes,
                        {{"PP", ours_thesis("8.5", f, "pp_certificates", 0)},
                         {"VE", ours_thesis("8.5", f, "ve_certificates", 0)},
                         {"VT", ours_thesis("8.5", f, "vt_certificates", 0)},
                         {"ET", ours_thesis("8.5", f, "et_certificates", 0)},
                         {"total", ours_thesis("8.5", f, "certificates", 0)}});
    return out;
  }

  std::string simulations() const {
    std::string out =
        "## Simulation (Figures 8.6 and 8.7)\n\n"
        "`kinetic::simulate`: reduced certificates, tree queue, no validation, until " +
        std::to_string(c_.events) +
        " certificate failures (the thesis ran 1000 events), the scene's end at t = 10, or a collision (where the "
        "thesis reverses the colliding objects and goes on). Milliseconds per batch of simultaneous failures. "
        "Our update is the thesis's local update (drag and out-of-order insertion) with certificates made "
        "again only where the tree changed, as `kvd simulate` runs by default.\n\n";
    for (const auto& [figure, moving] :
         {std::pair{"8.6", "all triangles moving"}, {"8.7", "10% of the triangles moving"}}) {
      for (const std::string& f : families) {
        const std::string fig = figure;
        const Cell shares = [=, this](std::size_t n) {
          return number(ref(fig, f, n, "tree_share"), 2) + " / " + number(ref(fig, f, n, "certificate_share"), 2);
        };
        const Cell thesis_shares = [=](std::size_t n) {
          const auto tree = thesis_value(fig, f, "tree_share", n), cert = thesis_value(fig, f, "certificate_share", n);
          return tree && cert ? *tree + " / " + *cert : dash;
        };
        out += size_table(f + ", " + moving, c_.simulated_sizes(),
                          {{"events (batches), how it ended", [=, this](std::size_t n) { return ending(fig, f, n); }},
                           {"construction", ours_thesis(fig, f, "construction_ms", 1)},
                           {"average update", ours_thesis(fig, f, "average_update_ms", 1)},
                           {"maximum update", ours_thesis(fig, f, "max_update_ms", 1)},
                           {"standard deviation", ours_thesis(fig, f, "stddev_update_ms", 1)},
                           {"tree / certificate share, ours", shares},
                           {"tree / certificate share, thesis", thesis_shares}});
      }
    }
    return out;
  }

  std::string bsp() const {
    std::string out = "## The KVD against the BSP (Figure 8.8)\n\n"
                      "KVD construction as in Figure 8.4; BSP construction: the randomized auto-partition BSP "
                      "with free splits (`kvd build --bsp`, exact, the median of " + std::to_string(repetitions) +
                      "); average update from Figure 8.6. The thesis's uniform-scale row of update / KVD "
                      "construction is quoted as printed, though it is not the quotient of its rows (75 / 281 = "
                      "0.27).\n\n";
    for (const std::string& f : families) {
      const Cell per_kvd = [=, this](std::size_t n) {
        return beside(ratio(ref("8.6", f, n, "average_update_ms"), ref("8.4", f, n, "construction_ms"), 3),
                      thesis_value("8.8", f, "update_per_kvd_construction", n));
      };
      const Cell per_bsp = [=, this](std::size_t n) {
        const auto bsp_ms = get("8.8", f, n, "exact", "bsp_construction_ms");
        return beside(ratio(ref("8.6", f, n, "average_update_ms"), bsp_ms, 3),
                      thesis_value("8.8", f, "update_per_bsp_construction", n));
      };
      const Cell bsp_ms = [=, this](std::size_t n) {
        return beside(number(get("8.8", f, n, "exact", "bsp_construction_ms"), 2),
                      thesis_value("8.8", f, "bsp_construction_ms", n));
      };
      out += size_table(f, c_.sizes,
                        {{"KVD construction ms",
                          ours_thesis("8.4", f, "construction_ms", 1, "8.8", "kvd_construction_ms")},
                         {"BSP construction ms", bsp_ms},
                         {"average update ms", ours_thesis("8.6", f, "average_update_ms", 1, "8.8")},
                         {"average update / KVD construction", per_kvd},
                         {"average update / BSP construction", per_bsp}});
    }
    return out;
  }

  std::string gain() const {
    std::string out =
        "## Kinetic gain against rebuilding at sampling instants (equation 8.1)\n\n"
        "The thesis's equation 8.1, over an interval with `s` samples and `e` events:\n\n"
        "    kinetic_gain = s * construction_cost - e * average_update_cost\n\n"
        "Ours, for the all-moving run of Figure 8.6 in the " + c_.reference() + " kernel:\n\n"
        "    gain(K) = K * C - B * U\n\n"
        "over the run's span [0, t_end] (t_end: its last batch, or the collision), where `B` is its number of "
        "batches and `U` their average update time (one update per batch of simultaneous failures, so `B * U` "
        "is the run's total update time), `K` the number of rebuilds at instants evenly spaced over the span, and "
        "`C` the cost of one rebuild: the median over " + std::to_string(rebuild_instants) +
        " instants evenly spaced inside the span of `tree::build` "
        "(one classifier for all, its polynomials cached, as in the simulation's rebuilds) or of "
        "`bsp::autopartition`. A positive gain means the kinetic run was cheaper; it breaks even at "
        "`K* = B * U / C`. Our update is still a rebuild followed by new certificates, so `U` exceeds the KVD's "
        "`C` and the kinetic run wins only with more samples than batches.\n\n";
    for (const auto& [structure, prefix] : {std::pair{"KVD", "kvd"}, {"BSP", "bsp"}}) {
      std::vector<std::string> header{"scene (" + std::string(structure) + ")", "span", "batches B", "B * U ms",
                                      "C ms"};
      for (std::size_t k : sampling_counts) header.push_back("gain ms, K = " + std::to_string(k));
      header.push_back("break-even K*");
      std::vector<std::vector<std::string>> rows;
      for (const std::string& f : families)
        for (std::size_t n : c_.simulated_sizes()) {
          const auto q = [&](const std::string& quantity) { return ref("gain", f, n, quantity); };
          const std::string rebuild = std::string(prefix) + "_rebuild_ms";
          std::vector<std::string> row{scene_name(f, n), number(q("span"), 3), number(q("batches"), 0),
                                       number(q("kinetic_update_ms"), 1), number(q(rebuild), 2)};
          for (std::size_t k : sampling_counts)
            row.push_back(number(q(std::string(prefix) + "_gain_" + std::to_string(k) + "_ms"), 1));
          row.push_back(ratio(q("kinetic_update_ms"), q(rebuild), 1));
          rows.push_back(row);
        }
      out += table(header, rows);
    }
    return out;
  }

  std::string culling() const {
    const std::string view = std::to_string(viewpoint[0]) + "," + std::to_string(viewpoint[1]) + "," +
                             std::to_string(viewpoint[2]);
    std::string out = "## Occlusion culling (Figure 8.9)\n\n"
                      "`kvd order --view " + view + " --cull`: the viewpoint is the decomposition point z (the "
                      "thesis does not give its viewpoint), exact. Each cell is *culled of total*.\n\n";
    for (const std::string& f : families) {
      const auto of = [=, this](const std::string& nodes, bool thesis) -> Cell {
        return [=, this](std::size_t n) {
          if (thesis) {
            const auto culled = thesis_value("8.9", f, nodes + "_culled", n);
            const auto total = thesis_value("8.9", f, nodes + "_total", n);
            return culled && total ? *culled + " of " + *total : dash;
          }
          return number(get("8.9", f, n, "exact", nodes + "_culled"), 0) + " of " +
                 number(get("8.9", f, n, "exact", nodes + "_total"), 0);
        };
      };
      out += size_table(f, c_.sizes,
                        {{"triangle nodes, ours", of("triangle_nodes", false)},
                         {"triangle nodes, thesis", of("triangle_nodes", true)},
                         {"tree nodes, ours", of("tree_nodes", false)},
                         {"tree nodes, thesis", of("tree_nodes", true)}});
    }
    return out;
  }

  std::string exactness() const {
    std::string out = "## The cost of exactness\n\n"
                      "The same construction (Figure 8.4) and all-moving simulation (Figure 8.6) in every kernel. "
                      "Certificates per batch is the simulation's `certificate_seconds`: making the certificates, "
                      "their failure times and the queue. Repairs: the signs of rounding trouble a floating-point "
                      "run detected (failed builds, repeated batches). The floating-point kernels can make more "
                      "certificates: a polynomial that is constant exactly (a vertex against the E-plane of an edge of its own "
                      "rigid triangle) keeps rounding noise in its coefficients of t, and is made.\n\n";
    std::vector<std::vector<std::string>> rows;
    for (const std::string& f : families)
      for (std::size_t n : c_.simulated_sizes())
        for (const std::string& k : c_.kernels) {
          const auto q = [&](const std::string& figure, const std::string& quantity) {
            return get(figure, f, n, k, quantity);
          };
          rows.push_back({scene_name(f, n), k, number(q("8.4", "construction_ms"), 1),
                          number(q("8.6", "events"), 0) + " (" + number(q("8.6", "batches"), 0) + ")",
                          number(q("8.5", "certificates"), 0), number(q("8.6", "average_update_ms"), 2),
                          number(q("8.6", "average_certificate_ms"), 2), number(q("8.6", "recovery_detected"), 0)});
        }
    out += table({"scene", "kernel", "construction ms", "events (batches)", "certificates at time 0",
                  "average update ms", "certificates per batch ms", "repairs"},
                 rows);
    const bool exact = std::find(c_.kernels.begin(), c_.kernels.end(), "exact") != c_.kernels.end();
    if (exact && c_.kernels.size() > 1) {
      std::vector<std::string> header{"scene"};
      for (const std::string& k : c_.kernels)
        if (k != "exact")
          for (const char* what : {"construction", "average update", "certificates per batch"})
            header.push_back(std::string(what) + ", exact / " + k);
      rows.clear();
      for (const std::string& f : families)
        for (std::size_t n : c_.simulated_sizes()) {
          std::vector<std::string> row{scene_name(f, n)};
          for (const std::string& k : c_.kernels) {
            if (k == "exact") continue;
            for (const auto& [figure, quantity] : {std::pair{"8.4", "construction_ms"},
                                                   {"8.6", "average_update_ms"},
                                                   {"8.6", "average_certificate_ms"}})
              row.push_back(ratio(get(figure, f, n, "exact", quantity), get(figure, f, n, k, quantity), 1));
          }
          rows.push_back(row);
        }
      out += "Ratios of time, exact against each other kernel:\n\n" + table(header, rows);
    } else {
      out += "(The ratios of time need exact and another kernel in --kernels.)\n\n";
    }
    return out + "The ratio of our exact root isolation to CGAL's `Algebraic_kernel_d_1` is measured by the separate "
                 "program `kvd_bench_next_root` (`src/bench/bench_next_root.cpp`; the README's Benchmarks "
                 "section), not here.\n\n";
  }

  std::string needs() const {
    std::string out = "## A scene pays only for what it needs\n\n"
                      "Certificates at time 0 and update costs (" + c_.reference() +
                      " kernel) with none, a tenth and all of the triangles moving: a static scene has no "
                      "certificate (its polynomials are constants, which are never made).\n\n";
    std::vector<std::vector<std::string>> rows;
    for (const std::string& f : families)
      for (std::size_t n : c_.simulated_sizes()) {
        const auto q = [&](const std::string& figure, const std::string& quantity) {
          return ref(figure, f, n, quantity);
        };
        rows.push_back({scene_name(f, n),
                        number(q("static", "certificates"), 0) + " / " + number(q("8.7", "certificates"), 0) + " / " +
                            number(q("8.5", "certificates"), 0),
                        number(q("8.7", "events"), 0) + " (" + number(q("8.7", "batches"), 0) + ") / " +
                            number(q("8.6", "events"), 0) + " (" + number(q("8.6", "batches"), 0) + ")",
                        number(q("8.7", "average_update_ms"), 1) + " / " + number(q("8.6", "average_update_ms"), 1)});
      }
    out += table({"scene", "certificates at time 0: 0% / 10% / 100% moving", "events (batches): 10% / 100%",
                  "average update ms: 10% / 100%"},
                 rows);
    out += "Degrees of the certificate polynomials: every polynomial of every certificate of the reduced set "
           "at time 0 (exact). The data files move linearly, `-quadratic` is the same family generated with "
           "`--degree 2`, and `rational-rotation` (`stiff/`) turns by the rational rotation of angle 2 atan t "
           "(`W = 1 + t^2`, D = 2). The bound is the reduced set's largest row (II) of table 3 in "
           "`proofs/degree-bounds.md`: `D` for rigid translations with fixed directions (its section 4), "
           "`8D + dx + 3dz` in general, with `D` the motions' degree and `dx`, `dz` those of the "
           "directions.\n\n";
    rows.clear();
    for (const Measurement& m : r_.all()) {
      if (m.where.figure != "degrees" || m.quantity != "bound") continue;
      const auto q = [&](const std::string& quantity) { return r_.get(m.where, quantity); };
      std::string histogram;
      int largest = 0;
      for (const Measurement& d : r_.all())
        if (d.where.figure == m.where.figure && d.where.family == m.where.family && d.where.size == m.where.size &&
            d.quantity.rfind("degree_", 0) == 0) {
          histogram += (histogram.empty() ? "" : ", ") + d.quantity.substr(7) + ": " + cli::fixed(d.value, 0);
          largest = std::stoi(d.quantity.substr(7));
        }
      const std::string d = number(q("D"), 0);
      const std::string bound =
          q("translations").value_or(0) > 0
              ? "D = " + d
              : "8 * " + d + " + " + number(q("dx"), 0) + " + 3 * " + number(q("dz"), 0) + " = " + number(m.value, 0);
      rows.push_back({scene_name(m.where.family, m.where.size), number(q("certificates"), 0),
                      number(q("polynomials"), 0), histogram.empty() ? dash : histogram, std::to_string(largest),
                      bound});
    }
    out += table({"scene", "certificates", "polynomials", "degree: count", "largest degree",
                  "bound: D (translations), 8D + dx + 3dz (general)"},
                 rows);
    return out;
  }

private:
  std::optional<double> get(const std::string& figure, const std::string& family, std::size_t size,
                            const std::string& kernel, const std::string& quantity) const {
    return r_.get({figure, family, size, kernel}, quantity);
  }
  std::optional<double> ref(const std::string& figure, const std::string& family, std::size_t size,
                            const std::string& quantity) const {
    return get(figure, family, size, c_.reference(), quantity);
  }

  // "ours / thesis", or ours alone where the thesis gives nothing; ours in
  // the reference kernel, the thesis's value by default of the same figure
  // and quantity.
  Cell ours_thesis(const std::string& figure, const std::string& family, const std::string& quantity, int digits,
                   const std::string& thesis_figure = "", const std::string& thesis_quantity = "") const {
    return [=, this](std::size_t n) {
      return beside(number(ref(figure, family, n, quantity), digits),
                    thesis_value(thesis_figure.empty() ? figure : thesis_figure, family,
                                 thesis_quantity.empty() ? quantity : thesis_quantity, n));
    };
  }

  // Events (batches) and how the run ended.
  std::string ending(const std::string& figure, const std::string& family, std::size_t n) const {
    const auto q = [&](const std::string& quantity) { return ref(figure, family, n, quantity); };
    if (!q("events")) return dash;
    std::string out = number(q("events"), 0) + " (" + number(q("batches"), 0) + "), ";
    const std::string reached = cli::fixed(q("time_reached").value_or(0), 3);
    if (q("stopped_by_collision")) return out + "collision at " + reached;
    if (q("stopped_by_limit")) return out + "t = " + cli::approx(q("time_limit").value_or(0)) + " (end)";
    if (q("stopped_by_exhausted")) return out + "no event after " + reached;
    return out + "event limit at " + reached;
  }

  const Config& c_;
  const Results& r_;
};

}  // namespace

std::string csv(const Results& r) {
  std::string out = "figure,family,size,kernel,quantity,value\n";
  for (const Measurement& m : r.all())
    out += m.where.figure + "," + m.where.family + "," + std::to_string(m.where.size) + "," + m.where.kernel + "," +
           m.quantity + "," + cli::approx(m.value) + "\n";
  return out;
}

std::string markdown(const Config& c, const Results& r, bool plotted) {
  const Report report(c, r);
  std::string out = report.introduction() + report.construction() + report.certificates() + report.simulations() +
                    report.bsp() + report.gain() + report.culling() + report.exactness() + report.needs();
  if (plotted)
    out += "## Plots\n\nConstruction time (Figure 8.4) and average update time (Figure 8.6) against the number of "
           "triangles, log-log, one line per kernel.\n\n"
           "![construction time](thesis-construction.svg)\n\n![average update time](thesis-update.svg)\n\n";
  return out;
}

std::string plot_data(const Config& c, const Results& r) {
  std::string out = "# N, then construction ms per kernel, then average update ms per kernel (";
  for (const std::string& k : c.kernels) out += " " + k;
  out += " ); one block per family\n";
  for (const std::string& f : families) {
    out += "# " + f + "\n";
    for (std::size_t n : c.sizes) {
      out += std::to_string(n);
      for (const auto& [figure, quantity] : {std::pair{"8.4", "construction_ms"}, {"8.6", "average_update_ms"}})
        for (const std::string& k : c.kernels) {
          const auto v = r.get({figure, f, n, k}, quantity);
          out += " " + (v ? cli::approx(*v) : "NaN");
        }
      out += "\n";
    }
    out += "\n\n";  // gnuplot's index separates blocks by two blank lines
  }
  return out;
}

// Column numbers refer to plot_data() above.
std::string gnuplot_script(const Config& c) {
  std::string kernels, family_list, tics;
  for (const std::string& k : c.kernels) kernels += (kernels.empty() ? "" : " ") + k;
  for (const std::string& f : families) family_list += (family_list.empty() ? "" : " ") + f;
  for (std::size_t n : c.sizes) tics += (tics.empty() ? "" : ", ") + std::to_string(n);
  const std::string data = c.out + "/thesis-plot.dat";
  std::string out = "set terminal svg size 1100,460 dynamic font 'sans,12'\n"
                    "set datafile missing 'NaN'\n"
                    "kernels = '" + kernels + "'\n"
                    "families = '" + family_list + "'\n"
                    "set logscale xy\n"
                    "set xtics (" + tics + ")\n"
                    "set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n"
                    "set grid\n"
                    "set key top left\n"
                    "set xlabel 'triangles (log)'\n";
  for (const auto& [name, title, label, first] :
       {std::tuple{"construction", "KVD construction (Figure 8.4)", "construction ms (log)", 2},
        {"update", "average update (Figure 8.6)", "average update ms (log)", 2 + static_cast<int>(c.kernels.size())}})
    out += std::string("set output '") + c.out + "/thesis-" + name + ".svg'\n"
           "set multiplot layout 1,2 title '" + title + " against the number of triangles, one run'\n"
           "set ylabel '" + label + "'\n"
           "do for [f=1:words(families)] {\n"
           "  set title word(families, f)\n"
           "  plot for [i=1:words(kernels)] '" + data + "' index (f-1) using 1:(column(" + std::to_string(first) +
           " + i - 1)) with linespoints pt i ps 1.2 title word(kernels, i)\n"
           "}\n"
           "unset multiplot\n";
  return out;
}

}  // namespace kvd::bench::thesis_suite
