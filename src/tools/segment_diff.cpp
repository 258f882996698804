// kvd diff on a segment scene: the exact kinetic segment BSP against the same
// run in another kernel (segments/segment_differential.hpp).
#include "diff_report.hpp"
#include "kvd/segments/segment_differential.hpp"
#include "segment_commands.hpp"

namespace kvd::cli {

int segment_diff(const Scene_args& sa, const std::string& text, const std::string& kernel, std::size_t events,
                 const std::optional<mpq_class>& epsilon) {
  const segments::Segment_scene s = sa.read_segments("diff", text);
  const auto progress = [](const std::string& which) { return progress_every_few_seconds("kvd diff: " + which + " run"); };
  // The kernel name and the numbers it must hold, before the exact run.
  with_kernel("diff", kernel, [&](const auto& k) {
    require_representable(*sa.path, s, k);
    return 0;
  }, epsilon);
  const segments::Segment_exact_run exact = segments::run_exact(s, events, progress("exact"));
  return with_kernel("diff", kernel, [&](const auto& k) {
    const auto d = segments::compare_with(exact, k, s, progress(kernel_label(k)));
    using Key = segments::Segment_certificate_key;
    const Diff_view<Key> v{
        d, [&](std::size_t b) -> const Exact_time& { return exact.run.batches[b].time; },
        [&](const Key& f) {
          return Json{{"certificate", segments::kind_name(f.kind)},
                      {"event_kind", segments::segment_event_names[static_cast<int>(segments::event_of(f, s.rank))]},
                      {"features", segments::features(f)}};
        },
        [&](const Key& f) {
          return std::string(segments::kind_name(f.kind)) + " (" +
                 segments::segment_event_names[static_cast<int>(segments::event_of(f, s.rank))] + ") " +
                 segments::features(f);
        },
        d.recovery};
    if (sa.json) print_diff_json(*sa.path, kernel, v);
    else print_diff_text(kernel, v);
    return 0;
  }, epsilon);
}

}  // namespace kvd::cli
