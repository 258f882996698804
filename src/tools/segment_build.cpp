// kvd build on a segment scene: the cylindrical BSP at an instant.
#include <chrono>
#include <iostream>

#include "json_out.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/segments/augmented_bsp.hpp"
#include "kvd/segments/cylindrical_bsp.hpp"
#include "kvd/segments/segment_crossings.hpp"
#include "segment_commands.hpp"

namespace kvd::cli {

namespace {

template <class K>
int run(const K& k, const Scene_args& sa, const segments::Segment_scene& s, const mpq_class& time, Segment_tree_text tree) {
  const auto start = std::chrono::steady_clock::now();
  const segments::Segment_predicates<K> pred(k, s);
  const auto t = k.time(from_rational<typename K::FT>(time));
  const segments::Cylindrical_bsp b = segments::build_cylindrical_bsp(pred, t);
  const std::string secs = seconds_since(start);
  if (tree != Segment_tree_text::none) {
    std::cout << (tree == Segment_tree_text::tree ? b.text() : segments::augment(b, pred, t).text()) << "\n";
    return 0;
  }
  const segments::Bsp_counts c = b.counts();
  const std::size_t crossings = segments::count_crossings(s, time);
  const auto& r = pred.counts();
  if (sa.json) {
    std::cout << json_line({{"kernel", kernel_label(k)}, {"time", time.get_str()}, {"segments", s.segments.size()},
                            {"crossings", crossings}, {"vertex_cuts", c.vertex_cuts},
                            {"intersection_cuts", c.intersection_cuts}, {"edge_cuts", c.edge_cuts},
                            {"nodes", c.nodes}, {"leaves", c.leaves}, {"height", c.height},
                            {"signs", {{"identity", r.identity}, {"value", r.value}, {"after", r.after},
                                       {"perturbation", r.perturbation}, {"value_by_filter", r.filtered}}},
                            {"seconds", decimal(secs)}, {"filter", filter_json(k)}})
              << "\n";
    return 0;
  }
  std::cout << "kernel:            " << kernel_label(k) << "\ntime:              " << time.get_str()
            << "\nsegments:          " << s.segments.size() << "\ncrossings:         " << crossings
            << "\nvertex cuts:       " << c.vertex_cuts << "\nintersection cuts: " << c.intersection_cuts
            << "\nedge cuts:         " << c.edge_cuts << "\nnodes:             " << c.nodes
            << "\nleaves:            " << c.leaves << "\nheight:            " << c.height
            << "\nsigns:             " << r.value << " by value (" << r.filtered << " of them by the interval filter), "
            << r.after << " just after, " << r.perturbation
            << " by the perturbation, " << r.identity << " by identity"
            << "\nseconds:           " << secs << "\n";
  return 0;
}

}  // namespace

void refuse_triangle_flags(const std::string& command, const std::vector<std::string>& given) {
  if (given.empty()) return;
  std::string list;
  for (const auto& f : given) list += (list.empty() ? "" : ", ") + f;
  throw Usage_error("kvd " + command + ": " + list + ": only for triangle scenes (this is a kvd-segments/1 scene)");
}

int segment_build(const Scene_args& sa, const std::string& text, const std::string& kernel, bool filter,
                  Segment_tree_text tree) {
  const segments::Segment_scene s = sa.read_segments("build", text);
  const mpq_class time = sa.time ? *sa.time : s.start;
  return with_kernel("build", kernel, [&](const auto& k) {
    require_representable(*sa.path, s, k);
    return run(k, sa, s, time, tree);
  }, std::nullopt, filter);
}

}  // namespace kvd::cli
