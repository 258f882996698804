// A hash table stored flat: open addressing in one array with Robin Hood
// linear probing (an element travelling farther from its home slot takes
// the place of one nearer its own), at most 7/8 full, erasing by shifting
// back (no tombstones). For the run's large tables that every certificate
// of a batch looks up: a node-based std::unordered_map costs a lookup three
// or four cache misses (the bucket, the node before the bucket's first, the
// nodes of the chain), this one about one, in about the same memory.
//
// Unlike std::unordered_map, an insertion or an erasure may move other
// elements: a reference into the table is valid only until the next
// insertion or erasure. Keys and values are default-constructible (an
// empty slot holds default ones).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace kvd::detail {

// Fibonacci hashing: a slot among 2^bits from the high bits of the product
// of h with 2^64 / φ, so that a hash weak in its low bits still spreads.
inline std::size_t fibonacci_slot(std::uint64_t h, int bits) {
  return static_cast<std::size_t>((h * 0x9e3779b97f4a7c15ull) >> (64 - bits));
}

template <class Key, class Value, class Hash>
class Flat_map {
public:
  // The value under `key`, or none.
  Value* find(const Key& key) {
    const std::size_t i = position(key);
    return i == npos ? nullptr : &slots_[i].value;
  }
  const Value* find(const Key& key) const { return const_cast<Flat_map*>(this)->find(key); }

  // The value under `key`, made (default) if absent, and whether it was.
  std::pair<Value*, bool> try_emplace(const Key& key) {
    if (const std::size_t i = position(key); i != npos) return {&slots_[i].value, false};
    if (8 * (size_ + 1) > 7 * slots_.size()) grow();
    ++size_;
    return {&slots_[place(Slot{tag(key), key, Value{}})].value, true};
  }
  Value& operator[](const Key& key) { return *try_emplace(key).first; }
  // The value under `key`, which must be there (std::out_of_range).
  Value& at(const Key& key) {
    if (Value* v = find(key)) return *v;
    throw std::out_of_range("Flat_map::at: no such key");
  }
  const Value& at(const Key& key) const { return const_cast<Flat_map*>(this)->at(key); }

  // Erases `key` if present.
  void erase(const Key& key) {
    if (const std::size_t i = position(key); i != npos) erase_slot(i);
  }
  // Erases `key` and returns its value, or none when absent.
  std::optional<Value> take(const Key& key) {
    const std::size_t i = position(key);
    if (i == npos) return std::nullopt;
    std::optional<Value> v(std::move(slots_[i].value));
    erase_slot(i);
    return v;
  }

  std::size_t size() const { return size_; }
  // f(key, value) for each element, in the table's order.
  template <class F>
  void for_each(F f) const {
    for (const Slot& s : slots_)
      if (s.tag != 0) f(s.key, s.value);
  }
  void clear() {
    slots_.clear();
    size_ = 0;
  }

private:
  struct Slot {
    std::uint64_t tag = 0;  // the key's hash with its low bit set; 0 when empty
    Key key{};
    Value value{};
  };

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  // The elements after slot i in its run, each away from its home, move
  // back one slot over it.
  void erase_slot(std::size_t i) {
    --size_;
    for (std::size_t j = next(i); slots_[j].tag != 0 && distance(j) > 0; i = j, j = next(j))
      slots_[i] = std::move(slots_[j]);
    slots_[i] = Slot{};
  }
  static std::uint64_t tag(const Key& key) { return static_cast<std::uint64_t>(Hash()(key)) | 1u; }
  std::size_t mask() const { return slots_.size() - 1; }
  std::size_t home(std::uint64_t h) const { return fibonacci_slot(h, std::countr_zero(slots_.size())); }
  std::size_t next(std::size_t i) const { return (i + 1) & mask(); }
  // How far the element in slot i lies from its home.
  std::size_t distance(std::size_t i) const { return (i - home(slots_[i].tag)) & mask(); }

  // The slot holding key, or npos: the run from its home ends at an empty
  // slot or at an element nearer its home than key would be there.
  std::size_t position(const Key& key) const {
    if (slots_.empty()) return npos;
    const std::uint64_t h = tag(key);
    for (std::size_t i = home(h), d = 0;; i = next(i), ++d) {
      const Slot& s = slots_[i];
      if (s.tag == 0 || distance(i) < d) return npos;
      if (s.tag == h && s.key == key) return i;
    }
  }

  // Puts an element that is not in the table where it belongs, moving on
  // the elements it displaces; where it went.
  std::size_t place(Slot s) {
    std::size_t at = npos;
    for (std::size_t i = home(s.tag), d = 0;; i = next(i), ++d) {
      Slot& here = slots_[i];
      if (here.tag == 0) {
        here = std::move(s);
        return at == npos ? i : at;
      }
      if (const std::size_t e = distance(i); e < d) {
        std::swap(here, s);
        if (at == npos) at = i;
        d = e;
      }
    }
  }

  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_ = std::vector<Slot>(old.empty() ? 16 : 2 * old.size());
    for (Slot& s : old)
      if (s.tag != 0) place(std::move(s));
  }

  std::vector<Slot> slots_;  // a power of two in size, or empty
  std::size_t size_ = 0;
};

}  // namespace kvd::detail
