// kvd bench update: what a batch costs with the thesis's local update
// against the reference rebuild, each with certificates kept after a batch
// and with every certificate made again (thesis chapter 7). One run per
// scene and configuration, exact kernel, reduced set, no validation.
// Writes update.md (one row per scene, medians) and update.csv (one row per
// scene and configuration).
#include <filesystem>
#include <iostream>

#include "bench.hpp"
#include "cli.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/scene_io.hpp"
#include "report.hpp"

namespace kvd::bench {

namespace {

const char* const update_help =
    "usage: kvd bench update [--scenes A,B,...] [--events N] [--data DIR] [--out DIR]\n"
    "\n"
    "The cost of a batch with --update local and --update rebuild, each with\n"
    "--upkeep local (certificates kept where the tree did not change) and\n"
    "--upkeep all (every certificate made again): one exact run of N\n"
    "certificate failures (default 100) per scene and configuration, reduced\n"
    "set, no validation. Reports medians in ms per batch, the tree part, the\n"
    "certificates made per batch, the nodes a local update touched and the\n"
    "share of batches touching fewer than 10, and whether the four runs end\n"
    "in the same tree (they must). Writes DIR/update.md (also to stdout) and\n"
    "DIR/update.csv; progress goes to stderr, one line per run.\n"
    "\n"
    "  --scenes   names under --data (default uniform-scale-100,uniform-scale-400)\n"
    "  --data     where the scenes are (default data)\n"
    "  --out      the output directory (default bench-out), created if needed\n"
    "\n"
    "Exit status: 0 on success, 1 when the runs of a scene end in different\n"
    "trees, 2 on bad input.\n";

struct Configuration {
  const char* name;
  kinetic::Update update;
  kinetic::Upkeep upkeep;
};
constexpr Configuration configurations[] = {
    {"local", kinetic::Update::local, kinetic::Upkeep::local},
    {"rebuild", kinetic::Update::rebuild, kinetic::Upkeep::local},
    {"local, --upkeep all", kinetic::Update::local, kinetic::Upkeep::all},
    {"rebuild, --upkeep all", kinetic::Update::rebuild, kinetic::Upkeep::all},
};

struct Run {
  std::size_t batches = 0;
  cli::Update_costs costs;
  cli::Recomputed recomputed;
  cli::Touched touched;
  std::string structure;
};

}  // namespace

int update(cli::Args& args) {
  std::vector<std::string> names{"uniform-scale-100", "uniform-scale-400"};
  std::size_t events = 100;
  std::string data = "data", out = "bench-out";
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << update_help;
      return 0;
    }
    if (a == "--scenes") names = cli::comma_list(args.value(a));
    else if (a == "--events") events = args.unsigned_value(a);
    else if (a == "--data") data = args.value(a);
    else if (a == "--out") out = args.value(a);
    else args.unknown(a);
  }
  if (names.empty()) throw cli::Usage_error("kvd bench update: --scenes needs at least one scene");
  // Every scene is loaded before the first run: bad input writes nothing.
  std::vector<scene::Scene> scenes;
  for (const std::string& n : names) scenes.push_back(scene::load_scene(data + "/" + n + ".json"));
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw cli::Usage_error("kvd bench update: cannot create " + out + " (" + ec.message() + ")");

  std::string csv =
      "scene,triangles,configuration,batches,median_ms,tree_median_ms,certificates_made_median,"
      "nodes_recomputed_median,nodes_touched_median,below_10_share,structure_hash\n";
  std::string md =
      "| scene | triangles | batches | local | rebuild | local, `--upkeep all` | rebuild, `--upkeep all` | tree part, "
      "local | tree part, rebuild | certificates made per batch (nodes), local | the same, `--upkeep all` | nodes "
      "touched (median) | batches touching < 10 nodes | same tree |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  bool all_same = true;
  const Exact_kernel k;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    std::vector<Run> runs;
    for (const Configuration& c : configurations) {
      kinetic::Options o;
      o.max_events = events;
      o.validate = kinetic::Validation::none;
      o.update = c.update;
      o.upkeep = c.upkeep;
      const auto sim = kinetic::simulate(k, scenes[i], o);
      runs.push_back({sim.batches.size(), cli::update_costs(sim), cli::certificates_recomputed(sim),
                      cli::nodes_touched(sim), sim.structure_hash});
      const Run& r = runs.back();
      std::cerr << "kvd bench update: " << names[i] << ", " << c.name << ": " << r.batches << " batches, median "
                << cli::fixed(r.costs.median, 3) << " ms\n";
      csv += names[i] + "," + std::to_string(scenes[i].triangles.size()) + ",\"" + c.name + "\"," +
             std::to_string(r.batches) + "," + cli::fixed(r.costs.median, 3) + "," + cli::fixed(r.costs.tree_median, 3) +
             "," + cli::fixed(r.recomputed.median, 1) + "," + cli::fixed(r.recomputed.nodes_median, 1) + "," +
             (c.update == kinetic::Update::local ? cli::fixed(r.touched.median, 1) + "," + cli::fixed(r.touched.below_10_share, 3)
                                                 : std::string(",")) +
             "," + r.structure + "\n";
    }
    const bool same = std::ranges::all_of(runs, [&](const Run& r) { return r.structure == runs[0].structure; });
    all_same = all_same && same;
    const auto made = [](const Run& r) {
      return cli::fixed(r.recomputed.median, 0) + " (" + cli::fixed(r.recomputed.nodes_median, 0) + ")";
    };
    md += "| " + names[i] + " | " + std::to_string(scenes[i].triangles.size()) + " | " + std::to_string(runs[0].batches) +
          " | " + cli::fixed(runs[0].costs.median, 2) + " | " + cli::fixed(runs[1].costs.median, 2) + " | " +
          cli::fixed(runs[2].costs.median, 2) + " | " + cli::fixed(runs[3].costs.median, 2) + " | " +
          cli::fixed(runs[0].costs.tree_median, 2) + " | " + cli::fixed(runs[1].costs.tree_median, 2) + " | " +
          made(runs[0]) + " | " + made(runs[2]) + " | " + cli::fixed(runs[0].touched.median, 1) + " | " +
          cli::fixed(100 * runs[0].touched.below_10_share, 1) + "% | " + (same ? "yes" : "**no**") + " |\n";
  }
  cli::write_atomically("bench update", out + "/update.csv", csv);
  cli::write_atomically("bench update", out + "/update.md", md);
  std::cout << md;
  std::cerr << "kvd bench update: wrote " << out << "/update.md and " << out << "/update.csv\n";
  if (!all_same) {
    std::cerr << "kvd bench update: the runs of a scene end in different trees\n";
    return 1;
  }
  return 0;
}

}  // namespace kvd::bench
