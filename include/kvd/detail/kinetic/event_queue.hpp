// The event queue: which certificates fail first. Two implementations of one
// interface, selected with `--queue`:
//  * tree: the thesis's kinetic priority queue (thesis 6.5), kept in the KVD
//    itself: every node holds the earliest failures of its own certificates
//    and of its subtrees, so the root holds the next batch; changing the
//    certificates of a node repairs only its path to the root;
//  * heap: an ordinary mutable heap (Boost.Heap's pairing heap) over all
//    certificates.
// "Earliest" is the kernel's compare: exact equality of algebraic numbers in
// the exact kernel, the thesis's epsilon-minimum in the floating-point ones.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "kvd/detail/tree/tree_links.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::kinetic {

enum class Queue_kind { tree, heap };

template <class K>
class Event_queue {
public:
  using Time = typename K::Time;
  virtual ~Event_queue() = default;
  // Sets the failure time of certificate `id` (none: it never fails), a
  // certificate of tree node `node`; ids are small integers.
  virtual void set(std::size_t id, int node, std::optional<Time> time) = 0;
  // Removes every certificate and adopts the shape of `t`.
  virtual void reset(const tree::Kvd_tree& t) = 0;
  // Adopts the shape of `t` keeping the certificates where they are (a
  // certificate at a node no longer in t must then be set again). `edited`
  // lists the nodes changed since the last reset or reshape
  // (Update_cost::changed); none: t may differ anywhere. `links` are t's.
  virtual void reshape(const tree::Kvd_tree& t, const tree::Tree_links& links, const std::vector<int>* edited) = 0;
  // The certificates failing first, all at one time (empty when none fails).
  virtual std::vector<std::size_t> first() const = 0;
  virtual std::optional<Time> first_time() const = 0;
};

template <class K>
std::unique_ptr<Event_queue<K>> make_queue(const K& k, Queue_kind kind);

}  // namespace kvd::kinetic
