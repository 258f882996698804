// A min-heap of queue entries on their failure time (a `time` member),
// compared by the kernel: exactly in the exact kernel. Entries go stale
// instead of being removed (their certificate made again or gone); the
// caller says which are, and they are dropped when they reach the top, or
// a few at a time by a sweep that goes round the heap (`trim`).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
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
    pushed_ = cursor_ = 0;
    started_ = false;
  }
  void push(const Entry& e) {
    entries_.push_back(e);
    std::push_heap(entries_.begin(), entries_.end(), later());
    ++pushed_;
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

  // Drops stale entries a few at a time, going round the heap from where
  // the last call stopped: each call looks at twice as many entries as were
  // pushed since the last one. An entry that went stale far ahead would
  // stay otherwise, and the heap would grow with the run. One round of the
  // heap, of n entries, comes with at most n / 2 pushes, so the heap holds
  // about its live entries and those that went stale during one round; and
  // no call costs more than a constant times its own pushes (an entry taken
  // from inside moves the last one to its place, which goes up or down a
  // few levels on average). The sweep used to drop them all at once when
  // the heap had doubled: a pause of the whole heap in one batch.
  // The entries pushed before the first call (the owner's certificates when
  // it was made, nearly all live) are not swept for: that would be a pass
  // over the whole heap for next to nothing.
  template <class Stale>
  void trim(Stale stale) {
    std::size_t budget = started_ ? 2 * pushed_ : 0;
    started_ = true;
    pushed_ = 0;
    while (budget-- > 0 && !entries_.empty()) {
      if (cursor_ >= entries_.size()) cursor_ = 0;
      // The entry moved into a dropped one's place is looked at next.
      if (stale(entries_[cursor_])) erase(cursor_);
      else ++cursor_;
    }
  }

private:
  auto later() const {
    return [k = k_](const Entry& a, const Entry& b) { return k->compare(a.time, b.time) > 0; };
  }

  // Entry i taken out: the last one goes to its place and up or down.
  void erase(std::size_t i) {
    const auto later_than = later();
    entries_[i] = std::move(entries_.back());
    entries_.pop_back();
    if (i >= entries_.size()) return;
    while (i > 0 && later_than(entries_[(i - 1) / 2], entries_[i])) {
      std::swap(entries_[i], entries_[(i - 1) / 2]);
      i = (i - 1) / 2;
    }
    for (;;) {
      std::size_t first = i;
      for (const std::size_t c : {2 * i + 1, 2 * i + 2})
        if (c < entries_.size() && later_than(entries_[first], entries_[c])) first = c;
      if (first == i) return;
      std::swap(entries_[i], entries_[first]);
      i = first;
    }
  }

  const K* k_;
  std::vector<Entry> entries_;
  std::size_t pushed_ = 0;  // since the last trim
  std::size_t cursor_ = 0;  // where the next trim looks first
  bool started_ = false;    // trimmed since made or cleared
};

}  // namespace kvd::kinetic
