// The cylindrical BSP of moving segments run on the paper's certificates
// alone (seed 003, section 3.1, Lemma 3.1): one per transient node (its cell
// collapses), one per endpoint (the segment just above or just below it
// changes) and one per segment (it flips). Each is a few of the
// construction's signs with their polynomials in t, and fails at the first
// root after now where one changes sign (kernel next_root); a batch is every
// certificate failing at the earliest failure time, compared exactly.
//
// - transient node: the x order of its cell's walls, and at each wall the
//   vertical order of its roof and floor (where it has both);
// - endpoint p with the segments a just above and b just below it
//   (aeg_neighbours): the side of p to a and to b, and the x order of p to
//   each endpoint of a and of b: p leaves the gap between them, or one of
//   them ends before x(p). A segment coming between is an endpoint or a
//   crossing passing x(p), which a transient node's certificate catches
//   (proofs/segment-certificates.md);
// - segment: the x order of its two endpoints.
//
// A lone flip (or several at one instant, none in a leaf of B_{i-1} below
// another's) is handled in place, as section 3.1.4 does it: in each leaf of
// B_{i-1} that the flipping segment s_i meets, its second point cut moves to
// the other side of its first, the subtrees beside them change places, and
// below s_i's edge cut between them every intersection cut swaps its
// children; the cells, logs and certificates of the nodes touched follow
// (proofs/segment-certificates.md, "Flips in place"). A batch whose failing
// certificates changed only signs that one segment's steps decide (two
// walls crossing, an endpoint passing through a segment; several at one
// instant, apart or one inside the other's region) reroutes that segment
// (reroutes). In a batch the guards refuse whole, the certificates that
// pass them alone are rerouted and the others replayed, when what each
// part changes lies apart from the other's (reroute_apart).
// Any other batch, and a flip that meets anything else at its instant, is
// replayed:
//
// the update is local, though not the paper's surgery (LeftShave, the
// splits, which are not implemented): each failing certificate names the
// cuts it is about (a transient node's walls, floor and roof; an endpoint's
// vertex cut, its neighbours' edge cuts and their endpoints' vertex cuts; a
// flipping segment's cuts), and the subtree of the topmost of those on the
// certificate's path is made again from the construction's log
// (kvd/detail/segments/bsp_builder.hpp), or of a cut higher up that passes
// through the event's point at that instant (above_ties), raised to its
// segment's first cut on its path (first_cut). Only its segment's cuts are
// made again; the later segments' steps are decided down to the cells they
// make, and a cell whose arrivals are those of an old subtree holding no
// node where a sign may change (changing) takes it whole, as the kept run's
// frontier nodes do (Subtree_fit); a leaf is replayed. The argument that
// this subtree holds every change (the changed sign is decided at one of
// those cuts, and the arrivals above it stay) is by the cases of
// proofs/segment-certificates.md, and is checked against the run that keeps
// every sign, batch by batch, not proved. Only the certificates of the nodes
// and endpoints there are made again. Kinetic_segment_bsp keeps every sign
// its construction decides, O(n log n + k) against these O(n + k), and finds
// the nodes to replay from them. Exact kernel only.
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "kvd/detail/kinetic/root_cache.hpp"
#include "kvd/detail/kinetic/time_heap.hpp"
#include "kvd/detail/segments/bsp_builder.hpp"
#include "kvd/detail/segments/reroute.hpp"
#include "kvd/segments/aeg_phases.hpp"
#include "kvd/segments/cylindrical_bsp.hpp"
#include "kvd/segments/segment_scene.hpp"

