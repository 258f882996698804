// kvd build SCENE: construct the KVD at an instant and print the statistics
// of thesis Figure 8.4.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include "cli.hpp"
#include "json_out.hpp"
#include "report.hpp"
#include "segment_commands.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/detail/scene/exact_number.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/bsp/autopartition.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"

namespace kvd::cli {

namespace {

const char* const build_help =
    "usage: kvd build SCENE [--time T] [--seed S] [--kernel exact|double|mpfr:BITS] [--no-filter]\n"
    "                 [--bsp] [--tree] [--augmented] [--json]\n"
    "                 [--allow-intersecting]\n"
    "  --no-filter     exact kernel: every sign in exact arithmetic, without the\n"
    "                  interval filter in front (the same tree, slower)\n"
    "\n"
    "Builds the KVD of the scene valid just after time T (default: the scene's\n"
    "start) and prints the construction statistics of the thesis's Figure 8.4:\n"
    "vertices, edges, triangles, P-, E- and T-nodes, total nodes, height, and\n"
    "the build time.\n"
    "\n"
    "  --time T        an exact number (\"1/3\", \"0.25\")\n"
    "  --seed S        replace the scene's priority order by the seeded one\n"
    "  --kernel K      exact (default), double, or mpfr:BITS\n"
    "  --bsp           build the baseline instead: the randomized auto-partition\n"
    "                  BSP with free splits (exact); prints nodes, fragments,\n"
    "                  height and seconds\n"
    "  --tree          print the tree itself instead, one node a line in\n"
    "                  pre-order (the format of Kvd_tree::describe)\n"
    "  --json          one JSON object: vertices, edges, triangles, p_nodes,\n"
    "                  e_nodes, t_nodes, nodes, height, seconds, structure_hash,\n"
    "                  filter (the exact kernel's filter statistics, README;\n"
    "                  null for double and mpfr), memory (the process's peak\n"
    "                  resident MiB, and that peak per node in bytes: the\n"
    "                  scene, the classifier's caches and the tree)\n"
    "  --allow-intersecting\n"
    "                  accept triangles that intersect at the start time\n"
    "\n"
    "For a kvd-segments/1 scene (told apart by its \"format\"): the cylindrical\n"
    "BSP of the segments (seed 003, section 2.1) just after T: segments,\n"
    "crossings at T, vertex, intersection and edge cuts, nodes, leaves, height,\n"
    "how many signs each rule decided (value_by_filter: of those by value, the\n"
    "ones the exact kernel's interval filter decided; none with --no-filter),\n"
    "seconds; --tree prints the tree as nested\n"
    "parentheses ((V s3.0 L R) a vertex cut, (I s1xs4 L R) an intersection cut,\n"
    "(E s2 BELOW ABOVE) an edge cut, . a leaf); --augmented prints seed 003's\n"
    "augmented BSP instead (section 3.1.4), which a flip leaves as it was: (T\n"
    "s3.0 s1xs3 LEFT BETWEEN RIGHT) a ternary node, the two point cuts one\n"
    "segment puts into one cell, and (I s1xs4 MARKED OTHER) an intersection\n"
    "cut whose children are the side of the earlier segment's marked endpoint\n"
    "(endpoint 0) and the other; --bsp does not apply.\n"
    "\n"
    "Exit status: 0 on success, 1 when a floating-point kernel's rounding makes\n"
    "triangles cross that the exact kernel keeps apart at T, 2 on a bad scene\n"
    "(including triangles that intersect at T) or bad usage.\n";

template <class K>
int run(const K& k, const std::string& path, const scene::Scene& s, const scene::Q& time, bool json, bool tree_only) {
  const auto start = std::chrono::steady_clock::now();
  const predicates::Classifier<K> classifier(k, s);
  const tree::Kvd_tree t = with_disjoint_triangles_in(
      "build", path, k, s, time, [&] { return tree::build(classifier, k.time(from_rational<typename K::FT>(time))); });
  const std::string secs = seconds_since(start);
  const tree::Tree_statistics st = t.statistics();
  const double peak = peak_rss_mib();
  const double per_node = st.nodes ? peak * 1024 * 1024 / static_cast<double>(st.nodes) : 0;
  if (tree_only) {
    std::cout << t.describe();
  } else if (json) {
    const Json j = {{"kernel", kernel_label(k)}, {"time", time.get_str()},
                    {"vertices", s.rest.size()}, {"edges", s.edges.size()},
                    {"triangles", s.triangles.size()}, {"p_nodes", st.p_nodes},
                    {"e_nodes", st.e_nodes}, {"t_nodes", st.t_nodes}, {"nodes", st.nodes},
                    {"height", st.height}, {"seconds", decimal(secs)},
                    {"structure_hash", tree::structure_hash(t)}, {"filter", filter_json(k)},
                    {"memory", {{"peak_rss_mib", decimal(fixed(peak, 1))}, {"peak_bytes_per_node", std::lround(per_node)}}}};
    std::cout << json_line(j) << "\n";
  } else {
    std::cout << "kernel:    " << kernel_label(k) << "\ntime:      " << time.get_str() << "\nvertices:  " << s.rest.size()
              << "\nedges:     " << s.edges.size() << "\ntriangles: " << s.triangles.size()
              << "\nP-nodes:   " << st.p_nodes << "\nE-nodes:   " << st.e_nodes << "\nT-nodes:   " << st.t_nodes
              << "\nnodes:     " << st.nodes << "\nheight:    " << st.height << "\nseconds:   " << secs
              << "\nstructure: " << tree::structure_hash(t) << "\nmemory:    " << fixed(peak, 1) << " MiB peak, "
              << std::lround(per_node) << " bytes per node\n";
  }
  return 0;
}

int run_bsp(const scene::Scene& s, const scene::Q& time, bool json) {
  const auto start = std::chrono::steady_clock::now();
  const bsp::Tree t = bsp::autopartition(s, time);
  const std::string secs = seconds_since(start);
  if (json)
    std::cout << json_line({{"structure", "bsp"}, {"time", time.get_str()}, {"triangles", s.triangles.size()},
                            {"nodes", t.nodes.size()}, {"fragments", t.fragments()}, {"height", t.height()},
                            {"seconds", decimal(secs)}})
              << "\n";
  else
    std::cout << "structure: auto-partition BSP\ntime:      " << time.get_str() << "\ntriangles: " << s.triangles.size()
              << "\nnodes:     " << t.nodes.size() << "\nfragments: " << t.fragments() << "\nheight:    " << t.height()
              << "\nseconds:   " << secs << "\n";
  return 0;
}

}  // namespace

int build(Args& args) {
  Scene_args sa;
  sa.wants_time = true;
  std::string kernel = "exact";
  bool baseline = false, tree_only = false, augmented = false, filter = true;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << build_help;
      return 0;
    }
    if (a == "--bsp") baseline = true;
    else if (a == "--tree") tree_only = true;
    else if (a == "--augmented") augmented = true;
    else if (a == "--kernel") kernel = args.value(a);
    else if (a == "--no-filter") filter = false;
    else if (!sa.take(args, a)) args.unknown(a);
  }
  if (augmented && tree_only) throw Usage_error("kvd build: --tree or --augmented, not both");
  const std::string text = sa.read_text("build");
  if (segments::scene_format(text) == "kvd-segments/1") {
    std::vector<std::string> triangle_only;
    if (baseline) triangle_only.push_back("--bsp");
    if (sa.load.allow_intersecting) triangle_only.push_back("--allow-intersecting");
    refuse_triangle_flags("build", triangle_only);
    return segment_build(sa, text, kernel, filter,
                         augmented   ? Segment_tree_text::augmented
                         : tree_only ? Segment_tree_text::tree
                                     : Segment_tree_text::none);
  }
  if (augmented) throw Usage_error("kvd build: --augmented: only for kvd-segments/1 scenes");
  const scene::Scene s = sa.read_scene("build", text);
  const scene::Q time = sa.time ? *sa.time : s.start;
  if (baseline) return run_bsp(s, time, sa.json);
  return with_kernel("build", kernel, [&](const auto& k) {
    require_representable(*sa.path, s, k);
    return run(k, *sa.path, s, time, sa.json, tree_only);
  }, std::nullopt, filter);
}

}  // namespace kvd::cli
