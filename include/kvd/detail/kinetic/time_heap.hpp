// A min-heap of queue entries on their failure time (a `time` member),
// compared by the kernel: exactly in the exact kernel. Entries go stale
// instead of being removed (their certificate made again or gone); the
// caller says which are, and they are dropped when they reach the top, or
// all at once when the heap has doubled since the last such sweep (`trim`).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace kvd::kinetic {

template <class K, class Entry>
class Time_heap {
public:
  // The kernel must outlive the heap.
  explicit Time_heap(const K& k) : k_(&k) {}

  bool empty() const { return entries_.empty(); }
  std::size_t size() const { return entries_.size(); }
  const Entry& top() const { return entries_.front(); }
  void clear() {
    entries_.clear();
    kept_.reset();
  }
  void push(const Entry& e) {
    entries_.push_back(e);
    std::push_heap(entries_.begin(), entries_.end(), later());
  }
  void pop() {
    std::pop_heap(entries_.begin(), entries_.end(), later());
    entries_.pop_back();
  }
  // The stale entries off the top; the earliest live entry's time.
  template <class Stale>
  std::optional<typename K::Time> next(Stale stale) {
    while (!empty() && stale(top())) pop();
    if (empty()) return std::nullopt;
    return top().time;
  }

  // Drops every stale entry once the heap holds more than twice the entries
  // the last sweep left (at least 2^10): an entry failing far ahead would
  // stay otherwise, and the heap would grow with the run. The entries at the
  // first call, pushed when the owner was made and nearly all live, count
  // as left by a sweep: sweeping them then would cost a pass over the whole
  // heap for next to nothing. So the heap holds at most about twice its
  // live entries, not twice the owner's certificates (most of which may
  // have no failure ahead), and between two sweeps come at least half as
  // many pushes as the second looks at: a constant per entry pushed.
  template <class Stale>
  void trim(Stale stale) {
    if (!kept_) kept_ = entries_.size();
    if (entries_.size() <= 2 * std::max(*kept_, std::size_t{1} << 10)) return;
    std::erase_if(entries_, stale);
    std::make_heap(entries_.begin(), entries_.end(), later());
    kept_ = entries_.size();
  }

private:
  auto later() const {
    return [k = k_](const Entry& a, const Entry& b) { return k->compare(a.time, b.time) > 0; };
  }

  const K* k_;
  std::vector<Entry> entries_;
  std::optional<std::size_t> kept_;  // the entries the last sweep left
};

}  // namespace kvd::kinetic