namespace kvd::segments {

enum class Aeg_certificate_kind { transient, endpoint, flip };
inline constexpr const char* aeg_certificate_kind_names[] = {"transient", "endpoint", "flip"};

// A certificate of the paper's set: of a transient node (its cell), an
// endpoint, or a segment (`index`).
struct Aeg_certificate_id {
  Aeg_certificate_kind kind = Aeg_certificate_kind::flip;
  std::size_t index = 0;  // endpoint or segment; 0 for a transient node
  Cell cell;              // a transient node's
  friend bool operator==(const Aeg_certificate_id&, const Aeg_certificate_id&) = default;
};

// What a certificate is about, for printing: a transient node's cell by its
// walls, floor and roof ("between s1.0 and s0xs1, above s0"), an endpoint
// ("s0.1") or a segment ("s3").
std::string aeg_certificate_subject(const Aeg_certificate_id& id);

template <class K>
class Aeg_kinetic_bsp {
public:
  using Time = typename K::Time;

  struct Batch {
    Time time;
    std::vector<Aeg_certificate_id> failing;  // by kind (transient, endpoint, flip), then cell or index
    bool changed = false;                     // the tree just after differs from the one before
    std::size_t certificates = 0;             // in force after the batch
    std::size_t replays = 0;                  // subtrees replayed
    std::size_t frontier_replays = 0;         // of those, below segments' steps decided again (reroutes)
    std::size_t nodes_rebuilt = 0;            // nodes made again
    std::size_t flipped_in_place = 0;         // leaves of B_{i-1} of a flip turned in place, not replayed
    std::size_t nodes_edited = 0;             // nodes whose children, cell or log those edits changed
    std::size_t certificates_made = 0;        // made again (computed, not kept), the failing ones included
    double update_seconds = 0;                // the tree and its certificates made again
    long signs = 0, held = 0;                 // decided by the update, and read from certificates in force
    long repeated = 0;                        // asked again in the batch, answered from its first decision
    Aeg_phases phases;                        // of `signs`, where they were decided
  };

  // The scene is copied; the run starts at its start. With `validate`, the
  // tree in force is compared, before each batch, with a fresh build at a
  // rational instant strictly between the last batch and this one: a
  // difference is a change of the tree that no certificate of the set saw.
  Aeg_kinetic_bsp(const K& k, Segment_scene scene, bool validate = false);
  // Its predicates keep the addresses of its kernel and scene.
  Aeg_kinetic_bsp(const Aeg_kinetic_bsp&) = delete;
  Aeg_kinetic_bsp& operator=(const Aeg_kinetic_bsp&) = delete;

  const Time& now() const { return now_; }
  // The tree in force, numbered afresh (the run edits its own in place).
  Cylindrical_bsp tree() const { return tree_.compacted(); }
  std::size_t certificates() const { return transient_.size() + endpoint_.size() + flip_.size(); }
  // The certificates in force, each with its failure time (none: not within
  // the span), in the order Batch::failing keeps.
  std::vector<std::pair<Aeg_certificate_id, std::optional<Time>>> certificate_list() const;
  // The tree in force as the run edits it (unused slots included) and its
  // construction's log by those slots, for a comparison with a fresh build's.
  const Cylindrical_bsp& edited_tree() const { return tree_; }
  const Build_log& log() const { return log_; }
  // The leaf beside endpoint e as the run keeps it (its certificate reads
  // that leaf's floor and roof), for a comparison with aeg_leaf.
  std::size_t leaf_beside(std::size_t e) const { return leaf_[e]; }
  // The earliest failure after now, within the scene's span.
  std::optional<Time> next_event_time();
  // Processes the next batch. Precondition: next_event_time() has a value.
  Batch advance();
  // Processes every batch at a time <= t, then moves now to t (if later),
  // but not past the span's end.
  std::vector<Batch> advance_to(const Time& t);
  // A flight-plan change: segment `segment` follows `motion` from now on.
  // The motion must put the segment where it is now (std::invalid_argument
  // otherwise, and when W vanishes at now or later in the span). Only the
  // certificates naming the segment are made again (Lemma 3.1: O(k_i + 1),
  // found through an index by segment); those whose signs just after now
  // the new motion changes fail now, and are updated as a batch's are. The
  // batch returned is that one, at now (failing empty when none did).
  Batch set_motion(std::size_t segment, const Segment_motion& motion);
  // The validations that found the tree in force different from a fresh
  // build, described, and how many ran.
  const std::vector<std::string>& validation_failures() const { return failures_; }
  std::size_t validations() const { return validations_; }
  // The scene with the flight-plan changes made.
  const Segment_scene& scene() const { return scene_; }

private:
  using P = typename K::Poly;
  // Signs with the keys they decide.
  using Decided = std::vector<std::pair<Segment_certificate_key, int>>;
  struct Certificate {
    Aeg_certificate_id id;
    std::optional<Time> fails;  // within the span
    std::uint64_t version = 0;  // queue entries of another version are stale
    Cell near;                  // an endpoint's: the leaf beside it, whose floor and roof it reads
    Decided decided;            // its signs when made, which hold until it fails
  };
  // Cells in the order of their walls, floor and roof.
  struct Cell_less {
    bool operator()(const Cell& a, const Cell& b) const {
      return std::tie(a.left, a.right, a.floor, a.roof) < std::tie(b.left, b.right, b.floor, b.roof);
    }
  };
  struct Entry {
    Time time;
    Aeg_certificate_kind kind;
    std::size_t index;  // the transient node's slot, the endpoint or the segment
    std::uint64_t version;
  };

