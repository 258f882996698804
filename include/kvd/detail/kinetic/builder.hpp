// The trees of a run: the classifier of the motions in force, the build and
// the local update. Triangles found crossing come back as a value (Meeting),
// not as an exception through the event loop.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "kvd/detail/kinetic/collision.hpp"
#include "kvd/detail/kinetic/local_update.hpp"
#include "kvd/detail/tree/journal.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/tree/build.hpp"

namespace kvd::kinetic {

// Triangles meeting: which features, in words, and the objects (increasing;
// empty when the build could not say).
struct Meeting {
  std::string error;
  std::vector<std::size_t> objects;
};

// The tree valid just after an instant, or why there is none.
struct Tree_after {
  std::optional<tree::Kvd_tree> tree;
  Meeting meeting;  // when there is no tree
  // A local update's tree (the tree in force, edited in place and moved
  // here): the nodes it changed (Update_cost::changed); none for a build.
  std::optional<std::vector<int>> edited;
};

template <class K>
class Builder {
  using Time = typename K::Time;

public:
  // `scene` holds the motions in force and outlives the builder.
  Builder(const K& k, const scene::Scene& scene, bool full) : k_(k), scene_(scene), full_(full) { motions_changed(); }

  // The scene's motions changed: a classifier of the new ones (its cache
  // holds motion polynomials).
  void motions_changed() { c_ = std::make_unique<const predicates::Classifier<K>>(k_, scene_); }
  const predicates::Classifier<K>& classifier() const { return *c_; }

  // The tree just after t; with the full set, the classifications it
  // evaluated are kept (evaluated()) for the certificates.
  Tree_after build(const Time& t) {
    evaluated_.clear();
    try {
      return {tree::build(*c_, t, full_ ? &evaluated_ : nullptr), {}, std::nullopt};
    } catch (const tree::Build_error& e) {
      return {std::nullopt, meeting(e), std::nullopt};
    }
  }
  const tree::Evaluated& evaluated() const { return evaluated_; }

  // `t` made, in place, the tree just after `at` by the local update moving
  // `moving` within `scope`, edited the `way` given (`links` being t's;
  // local_update), with its cost; or the meeting that stops it, `t` then left
  // exactly as it was (the update's edits are journalled and undone, as
  // they are for any exception that goes on). In a
  // floating-point kernel rounding can also leave pieces that no longer
  // fit together (a join that finds no shared side), given as a meeting of
  // no object, which the caller repairs by a build; exact arithmetic
  // cannot, so there it is a bug and the exception goes on.
  std::variant<Update_cost, Meeting> update(tree::Kvd_tree& t, const tree::Tree_links& links, const Time& at,
                                            const std::set<symbolic::Symbolic_plane>& moving, int scope,
                                            Edit way) const {
    tree::Tree_journal journal(t);
    try {
      return local_update(t, links, tree::Fragment_splitter<K>(*c_, at), moving, scope, &journal, way);
    } catch (const tree::Build_error& e) {
      journal.undo();
      return meeting(e);
    } catch (const std::logic_error& e) {
      journal.undo();
      if constexpr (std::is_same_v<K, Exact_kernel>) throw;
      return Meeting{e.what(), {}};
    } catch (...) {  // anything else (out of memory, say): undone, and passed on
      journal.undo();
      throw;
    }
  }

private:
  Meeting meeting(const tree::Build_error& e) const {
    return {e.what(), e.contact ? contact_objects(scene_, *e.contact) : std::vector<std::size_t>{}};
  }

  const K& k_;
  const scene::Scene& scene_;
  bool full_;
  std::unique_ptr<const predicates::Classifier<K>> c_;
  tree::Evaluated evaluated_;  // by the last build, for the full set
};

}  // namespace kvd::kinetic
