#include "kvd/detail/kinetic/event_queue.hpp"

#include <array>

#include <boost/heap/pairing_heap.hpp>

#include "kvd/detail/tree/slot_room.hpp"
#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/detail/tree/slot_marks.hpp"
#include "kvd/kernel/kernel.hpp"

namespace kvd::kinetic {

namespace {

// The thesis's kinetic priority queue. Changes mark the path to the root;
// first() recomputes the marked nodes bottom-up (a kinetic tournament).
template <class K>
class Tree_queue final : public Event_queue<K> {
  using Time = typename K::Time;
  struct Earliest {
    std::optional<Time> time;
    std::vector<std::size_t> ids;
  };
  struct Slot {
    int parent = -1, left = -1, right = -1;
    std::vector<std::pair<std::size_t, Time>> own;  // certificates that can fail
    mutable Earliest earliest;                      // of the subtree
    mutable bool dirty = true;
  };

public:
  explicit Tree_queue(const K& k) : k_(&k) {}

  void reset(const tree::Kvd_tree& t) override {
    tree::room_for(slots_, t.nodes.size());
    slots_.assign(t.nodes.size(), Slot{});
    for (std::size_t i = 0; i < t.nodes.size(); ++i) {
      slots_[i].left = t.nodes[i].left;
      slots_[i].right = t.nodes[i].right;
      for (int c : {t.nodes[i].left, t.nodes[i].right})
        if (c >= 0) slots_[static_cast<std::size_t>(c)].parent = static_cast<int>(i);
    }
    root_ = t.root;
    where_.clear();
  }

  // Only the nodes whose children changed, and their ancestors, recompute
  // their earliest failures.
  void reshape(const tree::Kvd_tree& t, const tree::Tree_links& links, const std::vector<int>* edited) override {
    for (std::size_t i = t.nodes.size(); i < slots_.size(); ++i)
      for (const auto& [id, time] : slots_[i].own) where_[id] = -1;
    slots_.resize(t.nodes.size());  // new slots are dirty
    root_ = t.root;
    // Released slots are left without links, and dirty: their earliest
    // failures are stale.
    const auto unlink = [&](std::size_t i) {
      Slot unlinked;
      unlinked.own = std::move(slots_[i].own);
      slots_[i] = std::move(unlinked);
    };
    std::vector<int> relinked;
    const auto relink = [&](int n) {
      const tree::Node& node = t.nodes[static_cast<std::size_t>(n)];
      Slot& s = slot(n);
      if (s.left != node.left || s.right != node.right) s.dirty = true;
      s.left = node.left;
      s.right = node.right;
      for (int c : {node.left, node.right})
        if (c >= 0) slot(c).parent = n;
      relinked.push_back(n);
    };
    if (edited) {
      for (int n : *edited) {
        if (static_cast<std::size_t>(n) >= slots_.size()) continue;  // released and dropped: unlinked above
        if (links.live(n)) relink(n);
        else unlink(static_cast<std::size_t>(n));
      }
    } else {
      for (std::size_t i = 0; i < slots_.size(); ++i)
        if (links.live(static_cast<int>(i))) relink(static_cast<int>(i));
        else unlink(i);
    }
    if (t.root >= 0) slot(t.root).parent = -1;
    // A dirty node's ancestors are dirty again (mark() relies on it); each
    // path is walked up to a node already walked.
    for (int n : relinked) {
      if (!slot(n).dirty) continue;
      for (int i = slot(n).parent; i >= 0 && walked_.set(static_cast<std::size_t>(i)); i = slot(i).parent)
        slot(i).dirty = true;
    }
    walked_.clear();
  }

  void set(std::size_t id, int node, std::optional<Time> time) override {
    if (id < where_.size() && where_[id] >= 0) {  // leave the old node
      auto& own = slot(where_[id]).own;
      std::erase_if(own, [&](const auto& e) { return e.first == id; });
      mark(where_[id]);
    }
    if (id >= where_.size()) where_.resize(id + 1, -1);
    where_[id] = time ? node : -1;
    if (!time) return;
    slot(node).own.emplace_back(id, std::move(*time));
    mark(node);
  }

