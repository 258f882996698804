// kvd bench thesis: the thesis's Figures 8.4-8.9 for our implementation, in
// one process. For each family and size: the construction in every kernel,
// the BSP, occlusion culling, the simulations with all, a tenth and none of
// the triangles moving in every kernel, the kinetic gain of equation 8.1
// and the degrees of the certificate polynomials. Writes thesis.md (our
// values beside the thesis's), thesis.csv (one row per measurement) and,
// when gnuplot is installed, thesis-construction.svg and thesis-update.svg.
#include <algorithm>
#include <iostream>

#include "bench.hpp"
#include "cli.hpp"
#include "gnuplot.hpp"
#include "sweep.hpp"
#include "kvd/scene/generators.hpp"
#include "thesis.hpp"

namespace kvd::bench {

namespace {

using namespace thesis_suite;

const char* const thesis_help =
    "usage: kvd bench thesis [--sizes 25,50,100] [--events N] [--simulate-up-to N]\n"
    "                        [--kernels K1,K2,...] [--data DIR] [--out OUT]\n"
    "\n"
    "The thesis's Figures 8.4-8.9 for our implementation, for the families\n"
    "uniform-scale and uniform-density at each size (DIR/<family>-<size>.json):\n"
    "construction statistics (8.4), certificates at the start (8.5), simulations\n"
    "of N certificate failures (default 200) with all triangles moving (8.6, the\n"
    "data files) and a tenth of them (8.7, generated as kvd generate FAMILY\n"
    "--triangles SIZE --moving 1/10 --seed 1), the KVD against the BSP (8.8),\n"
    "the kinetic gain against rebuilding at sampling instants (equation 8.1),\n"
    "occlusion culling from (50,-100,50) (8.9), the cost of exactness (every\n"
    "kernel of --kernels, default exact,double; the first one is that of the\n"
    "figures), and what a scene pays for: certificates of a static scene and\n"
    "the degrees of the certificate polynomials for linear and quadratic\n"
    "motion and a rational rotation (DIR/stiff/rational-rotation.json).\n"
    "Simulations are not validated. Writes OUT/thesis.md (also to stdout),\n"
    "OUT/thesis.csv and, with gnuplot on the PATH, OUT/thesis-construction.svg\n"
    "and OUT/thesis-update.svg (log-log, one line per kernel). Progress goes to\n"
    "stderr, one line per measurement.\n"
    "\n"
    "  --sizes    numbers of triangles (default 25,50,100; the data files hold\n"
    "             25, 50, 100, 200, 400 and 800)\n"
    "  --simulate-up-to N  simulations, the kinetic gain and the cost of\n"
    "             exactness only at sizes up to N (default 200); larger sizes\n"
    "             get construction, certificates, the BSP and culling\n"
    "  --data     where the scenes are (default data)\n"
    "  --out      the output directory (default bench-out), created if needed\n"
    "\n"
    "Exit status: 0 on success, 2 on bad input.\n";

// The scenes of one family and size: the data file (all moving linearly),
// and generated as kvd generate does with seed 1, a tenth moving, none
// moving, and all moving quadratically.
struct Sized_scenes {
  std::string family;
  std::size_t size;
  scene::Scene all_moving, tenth_moving, still, quadratic;
};

// Runs gnuplot on the results; whether it wrote the plots.
bool plot(const Config& c, const Results& r) {
  // The script and its data stay beside the plots, to re-plot by hand.
  cli::write_atomically("bench thesis", c.out + "/thesis-plot.dat", plot_data(c, r));
  if (!run_gnuplot("thesis", c.out + "/thesis.gp", gnuplot_script(c),
                   {c.out + "/thesis-construction.svg", c.out + "/thesis-update.svg"}))
    return false;
  std::cerr << "kvd bench thesis: wrote " << c.out << "/thesis-construction.svg and " << c.out
            << "/thesis-update.svg\n";
  return true;
}

}  // namespace

int thesis(cli::Args& args) {
  Config c;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << thesis_help;
      return 0;
    }
    if (a == "--sizes") c.sizes = sizes_option("thesis", args.value(a));
    else if (a == "--events") c.events = args.unsigned_value(a);
    else if (a == "--simulate-up-to") c.simulate_up_to = args.unsigned_value(a);
    else if (a == "--kernels") c.kernels = cli::comma_list(args.value(a));
    else if (a == "--data") c.data = args.value(a);
    else if (a == "--out") c.out = args.value(a);
    else args.unknown(a);
  }
  // Check every name and load or generate every scene before the first
  // measurement, so bad input costs nothing and writes nothing.
  check_out("thesis", c.out);
  if (c.kernels.empty()) throw cli::Usage_error("kvd bench thesis: --kernels needs at least one kernel");
  for (const std::string& k : c.kernels) cli::with_kernel("bench thesis", k, [](const auto&) { return 0; });
  std::vector<Sized_scenes> scenes;
  for (const std::string& family : families)
    for (std::size_t size : c.sizes)
      scenes.push_back({family, size, scene::load_scene(c.data + "/" + family + "-" + std::to_string(size) + ".json"),
                        {}, {}, {}});
  const scene::Scene rotation = scene::load_scene(c.data + "/stiff/rational-rotation.json");
  for (Sized_scenes& s : scenes) {
    s.tenth_moving = generated("thesis", s.family, s.size, scene::Q(1, 10), 1);
    s.still = generated("thesis", s.family, s.size, 0, 1);
    s.quadratic = generated("thesis", s.family, s.size, 1, 2);
  }
  make_out("thesis", c.out);

  Results r;
  for (const Sized_scenes& s : scenes) {
    const auto at = [&](const std::string& figure, const std::string& kernel) {
      return Where{figure, s.family, s.size, kernel};
    };
    for (const std::string& k : c.kernels) construction(at("8.4", k), s.all_moving, r);
    bsp_construction(at("8.8", "exact"), s.all_moving, r);
    culling(at("8.9", "exact"), s.all_moving, r);
    if (s.size > c.simulate_up_to) {
      certificates(at("8.5", c.reference()), s.all_moving, r);
    } else {
      for (const std::string& k : c.kernels) {
        simulation(at("8.6", k), s.all_moving, c.events, k == c.reference(), r);
        simulation(at("8.7", k), s.tenth_moving, c.events, false, r);
        simulation(at("static", k), s.still, 0, false, r);
      }
    }
    degrees(at("degrees", "exact"), s.all_moving, r);
    degrees({"degrees", s.family + "-quadratic", s.size, "exact"}, s.quadratic, r);
  }
  degrees({"degrees", "rational-rotation", rotation.triangles.size(), "exact"}, rotation, r);

  cli::write_atomically("bench thesis", c.out + "/thesis.csv", csv(r));
  const std::string md = markdown(c, r, plot(c, r));
  cli::write_atomically("bench thesis", c.out + "/thesis.md", md);
  std::cout << md;
  std::cerr << "kvd bench thesis: wrote " << c.out << "/thesis.md and " << c.out << "/thesis.csv\n";
  return 0;
}

}  // namespace kvd::bench
