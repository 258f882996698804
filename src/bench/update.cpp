// kvd bench update: what a batch costs against the number of triangles
// (thesis chapter 7; the kinetic-cost targets of a KDS: far below a rebuild
// and growing slowly in N). Generated uniform-scale scenes, all moving
// linearly, seed 1; one run per size and configuration, reduced set, no
// validation. Writes update.csv, update.md and, with gnuplot, update.svg.
#include "update.hpp"

#include <iostream>

#include "bench.hpp"
#include "cli.hpp"
#include "gnuplot.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kernel/float_kernel.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/tree/build.hpp"
#include "sweep.hpp"

namespace kvd::bench {

namespace {

using namespace update_suite;

const char* const update_help =
    "usage: kvd bench update [--sizes N,N,...] [--events N] [--rebuild-up-to N]\n"
    "                        [--upkeep-all-up-to N] [--out DIR]\n"
    "\n"
    "The cost of a batch against the number of triangles: for each size, the\n"
    "scene of kvd generate uniform-scale --triangles N --seed 1 (all moving\n"
    "linearly), simulated for N certificate failures (default 100), reduced\n"
    "set, no validation, with\n"
    "  local                  the exact kernel and the local update\n"
    "  reinsert               the exact kernel, every piece of a moving site\n"
    "                         dragged out and inserted again from the root\n"
    "  local, double          the double kernel and the local update\n"
    "  rebuild                the exact kernel rebuilding the tree (sizes up to\n"
    "                         --rebuild-up-to, default 800)\n"
    "  local, --upkeep all    and rebuild, --upkeep all: every certificate made\n"
    "                         again after each batch (sizes up to\n"
    "                         --upkeep-all-up-to, default 100)\n"
    "Reports mean, median and max ms per batch (everything from the failure to\n"
    "the next queue minimum), the nodes the local and reinsert updates touched and\n"
    "the nodes the batch changed (the larger of the cuts and fragments made and\n"
    "those removed), the certificates made,\n"
    "the peak memory of the process, the growth exponent of the mean in N\n"
    "(least squares on log-log), and whether the exact runs of a size end in\n"
    "the same tree (they must). Writes DIR/update.csv, DIR/update.md (also to\n"
    "stdout) and, with gnuplot on the PATH, DIR/update.svg (log-log); progress\n"
    "goes to stderr, one line per run.\n"
    "\n"
    "  --sizes    numbers of triangles (default 100,200,400,800,1600,3200)\n"
    "  --out      the output directory (default bench-out), created if needed\n"
    "\n"
    "Exit status: 0 on success, 1 when the exact runs of a size end in\n"
    "different trees, 2 on bad input.\n";

struct Configuration {
  const char* name;
  bool exact;
  kinetic::Update update;
  kinetic::Upkeep upkeep;
};
constexpr Configuration configurations[] = {
    {"local", true, kinetic::Update::local, kinetic::Upkeep::local},
    {"reinsert", true, kinetic::Update::reinsert, kinetic::Upkeep::local},
    {"local, double", false, kinetic::Update::local, kinetic::Upkeep::local},
    {"rebuild", true, kinetic::Update::rebuild, kinetic::Upkeep::local},
    {"local, --upkeep all", true, kinetic::Update::local, kinetic::Upkeep::all},
    {"rebuild, --upkeep all", true, kinetic::Update::rebuild, kinetic::Upkeep::all},
};

bool wanted(const Config& c, const Configuration& conf, std::size_t n) {
  if (conf.upkeep == kinetic::Upkeep::all) return n <= c.upkeep_all_up_to;
  return conf.update != kinetic::Update::rebuild || n <= c.rebuild_up_to;
}

template <class K>
Run simulate(const K& k, const scene::Scene& s, const Config& c, const Configuration& conf) {
  kinetic::Options o;
  o.max_events = c.events;
  o.validate = kinetic::Validation::none;
  o.update = conf.update;
  o.upkeep = conf.upkeep;
  try {
    const auto sim = kinetic::simulate(k, s, o);
    return {conf.name,           conf.exact,         sim.batches.size(), cli::update_costs(sim),
            cli::certificates_recomputed(sim), cli::nodes_touched(sim), sim.structure_hash, {}};
  } catch (const tree::Build_error& e) {
    if (conf.exact) throw;  // the generated scene is valid: exactly, its triangles never meet at the start
    Run failed;
    failed.configuration = conf.name;
    failed.exact = false;
    failed.failure = e.what();
    return failed;
  }
}

}  // namespace

int update(cli::Args& args) {
  Config c;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << update_help;
      return 0;
    }
    if (a == "--sizes") c.sizes = sizes_option("update", args.value(a));
    else if (a == "--events") c.events = args.unsigned_value(a);
    else if (a == "--rebuild-up-to") c.rebuild_up_to = args.unsigned_value(a);
    else if (a == "--upkeep-all-up-to") c.upkeep_all_up_to = args.unsigned_value(a);
    else if (a == "--out") c.out = args.value(a);
    else args.unknown(a);
  }
  make_out("update", c.out);

  std::vector<Size> sizes;
  bool all_same = true;
  for (std::size_t n : c.sizes) {
    std::cerr << "kvd bench update: generating " << n << " triangles\n";
    const scene::Scene s = generated("update", "uniform-scale", n, 1, 1);
    Size size;
    size.triangles = n;
    for (const Configuration& conf : configurations) {
      if (!wanted(c, conf, n)) continue;
      size.runs.push_back(conf.exact ? simulate(Exact_kernel(), s, c, conf) : simulate(Double_kernel(), s, c, conf));
      const Run& r = size.runs.back();
      if (!r.failure.empty()) {
        std::cerr << "kvd bench update: " << n << " triangles, " << r.configuration << ": " << r.failure << "\n";
        continue;
      }
      std::cerr << "kvd bench update: " << n << " triangles, " << r.configuration << ": " << r.batches
                << " batches, mean " << cli::fixed(r.costs.average, 3) << " ms, median "
                << cli::fixed(r.costs.median, 3) << " ms\n";
    }
    size.peak_rss_mib = cli::peak_rss_mib();
    all_same = all_same && size.same_tree();
    sizes.push_back(std::move(size));
  }
  cli::write_atomically("bench update", c.out + "/update.csv", csv(sizes));
  cli::write_atomically("bench update", c.out + "/update-plot.dat", plot_data(sizes));
  const bool plotted = run_gnuplot("update", c.out + "/update.gp", gnuplot_script(c), {c.out + "/update.svg"});
  const std::string md = markdown(c, sizes, plotted);
  cli::write_atomically("bench update", c.out + "/update.md", md);
  std::cout << md;
  std::cerr << "kvd bench update: wrote " << c.out << "/update.md, " << c.out << "/update.csv"
            << (plotted ? ", " + c.out + "/update.svg" : std::string()) << "\n";
  if (!all_same) {
    std::cerr << "kvd bench update: the exact runs of a size end in different trees\n";
    return 1;
  }
  return 0;
}

}  // namespace kvd::bench
