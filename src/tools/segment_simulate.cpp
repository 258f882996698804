// kvd simulate on a segment scene: the kinetic cylindrical BSP (seed 003,
// section 3.1), its batches and the events by kind.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <numeric>

#include "json_out.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "report.hpp"
#include "segment_commands.hpp"

namespace kvd::cli {

namespace {

template <class K>
int run(const K& k, const Scene_args& sa, const segments::Segment_scene& s, const Segment_run_options& o) {
  using Kinetic = segments::Kinetic_segment_bsp<K>;
  const auto [kin, construction_ms] = start_run<Kinetic>(k, s, o.validate, o.update);
  std::vector<typename Kinetic::Batch> listed;  // with --list
  std::array<std::size_t, 4> events{}, changed_by{};
  std::size_t changed = 0, simultaneous = 0, frontier = 0, subtree = 0;
  std::vector<double> ms, rebuilt, signs;
  auto [stopped, batches, failures, reached] = run_batches(kin, k, o, [&](typename Kinetic::Batch&& b) {
    signs.push_back(static_cast<double>(b.signs));
    frontier += b.frontier_replays;
    subtree += b.subtree_replays;
    rebuilt.push_back(static_cast<double>(b.nodes_rebuilt));
    for (std::size_t e = 0; e < 4; ++e) {
      events[e] += b.events[e];
      changed_by[e] += b.changed && b.events[e] > 0;
    }
    changed += b.changed;
    simultaneous += b.failing.size() > 1;
    ms.push_back(b.update_seconds * 1e3);
    if (o.list) listed.push_back(std::move(b));
  });
  if (kin.stuck()) {
    stopped = "stuck";
    reached = kin.now();
  }
  const segments::Bsp_counts c = kin.tree().counts();
  const double mean = ms.empty() ? 0 : std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
  const double max = ms.empty() ? 0 : *std::max_element(ms.begin(), ms.end());
  const bool failed = !kin.validation_failures().empty() || kin.stuck();
  if (sa.json) {
    Json by_kind = Json::object(), changing = Json::object();
    for (std::size_t e = 0; e < 4; ++e) {
      by_kind[segments::segment_event_names[e]] = events[e];
      changing[segments::segment_event_names[e]] = changed_by[e];
    }
    Json list = Json::array();
    if (o.list)
      for (const auto& b : listed) {
        Json kinds = Json::object();
        for (std::size_t e = 0; e < 4; ++e)
          if (b.events[e]) kinds[segments::segment_event_names[e]] = b.events[e];
        list.push_back({{"time", k.to_string(b.time)}, {"approx", approx(k.to_double(b.time))},
                        {"failing", b.failing.size()}, {"events", kinds}, {"changed", b.changed},
                        {"certificates", b.certificates}, {"nodes_rebuilt", b.nodes_rebuilt},
                        {"frontier_replays", b.frontier_replays}, {"subtree_replays", b.subtree_replays},
                        {"signs", b.signs}, {"held", b.held},
                        {"update_ms", decimal(fixed(b.update_seconds * 1e3, 3))}});
      }
    Json j = {{"kernel", kernel_label(k)}, {"segments", s.segments.size()}, {"batches", batches},
              {"failures", failures}, {"simultaneous_batches", simultaneous}, {"changed_batches", changed},
              {"failures_by_event", by_kind}, {"changed_batches_by_event", changing}, {"stopped", stopped},
              {"validation", o.validate ? "every" : "none"}, {"validations", kin.validations()},
              {"validation_failures", kin.validation_failures().size()},
              {"time_reached_exact", k.to_string(reached)}, {"time_reached", approx(k.to_double(reached))},
              {"nodes", c.nodes}, {"height", c.height}, {"certificates", kin.certificates()},
              {"construction_ms", decimal(fixed(construction_ms, 3))},
              {"update_ms", {{"mean", decimal(fixed(mean, 3))}, {"median", decimal(fixed(median(ms), 3))},
                             {"max", decimal(fixed(max, 3))}}},
              {"update", segments::segment_update_names[static_cast<int>(o.update)]},
              {"nodes_rebuilt_median", median(rebuilt)}, {"signs_median", median(signs)},
              {"replays", {{"frontier", frontier}, {"subtree", subtree}}}, {"filter", filter_json(k)},
              {"recovery", recovery_json(kin.recovery())}};
    if (o.list) j["batch_list"] = list;
    std::cout << json_line(j) << "\n";
  } else {
    if (o.list)
      for (const auto& b : listed) {
        std::cout << "t = " << k.to_string(b.time) << " (" << approx(k.to_double(b.time)) << "): " << b.failing.size()
                  << " failing,";
        for (std::size_t e = 0; e < 4; ++e)
          if (b.events[e]) std::cout << " " << b.events[e] << " " << segments::segment_event_names[e];
        std::cout << (b.changed ? ", tree changed" : ", tree unchanged") << "\n";
      }
    std::cout << "kernel:        " << kernel_label(k) << "\nsegments:      " << s.segments.size()
              << "\nbatches:       " << batches << " (" << changed << " changed the tree, " << simultaneous
              << " simultaneous)\nfailures:      " << failures << " (";
    for (std::size_t e = 0; e < 4; ++e)
      std::cout << (e ? ", " : "") << events[e] << " " << segments::segment_event_names[e];
    std::cout << ")\nstopped:       " << stopped << " at t = " << k.to_string(reached)
              << "\nvalidations:   " << kin.validations() << " (" << kin.validation_failures().size() << " failed)"
              << "\ntree:          " << c.nodes << " nodes, height " << c.height << ", " << kin.certificates()
              << " certificates\nconstruction:  " << fixed(construction_ms, 3)
              << " ms (the tree and its certificates)\nupdate (ms):   mean " << fixed(mean, 3) << ", median "
              << fixed(median(ms), 3) << ", max " << fixed(max, 3) << "\nnodes made:    median " << median(rebuilt)
              << " a batch ("
              << segments::segment_update_names[static_cast<int>(o.update)] << ")\nsigns decided: median "
              << median(signs) << " a batch\n";
    if (o.update != segments::Segment_update::rebuild)
      std::cout << "replays:       " << frontier << " at the frontier, " << subtree << " of whole subtrees\n";
    if (kin.recovery().detected()) std::cout << "recovery:      " << recovery_text(kin.recovery()) << "\n";
  }
  for (const auto& f : kin.validation_failures()) std::cerr << "kvd simulate: validation failed: " << f << "\n";
  return failed ? 1 : 0;
}

}  // namespace

int segment_simulate(const Scene_args& sa, const std::string& text, const Segment_run_options& o) {
  const segments::Segment_scene s = sa.read_segments("simulate", text);
  if (o.until) require_in_span("simulate", "--until", *o.until, s.start, s.end);
  if (o.paper) return segment_simulate_paper(sa, s, o);
  return with_kernel("simulate", o.kernel, [&](const auto& k) {
    require_representable(*sa.path, s, k);
    return run(k, sa, s, o);
  }, o.epsilon, o.filter);
}

}  // namespace kvd::cli
