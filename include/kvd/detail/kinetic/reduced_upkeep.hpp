// Keeping the reduced set (thesis 6.4) over a run: after a batch only the
// nodes whose certificates can have changed make them again (thesis 6.5).
//
// What a node's certificates are made from is its key: its cut and
// fragment, and, when they name walls of its ancestors (names_walls), the
// cuts of its ancestors and the intersection endpoints of its E-node
// ancestors' fragments (the P-walls those stand for); and the motions
// (a motion change starts afresh with clear()). A node whose key was in the
// tree before the batch, and which holds no certificate that failed in the
// batch, keeps the certificates it had. The others make theirs at the new
// instant, taking from the record their slot held those under a key that
// did not fail (a certificate's polynomials are its key's). Keys are
// compared exactly (no hashing), so a node's key is equal only when the
// inputs are.
//
// The walls a node's certificates name were the nearest when the node made
// them; a node that keeps its certificates keeps that choice
// (proofs/certificates.md, section 3). The choice depends on the tree's
// content only, never on how the update built it, so the local update and
// the rebuild keep the same certificates.
#pragma once

#include <cstddef>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "kvd/detail/flat_map.hpp"
#include "kvd/detail/tree/slot_marks.hpp"
#include "kvd/detail/tree/tree_links.hpp"
#include "kvd/kinetic/certificate.hpp"

namespace kvd::kinetic {

// The intersection points an E-node's fragment ends at, in order: the
// P-walls (intersection cuts) it offers its subtree besides its cut. None
// for other nodes.
std::vector<symbolic::Symbolic_vertex> intersection_walls(const tree::Node& n);

// Whether a node's reduced certificates name walls of its ancestors: a
// point node's (thesis 6.4.1) and an edge fragment's with an intersection
// endpoint (6.4.2). A triangle node's (6.4.4) and the other edge nodes'
// (6.4.3, ET) are made from its cut and fragment alone.
bool names_walls(const tree::Node& n);

// The reduced certificates one node makes at `now`, its ancestors being
// `path` (root first); each named once, by key. A certificate whose key is
// in `held` (sorted by key) and not in `failed` is moved from there rather
// than made.
template <class K>
class Reduced_maker {
public:
  Reduced_maker(const predicates::Classifier<K>& c, const tree::Kvd_tree& t, const typename K::Time& now);
  ~Reduced_maker();
  std::vector<Certificate<typename K::Poly>> of_node(int n, const std::vector<int>& path,
                                                     std::vector<Certificate<typename K::Poly>>* held = nullptr,
                                                     const std::set<Certificate_key>& failed = {});

private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

template <class K>
class Reduced_upkeep {
public:
  using Poly = typename K::Poly;
  // A certificate in force, and whether its node made it at this update.
  struct Held {
    const Certificate<Poly>* certificate;
    bool made;
  };
  struct Work {
    std::size_t nodes = 0;         // nodes that made their certificates
    std::size_t certificates = 0;  // certificates they made (before merging equal keys)
  };

  // How the set in force changed: the keys no longer in force, and the
  // certificates new in force, made again, or held by another node now.
  struct Changes {
    std::vector<Certificate_key> gone;
    std::vector<Held> changed;
  };

  // Brings the reduced set up to date with t just after `now`; `failed`
  // names the certificates that failed since the last update, `edited` the
  // nodes changed since then (Update_cost::changed), or none when t is new
  // (a build); `links` are t's. Only those nodes, the failed ones, their
  // ancestors and the subtrees below a node whose key changed are looked
  // at. Each key is in force once, held by the least node slot that has
  // it. The pointers stay valid until the next update or clear().
  Changes update(const predicates::Classifier<K>& c, const tree::Kvd_tree& t, const tree::Tree_links& links,
                 const std::vector<int>* edited, const typename K::Time& now,
                 const std::set<Certificate_key>& failed, Work& work);
  // Forgets every node's certificates and what is in force: the next update
  // makes them all, and reports them all as changed.
  void clear();
  // The next update makes every node's certificates again, and reports
  // only what changed in force (Upkeep::all, the reference).
  void remake_all() { remake_ = true; }

private:
  // An ancestor path as the walls it offers: the parent path, a cut, and the
  // intersection endpoints of an E-cut's fragment.
  using Path = std::tuple<int, symbolic::Symbolic_plane, std::vector<symbolic::Symbolic_vertex>>;
  struct Key {
    // The ancestors, as an id of paths_ (-1 at the root), or `unwalled` for
    // a node whose certificates name no wall of an ancestor.
    int path;
    symbolic::Symbolic_plane cut;
    tree::Fragment fragment;
    auto operator<=>(const Key&) const = default;
  };
  struct Hash {
    symbolic::Symbolic_hash h;
    std::size_t operator()(const Key& k) const {
      return h.mix(h.mix(static_cast<std::size_t>(k.path), h(k.cut)), h(k.fragment));
    }
    std::size_t operator()(const Path& p) const {
      return h.mix(h.mix(static_cast<std::size_t>(std::get<0>(p)), h(std::get<1>(p))), h(std::get<2>(p)));
    }
  };
  // What a node slot of the tree held at the last update. A node whose slot
  // holds its key is matched in place (the local update keeps the slots of
  // the nodes it does not touch); others are looked up by key (`where_`).
  static constexpr int unwalled = -2;
  struct Record {
    bool used = false;
    Key key;
    tree::Fragment fragment;  // as the tree held it: equal means equal keys
    int path = -1;            // the path id of its ancestors
    int children_path = -1;   // the path id the node gives its children
    std::vector<Certificate<Poly>> certificates;
  };
  std::vector<Record> records_;
  kvd::detail::Flat_map<Key, int, Hash> where_;  // the slot holding each key
  // The slots holding each key, increasing (one but in degenerate cases).
  kvd::detail::Flat_map<Certificate_key, std::vector<int>, Certificate_key_hash> holders_;
  kvd::detail::Flat_map<Path, int, Hash> paths_;  // every path met since the last clear()
  int next_path_ = 0;
  bool remake_ = false;
  // One update's marks per slot: holding a failed certificate, on a path
  // to be walked, record not kept in place, certificates given to another
  // slot, record rewritten, certificates made; cleared as the next starts.
  tree::Slot_marks failed_, marked_, not_kept_, given_, rewritten_, fresh_;
};

}  // namespace kvd::kinetic
