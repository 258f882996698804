// Splitting a fragment by a cut plane (thesis 5.3.3): the one geometric step
// of both the construction and the local updates (thesis 7.2). A fragment's
// corners are classified at an instant; a crossed fragment gets new corners
// named by the features that define them.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "kvd/predicates/classify.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/kvd_tree.hpp"

namespace kvd::tree {

using Piece = std::optional<Fragment>;

template <class K>
class Fragment_splitter {
public:
  // With `evaluated`, every classification made is appended to it.
  Fragment_splitter(const predicates::Classifier<K>& c, const typename K::Time& t, Evaluated* evaluated = nullptr)
      : c_(c), t_(t), evaluated_(evaluated) {}

  // The parts of f, a fragment of `cut`, on the negative and the positive
  // side of `plane`. A fragment lying in the plane by construction goes to
  // the positive side. Throws Build_error when f crosses a triangle's plane,
  // or lies in it and meets the triangle.
  std::pair<Piece, Piece> split(const Fragment& f, const Symbolic_plane& plane, const Symbolic_plane& cut) const;

  const predicates::Classifier<K>& classifier() const { return c_; }

private:
  // Of a fragment split by a triangle's plane: whether every corner lies in
  // the plane for good, and those the perturbation put on a side.
  struct In_plane {
    bool all;
    std::vector<Symbolic_vertex> perturbed;
  };
  int side(const Symbolic_vertex& v, const Symbolic_plane& p, In_plane& in_plane) const;
  void check_not_overlapping(const In_plane& in_plane, const Symbolic_plane& plane, const Symbolic_plane& cut) const;
  Symbolic_vertex crossing(const symbolic::Symbolic_edge& edge, const Symbolic_plane& plane) const;
  Triangle_fragment clip(const Triangle_fragment& t, const std::vector<int>& s, int keep, const Symbolic_plane& plane,
                         const symbolic::Symbolic_edge& cut_line) const;

  const predicates::Classifier<K>& c_;
  const typename K::Time& t_;
  Evaluated* evaluated_;
};

}  // namespace kvd::tree