  // A certificate as the index by segment names it.
  struct Held {
    Aeg_certificate_kind kind;
    std::size_t index;
    friend auto operator<=>(const Held&, const Held&) = default;
  };

  // The tree, its log and every certificate just after now.
  void rebuild();
  // Asks the predicates for the signs of certificate c (of node, endpoint
  // or segment `index`): its cell's for a transient node, its near leaf's
  // floor and roof for an endpoint, its endpoints' x order for a segment.
  void ask(const Certificate& c, std::size_t index);
  // Those signs just after now.
  Decided signs(const Certificate& c, std::size_t index);
  // The certificate made again and queued at its failure: the first root
  // after now of the polynomials of its signs.
  void make(Certificate& c, std::size_t index);
  // Certificate c entered in the index under each segment it names, once
  // the index is made, and the index made again when it has grown too large.
  void index(const Certificate& c, std::size_t index);
  // by_segment_ made from the certificates in force.
  void reindex();
  void enter(const Certificate& c, std::size_t index);
  // add(s) for each segment certificate c (of node, endpoint or segment
  // `index`) names, a segment maybe more than once.
  template <class F>
  void named_by(const Certificate& c, std::size_t index, F add) const;
  // The certificates in force naming segment s (entries gone since dropped).
  std::vector<Held> naming(std::size_t s);
  Certificate& held(const Held& h);
  // Endpoint e's certificate taken off its leaf's list, to be found again.
  void detach(std::size_t e);
  // The batch of the failing certificates `entries` at now: the tree and
  // the certificates updated.
  void update(std::vector<Entry> entries, Batch& b);
  // A transient node's certificate: taken from spare_ when a node of a
  // replayed subtree had the same cell (the same signs, so the same failure
  // time: it has not failed), else made.
  void make_transient(std::size_t node);
  // An endpoint's, its leaf found from `from` (an ancestor of it): kept when
  // its floor and roof are the same and it is not failing now, else made.
  // With `near`, `from` is only where it was: its leaf is found from the
  // first of `from` and its ancestors whose cell it lies inside now.
  void make_endpoint(std::size_t e, std::size_t from = 0, bool near = false);
  // The endpoints beside node n, their leaves found again from `from`
  // (an ancestor of them, n itself when it stays a leaf; with `near`, as
  // make_endpoint's).
  void remake_beside(std::size_t n, std::size_t from, bool near = false);
  // Whether point p lies inside node n's cell now: its signs against the
  // cell's walls, floor and roof decided by their values, each the cell's
  // side. The cell lies on one side of every cut above it, and a point
  // inside it strictly on the same side: an endpoint's leaf below n is the
  // one a search from the root finds, and no cut above n meets p now.
  bool inside(const Site_point& p, std::size_t n) const;
  void make_flip(std::size_t s);
  // The nodes whose cut the insertion of segment s made, none of them below
  // another: s's first cut in each leaf of B_{i-1} that s meets, found down
  // the nodes whose log holds an arrival of s.
  std::vector<std::size_t> tops(std::size_t s) const;
  // The flips of the segments `turning` done in place (see above) when they
  // are lone ones: every failing transient node (`failing`) lies below a
  // turning segment's edge cuts between its point cuts, and no leaf of
  // B_{i-1} that one meets lies below another's; else nothing is done and
  // false returned.
  bool flip_in_place(const std::vector<std::size_t>& turning, const std::set<std::size_t>& failing, Batch& b);
  // The neighbours of endpoint e (its leaf's floor and roof) on whose line
  // its segment lies at now (both its endpoints' sides of it vanish there):
  // two parallel segments passing through each other's line swap their
  // order at every wall across both, not only near e, and the signs of
  // later segments' crossings on either against the other change too.
  std::vector<std::size_t> collinear(std::size_t e) const;
  // What a failing certificate is about: the points and segments of its
  // cuts (see above; a flip's segment; a collinear endpoint's own segment
  // too), and the node its path starts from (a transient node, an
  // endpoint's leaf; none for a flip).
  std::size_t subjects(const Entry& e, std::vector<Site_point>& points, std::vector<std::size_t>& segments) const;
  // The subtrees to replay for a failing certificate (see above; for a
  // collinear endpoint's, `passing`).
  std::vector<std::size_t> roots(const Entry& e) const;
  // For endpoint e on its neighbour's line (collinear): every sign that
  // changes names both segments, and is decided at a cut no earlier than
  // the earlier of them, so below the topmost such nodes that either
  // segment reaches (its frontier nodes); those are returned. When one of
  // the two segments' steps above them asks a sign that vanishes now (a
  // degenerate instant), the tree's root.
  std::vector<std::size_t> passing(std::size_t e) const;
  // Whether a key's sign may change now: a polynomial deciding it vanishes
  // (not a tie for good that the perturbation decides the same way before
  // and after; order_at of a line with itself is no sign: decided_keys
  // lists it).
  bool vanishes(const Segment_certificate_key& k) const {
    return !(k.kind == Segment_certificate_key::Kind::order_at && k.i == k.j) &&
           counting(phases_.own_guard, [&] { return pred_.sign_of(k, now_).at_root; });
  }
  // Whether no wall of point cut u's cell and no point cut in its subtree
  // meets u's point's abscissa now (a polynomial of their x order vanishes
  // there) but by a key in `changed`: the points of the other segments'
  // arrivals at u are among those, so none of their signs at u vanishes
  // now (proofs/segment-local-update.md, "Rerouting on the paper's set",
  // case 2). Only the cells whose x-range holds that abscissa now are
  // searched; false as soon as one such sign vanishes now and is not a
  // changed key (the caller then reads u's log).
  bool abscissa_clear(std::size_t u, const std::set<Segment_certificate_key>& changed) const;
  // Whether the signs of the steps of the segment of rank r at each node
  // of `ends` against the sides of its cell settle every sign of those
  // steps above: none vanishes now, is a key in `changed` (normal forms)
  // or is a tie for good. A point of a step on its cell's floor or roof is
  // asked against the floor or roof of that segment's own cut instead
  // (proofs/segment-local-update.md, "Rerouting on the paper's set", case 1).
  bool squeezed(const std::vector<std::size_t>& ends, std::size_t r,
                const std::set<Segment_certificate_key>& changed) const;
  // Whether old subtree o, made in its cell before, is the subtree of the
  // cell `now` with the walls that moved renamed: each moved wall meets its
  // new one's abscissa now, and no point cut along it and no floor and
  // roof of a leaf along it meets that abscissa now (by value, off any 0/0
  // point), so every sign its steps decided with the old wall stays with
  // the new one (proofs/segment-local-update.md, "Cells kept", walls
  // renamed). The caller has checked the rest: the log renamed is the
  // cell's arrivals, and o holds no change.
  bool walls_renamed(std::size_t o, const Cell& now) const;
  // f(), the signs it decided added to `to` (Batch::phases).
  template <class F>
  auto counting(long& to, F f) const {
    const long before = pred_.counts().decided();
    const auto add = [&] { to += pred_.counts().decided() - before; };
    if constexpr (std::is_void_v<decltype(f())>) {
      f();
      add();
    } else {
      auto r = f();
      add();
      return r;
    }
  }
  // The nodes where a sign may change: the failing transient nodes and
  // endpoints' leaves, and below the roots every cut of a point or segment
  // the failing certificates are about (for a flip, every point on its
  // segment), and the nodes `asked` (reroutes), with their ancestors. A
  // replay keeps an old subtree whole only where its arrivals are the same
  // and it holds none of them.
  std::set<std::size_t> changing(const std::vector<Entry>& entries, const std::vector<std::size_t>& roots,
                                 std::vector<std::size_t> asked) const;
  // Whether `at` meets node n's cut at now (a sign there is zero at now and
  // decided just after, or by the perturbation). With `identities` false, a
  // sign zero by identity (`at` a crossing on the cut's segment, for good)
  // is no tie.
  bool ties(const Bsp_node& n, const Site_point& at, bool identities) const;
  // Whether a sign is such a tie: zero at now, decided just after or by the
  // perturbation (or by identity, with `identities`).
  static bool tied(const Segment_sign& s, bool identities) {
    return s.rule != Segment_rule::value && (identities || s.rule != Segment_rule::identity);
  }
  // The topmost of `top` and its ancestors whose cut `at` meets at now
  // (ties): a change at `at` may cross that cut, as where a crossing born at
  // an endpoint lies on the other side of a wall with the same abscissa.
  std::size_t above_ties(std::size_t top, const Site_point& at, bool identities = true) const;
  // The topmost node above v, or v, on whose path to v every cut is of v's
  // segment: its first cut there (v for a leaf), the node a replay of v
  // remakes with only that segment's cuts made again.
  std::size_t first_cut(std::size_t v) const;
  // The nodes of `nodes` below no other of them.
  std::vector<std::size_t> outermost(const std::set<std::size_t>& nodes) const;
  // A batch whose failing certificates (transient cells and endpoints, no
  // flip) changed signs, against those each was made with
  // (Certificate::decided), that one segment's steps decide: each changed
  // key (taken as an x order, `normal`) names that segment last, as two
  // walls crossing do (the later wall's segment) and an endpoint passing
  // through a segment (the later of the two); several such segments at one
  // instant. For each, the topmost nodes above
  // its frontier where its steps decide a changed key are found; when none
  // of its other steps there, nor another segment's step at those nodes
  // about the changed points, changes sign now, and no cut on the
  // certificates' paths above the frontier ties with its points now but the
  // keys' own, its steps are decided again from those nodes
  // (reroute_segment) and the frontier nodes whose arrivals changed, and
  // those above the certificates' nodes, are returned to be made again, its
  // cuts first (proofs/segment-local-update.md, "Frontier replay",
  // "Rerouting on the paper's set"); else nothing is done and none returned.
  // When one segment's nodes lie at or above another's, every segment's
  // steps are decided again down to the frontier of the earliest, and the
  // frontier nodes there are returned to be made again with the earliest
  // segment's cuts first, marked `several` ("Several segments at one
  // instant"); the nodes below them where a later segment's steps ask a
  // sign that changes or vanishes now are added to `asked`. With `proceed`,
  // once the guards have passed and before anything is changed, it is told
  // the nodes a reroute changes below (every segment's tops and frontier
  // nodes) and whether they are nested, and the reroute goes on only if it
  // says so.
  using Reroute_check = std::function<bool(const std::vector<std::size_t>& region, bool nested)>;
  std::vector<Replay_root> reroutes(const std::vector<Entry>& entries, std::vector<std::size_t>& asked,
                                    const Reroute_check& proceed = {});
  // A batch that reroutes() refuses whole: the certificates that pass its
  // guards alone are rerouted together, and the others' named subtrees
  // (raised to first cuts) made again, when no such subtree holds or lies
  // below a node the reroute changes below, and the reroute is not nested.
  // Else nothing is done and nothing returned. On success, `searched` and
  // `remade` are remade_roots' of the others.
  std::vector<Replay_root> reroute_apart(const std::vector<Entry>& entries, std::vector<std::size_t>& asked,
                                         std::vector<std::size_t>& searched, std::vector<std::size_t>& remade);
  // The subtrees that entries name (roots), none below another
  // (`searched`), and those raised to their segments' first cuts, none
  // below another: the roots made again.
  std::vector<std::size_t> remade_roots(const std::vector<Entry>& entries, std::vector<std::size_t>& searched) const;
  // Whether segments i and j cross just after now: the endpoints of each lie
  // on either side of the other's line.
  bool crossing(std::size_t i, std::size_t j) const;
  // Makes the subtrees of `roots` (none below another) again, keeping the
  // old subtrees below each root's cuts whose arrivals did not change and
  // that hold no node of `dirty` (Subtree_fit), and makes the certificates
  // of the nodes made or given a new cell; whether the tree changed.
  // A root with a rank is a frontier node, made again with that segment's
  // cuts first; any other is its segment's first cut on its path, or a
  // leaf; the endpoints beside its nodes gone are found again from
  // the tree's root (they may have moved to another frontier node).
  bool replay(const std::vector<Replay_root>& roots, std::set<std::size_t> dirty, Batch& b);
  // The cells of an update that took an old subtree whole (Subtree_fit::kept),
  // and the nodes below them given a new cell.
  struct Kept {
    std::set<std::size_t> tops, recelled;
  };
  // Makes the certificates of the transient nodes in v's subtree (a node is
  // transient when its parent is a point cut and no point cut lies in its
  // subtree); whether a point cut lies there (kept in points_). Below a
  // kept top, a node whose cell stayed is not visited: its subtree, cell and
  // parent's cut are as they were, and so are its certificate and points_.
  bool certify_below(std::size_t v, const Kept& kept, bool inside = false);
  // Whether the transient nodes' certificates and points_ are those that
  // certify_below makes afresh (a validation's check of the update's
  // bookkeeping); if not, what differs.
  std::optional<std::string> certified_afresh() const;
  bool stale(const Entry& e) const;

