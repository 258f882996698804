// Construction of the KVD (thesis 5.3.3): for every triangle in priority
// order, the P-cuts of the vertices it owns, then the E-cuts of the edges it
// owns, then its T-cut, each filtered down the tree and split by the nodes it
// crosses. Shared vertices and edges are cut once, by the triangle of
// highest priority containing them. Intersection cuts stay implicit in the
// E-nodes' fragments (thesis 5.3.3, 6.4.2).
#pragma once

#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "kvd/predicates/classify.hpp"
#include "kvd/scene/scene.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::tree {

// Two triangles meeting: a fragment of `site` (an E- or T-cut) crosses the
// plane of `triangle`.
struct Contact {
  symbolic::Symbolic_plane site;
  std::size_t triangle;
};

// Raised when a fragment would have to be split by a T-node: the triangles
// intersect at the build instant. `contact` says which, when known.
class Build_error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
  Build_error(const std::string& what, Contact c) : std::runtime_error(what), contact(c) {}
  std::optional<Contact> contact;
};

// Every classification a construction evaluated, in order: the construction
// branches only on these signs, so while none of them changes, neither does
// the tree (DESIGN.md section 5, the "full" certificate set).
using Evaluated = std::vector<std::pair<symbolic::Symbolic_vertex, symbolic::Symbolic_plane>>;

// The tree valid on (t, t + δ); with `evaluated`, also the classifications
// it made.
template <class K>
Kvd_tree build(const predicates::Classifier<K>& classifier, const typename K::Time& t, Evaluated* evaluated = nullptr);

}  // namespace kvd::tree
