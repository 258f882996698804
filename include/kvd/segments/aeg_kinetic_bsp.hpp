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
// This is the paper's event detection, not yet its update: at each batch the
// tree and the certificates are built again at now, where the paper changes
// O(1) of them by its surgeries (LeftShave, the splits), which are not
// implemented. Kinetic_segment_bsp is the structure with local updates; it
// keeps every sign its construction decides, O(n log n + k) against these
// O(n + k). The tests compare the two runs' batches: the tree changes at
// exactly the failures of this set. Exact kernel only.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "kvd/detail/kinetic/root_cache.hpp"
#include "kvd/segments/cylindrical_bsp.hpp"

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
    std::vector<Aeg_certificate_id> failing;  // transient nodes in pre-order, then endpoints, then segments
    bool changed = false;                     // the tree just after differs from the one before
    std::size_t certificates = 0;             // in force after the batch
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
  const Cylindrical_bsp& tree() const { return tree_; }
  std::size_t certificates() const { return certs_.size(); }
  // The earliest failure after now, within the scene's span.
  std::optional<Time> next_event_time() const;
  // Processes the next batch. Precondition: next_event_time() has a value.
  Batch advance();
  // The validations that found the tree in force different from a fresh
  // build, described, and how many ran.
  const std::vector<std::string>& validation_failures() const { return failures_; }
  std::size_t validations() const { return validations_; }

private:
  using P = typename K::Poly;
  struct Certificate {
    Aeg_certificate_id id;
    std::optional<Time> fails;  // within the span
  };
  // The tree and the certificates just after now.
  void make();
  // The certificate's failure: the first root after now of the polynomials
  // that decided the signs `decide` asks for.
  template <class F>
  void add(const Aeg_certificate_id& id, F decide);

  K k_;
  Segment_scene scene_;
  bool validate_;
  Time now_;
  bool bounded_;
  Time end_;
  Segment_predicates<K> pred_;
  Cylindrical_bsp tree_;
  std::vector<Certificate> certs_;
  std::vector<P> polys_;  // of the certificate being made
  kinetic::Root_cache<K> roots_;
  std::vector<std::string> failures_;
  std::size_t validations_ = 0;
};

}  // namespace kvd::segments
