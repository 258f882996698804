// kvd simulate --certificates paper on a segment scene: the run on seed
// 003's own certificate set (kvd/segments/aeg_kinetic_bsp.hpp), its batches
// and the certificates that fail in them.
#include <algorithm>
#include <array>
#include <iostream>
#include <numeric>

#include "json_out.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"
#include "report.hpp"
#include "segment_commands.hpp"

namespace kvd::cli {

namespace {

using segments::Aeg_certificate_kind;

const char* kind_text(Aeg_certificate_kind k) { return segments::aeg_certificate_kind_names[static_cast<int>(k)]; }

// Where a batch decided its signs, by name.
Json signs_by(const segments::Aeg_phases& p) {
  Json out = Json::object();
  for (const auto& [name, signs] : p.named()) out[name] = signs;
  return out;
}

}  // namespace

int segment_simulate_paper(const Scene_args& sa, const segments::Segment_scene& s, const Segment_run_options& o) {
  const Exact_kernel k(o.filter);  // --no-filter: every sign in exact arithmetic
  using Run = segments::Aeg_kinetic_bsp<Exact_kernel>;
  const auto [run, construction_ms] = start_run<Run>(k, s, o.validate);
  std::vector<Run::Batch> listed;  // with --list
  std::size_t changed = 0, simultaneous = 0;
  std::size_t replays = 0, frontier = 0, flipped = 0;
  std::array<std::size_t, 3> by_kind{};
  std::vector<double> ms, made, certified, signs;
  const auto [stopped, batches, failures, reached] = run_batches(run, k, o, [&](Run::Batch&& b) {
    signs.push_back(static_cast<double>(b.signs));
    changed += b.changed;
    simultaneous += b.failing.size() > 1;
    replays += b.replays;
    frontier += b.frontier_replays;
    flipped += b.flipped_in_place > 0;
    for (const auto& id : b.failing) ++by_kind[static_cast<std::size_t>(id.kind)];
    ms.push_back(b.update_seconds * 1e3);
    made.push_back(static_cast<double>(b.nodes_rebuilt));
    certified.push_back(static_cast<double>(b.certificates_made));
    if (o.list) listed.push_back(std::move(b));
  });
  const double mean = ms.empty() ? 0 : std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
  const double max = ms.empty() ? 0 : *std::max_element(ms.begin(), ms.end());
  const segments::Bsp_counts c = run.tree().counts();
  // Lemma 3.1: O(1) certificates change at an event.
  const double certified_mean =
      certified.empty() ? 0 : std::accumulate(certified.begin(), certified.end(), 0.0) / static_cast<double>(certified.size());
  const double certified_max = certified.empty() ? 0 : *std::max_element(certified.begin(), certified.end());
  if (sa.json) {
    Json kinds = Json::object();
    for (std::size_t i = 0; i < 3; ++i) kinds[segments::aeg_certificate_kind_names[i]] = by_kind[i];
    Json j = {{"kernel", kernel_label(k)}, {"certificate_set", "paper"}, {"segments", s.segments.size()},
              {"batches", batches}, {"failures", failures}, {"failures_by_kind", kinds},
              {"changed_batches", changed}, {"simultaneous_batches", simultaneous}, {"stopped", stopped},
              {"validation", o.validate ? "every" : "none"}, {"validations", run.validations()},
              {"validation_failures", run.validation_failures().size()},
              {"time_reached_exact", k.to_string(reached)}, {"time_reached", approx(k.to_double(reached))},
              {"nodes", c.nodes}, {"height", c.height}, {"certificates", run.certificates()},
              {"construction_ms", decimal(fixed(construction_ms, 3))},
              {"update_ms", {{"mean", decimal(fixed(mean, 3))}, {"median", decimal(fixed(median(ms), 3))},
                             {"max", decimal(fixed(max, 3))}}},
              {"nodes_rebuilt_median", median(made)}, {"signs_median", median(signs)}, {"replays", replays}, {"frontier_replays", frontier},
              {"flips_in_place", flipped},
              {"certificates_made", {{"mean", decimal(fixed(certified_mean, 2))}, {"median", median(certified)},
                                     {"max", static_cast<std::size_t>(certified_max)}}}};
    if (o.list) {
      Json list = Json::array();
      for (const auto& b : listed) {
        Json failing = Json::array();
        for (const auto& id : b.failing) failing.push_back({{"kind", kind_text(id.kind)}, {"of", segments::aeg_certificate_subject(id)}});
        list.push_back({{"time", k.to_string(b.time)}, {"approx", approx(k.to_double(b.time))},
                        {"failing", failing}, {"changed", b.changed}, {"certificates", b.certificates},
                        {"replays", b.replays}, {"frontier_replays", b.frontier_replays}, {"nodes_rebuilt", b.nodes_rebuilt},
                        {"flipped_in_place", b.flipped_in_place}, {"nodes_edited", b.nodes_edited},
                        {"certificates_made", b.certificates_made}, {"signs", b.signs}, {"held", b.held},
                        {"repeated", b.repeated},
                        {"signs_by", signs_by(b.phases)},
                        {"update_ms", decimal(fixed(b.update_seconds * 1e3, 3))}});
      }
      j["batch_list"] = list;
    }
    std::cout << json_line(j) << "\n";
  } else {
    if (o.list)
      for (const auto& b : listed) {
        std::cout << "t = " << k.to_string(b.time) << " (" << approx(k.to_double(b.time)) << "):";
        for (std::size_t i = 0; i < b.failing.size(); ++i)
          std::cout << (i ? ";" : "") << " " << kind_text(b.failing[i].kind) << " " << segments::aeg_certificate_subject(b.failing[i]);
        std::cout << (b.changed ? "; tree changed" : "; tree unchanged") << "\n";
      }
    std::cout << "kernel:        " << kernel_label(k) << "\ncertificates:  paper (seed 003: transient nodes, "
              << "endpoints' neighbours, flips)\nsegments:      " << s.segments.size()
              << "\nbatches:       " << batches << " (" << changed << " changed the tree, " << simultaneous
              << " simultaneous)\nfailures:      " << failures << " (";
    for (std::size_t i = 0; i < 3; ++i) std::cout << (i ? ", " : "") << by_kind[i] << " " << kind_text(Aeg_certificate_kind(i));
    std::cout << ")\nstopped:       " << stopped << " at t = " << k.to_string(reached)
              << "\nvalidations:   " << run.validations() << " (" << run.validation_failures().size() << " failed)"
              << "\ntree:          " << c.nodes << " nodes, height " << c.height << ", " << run.certificates()
              << " certificates\nconstruction:  " << fixed(construction_ms, 3)
              << " ms (the tree and its certificates)\nupdate (ms):   mean " << fixed(mean, 3) << ", median "
              << fixed(median(ms), 3) << ", max " << fixed(max, 3) << "\nnodes made:    median " << median(made)
              << " a batch (" << replays
              << " subtrees replayed, " << flipped << " flips done in place)\ncertificates made: median "
              << median(certified) << ", mean " << fixed(certified_mean, 2) << ", max " << certified_max
              << " a batch\nsigns decided: median " << median(signs) << " a batch\n";
  }
  for (const auto& f : run.validation_failures()) std::cerr << "kvd simulate: validation failed: " << f << "\n";
  return run.validation_failures().empty() ? 0 : 1;
}

}  // namespace kvd::cli
