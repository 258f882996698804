#include "kvd/segments/kinetic_segment_bsp.hpp"

#include <chrono>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/kinetic/validator.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::segments {

template <class K>
Kinetic_segment_bsp<K>::Kinetic_segment_bsp(const K& k, Segment_scene scene, bool validate, Segment_update update)
    : k_(k),
      scene_(std::move(scene)),
      validate_(validate),
      update_(update),
      now_(k_.time(from_rational<typename K::FT>(scene_.start))),
      pred_(k_, scene_) {
  rebuild();
}

template <class K>
void Kinetic_segment_bsp<K>::rebuild() {
  certificates_.clear();
  pred_.record(&certificates_);
  tree_ = build_cylindrical_bsp(pred_, now_);
  pred_.record(nullptr);
  failing_.clear();
  // A failure after the span's end is no event; without an end, every one is.
  const bool bounded = scene_.end.has_value();
  const Time end = bounded ? k_.time(from_rational<typename K::FT>(*scene_.end)) : now_;
  for (const auto& [key, polys] : certificates_) {
    std::optional<Time> first;
    for (const auto& q : polys) {
      const auto& r = roots_.next_root(k_, q, now_);
      if (r && (!first || k_.compare(*r, *first) < 0)) first = r;
    }
    if (first && !(bounded && k_.compare(*first, end) > 0)) failing_.emplace_back(key, *first);
  }
}

template <class K>
std::optional<typename K::Time> Kinetic_segment_bsp<K>::next_event_time() {
  std::optional<Time> first;
  for (const auto& [key, time] : failing_)
    if (!first || k_.compare(time, *first) < 0) first = time;
  return first;
}

template <class K>
typename Kinetic_segment_bsp<K>::Batch Kinetic_segment_bsp<K>::advance() {
  const Time t = *next_event_time();
  Batch b{t, {}, {}, false, 0, 0, 0};
  for (const auto& [key, time] : failing_) {
    if (k_.compare(time, t) == 0) {
      b.failing.push_back(key);
      ++b.events[static_cast<std::size_t>(event_of(key, scene_.rank))];
    }
  }
  if (validate_) {
    const Segment_predicates<K> oracle(k_, scene_);
    const Time mid = kinetic::between(k_, now_, t);
    ++validations_;
    if (build_cylindrical_bsp(oracle, mid).text() != tree_.text())
      failures_.push_back("the tree in force before t = " + k_.to_string(t) +
                          " differs from a fresh build at t = " + k_.to_string(mid));
  }
  const std::string before = tree_.text();
  const auto start = std::chrono::steady_clock::now();
  now_ = t;
  rebuild();
  b.update_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  b.changed = tree_.text() != before;
  b.nodes_rebuilt = tree_.counts().nodes;
  b.certificates = certificates_.size();
  return b;
}

#define KVD_INSTANTIATE_KINETIC_SEGMENT_BSP(K) template class Kinetic_segment_bsp<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_KINETIC_SEGMENT_BSP)

}  // namespace kvd::segments