  K k_;
  Segment_scene scene_;
  bool validate_;
  Time now_;
  bool bounded_;
  Time end_;
  Segment_predicates<K> pred_;
  Cylindrical_bsp tree_;
  Build_log log_;
  std::map<std::size_t, Certificate> transient_;  // by node slot
  std::vector<char> points_;                      // by node slot: whether a point cut lies in its subtree
  // During an update: the certificates of the transient nodes of the
  // replayed subtrees (failing ones left out), and the failing endpoints.
  std::map<Cell, Certificate, Cell_less> spare_;
  std::set<std::size_t> failing_endpoints_;  // failing: made again, not kept
  std::vector<Certificate> endpoint_, flip_;
  std::vector<std::size_t> leaf_;  // per endpoint: the leaf beside it (aeg_neighbours)
  std::map<std::size_t, std::vector<std::size_t>> beside_;  // per leaf slot: the endpoints it is beside
  kinetic::Time_heap<K, Entry> queue_{k_};
  std::uint64_t versions_ = 0;
  std::vector<P> polys_;           // of the certificate being made
  std::size_t made_ = 0;           // certificates made, for Batch::certificates_made
  // Per segment, the certificates naming it, some gone since (naming drops
  // them); made from the certificates in force at the first flight-plan
  // change (a run without one does not pay for it: made at the start, its
  // remaking paused a batch of 12,800 segments for 13 to 15 ms), and again when
  // it holds twice as many entries as they can name, so that its size
  // stays within a constant of theirs at a constant amortized cost per
  // certificate made.
  std::vector<std::vector<Held>> by_segment_;
  std::size_t indexed_ = 0;
  kinetic::Root_cache<K> roots_;
  std::vector<std::string> failures_;
  std::size_t validations_ = 0;
  mutable Aeg_phases phases_;  // of the batch being updated
};

}  // namespace kvd::segments