  std::vector<std::size_t> first() const override { return root_ < 0 ? std::vector<std::size_t>{} : earliest(root_).ids; }
  std::optional<Time> first_time() const override { return root_ < 0 ? std::nullopt : earliest(root_).time; }

private:
  Slot& slot(int n) { return slots_[static_cast<std::size_t>(n)]; }
  const Slot& slot(int n) const { return slots_[static_cast<std::size_t>(n)]; }

  // A dirty node's ancestors are dirty: the walk stops at the first one.
  void mark(int n) {
    for (; n >= 0 && !slot(n).dirty; n = slot(n).parent) slot(n).dirty = true;
  }

  // The least failure time in the subtree and every id failing then; each
  // candidate is compared once, and only the least time is copied.
  const Earliest& earliest(int n) const {
    const Slot& s = slot(n);
    if (!s.dirty) return s.earliest;
    const Time* least = nullptr;  // into s.own or a child's earliest, both left alone below
    std::vector<std::size_t> ids;
    const auto offer = [&](const Time& t, const auto& more) {
      const int cmp = least ? k_->compare(t, *least) : -1;
      if (cmp < 0) least = &t, ids.assign(more.begin(), more.end());
      else if (cmp == 0) ids.insert(ids.end(), more.begin(), more.end());
    };
    for (const auto& [id, t] : s.own) offer(t, std::array{id});
    for (int c : {s.left, s.right}) {
      if (c < 0) continue;
      const Earliest& sub = earliest(c);
      if (sub.time) offer(*sub.time, sub.ids);
    }
    s.earliest.time = least ? std::optional<Time>(*least) : std::nullopt;
    s.earliest.ids = std::move(ids);
    s.dirty = false;
    return s.earliest;
  }

  const K* k_;
  std::vector<Slot> slots_;
  std::vector<int> where_;  // the node holding each certificate, -1 if none
  tree::Slot_marks walked_;  // reshape's, cleared after each
  int root_ = -1;
};

// An ordinary mutable heap over all certificates.
template <class K>
class Heap_queue final : public Event_queue<K> {
  using Time = typename K::Time;
  struct Entry {
    Time time;
    std::size_t id;
  };
  struct Later {
    const K* k;
    bool operator()(const Entry& a, const Entry& b) const {
      const int c = k->compare(a.time, b.time);
      return c != 0 ? c > 0 : a.id > b.id;
    }
  };
  using Heap = boost::heap::pairing_heap<Entry, boost::heap::compare<Later>, boost::heap::mutable_<true>>;

public:
  explicit Heap_queue(const K& k) : k_(&k), heap_(Later{&k}) {}

  void reset(const tree::Kvd_tree&) override {
    heap_.clear();
    handles_.clear();
  }
  void reshape(const tree::Kvd_tree&, const tree::Tree_links&, const std::vector<int>*) override {}

  void set(std::size_t id, int, std::optional<Time> time) override {
    if (id >= handles_.size()) handles_.resize(id + 1);
    auto& h = handles_[id];
    if (h && time) heap_.update(*h, Entry{std::move(*time), id});
    else if (h) heap_.erase(*h), h.reset();
    else if (time) h = heap_.push(Entry{std::move(*time), id});
  }

  std::vector<std::size_t> first() const override {
    std::vector<std::size_t> ids;
    if (heap_.empty()) return ids;
    const Time& t = heap_.top().time;
    for (auto it = heap_.ordered_begin(); it != heap_.ordered_end() && k_->compare(it->time, t) == 0; ++it)
      ids.push_back(it->id);
    return ids;
  }
  std::optional<Time> first_time() const override {
    if (heap_.empty()) return std::nullopt;
    return heap_.top().time;
  }

private:
  const K* k_;
  Heap heap_;
  std::vector<std::optional<typename Heap::handle_type>> handles_;
};

}  // namespace

template <class K>
std::unique_ptr<Event_queue<K>> make_queue(const K& k, Queue_kind kind) {
  if (kind == Queue_kind::heap) return std::make_unique<Heap_queue<K>>(k);
  return std::make_unique<Tree_queue<K>>(k);
}

#define KVD_INSTANTIATE_QUEUE(K) template std::unique_ptr<Event_queue<K>> make_queue<K>(const K&, Queue_kind);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_QUEUE)

}  // namespace kvd::kinetic
