// The event-order certificate of an exact simulation (proofs/
// event-order-certificate.md): every certificate polynomial in force on every
// interval between consecutive event times, and every event with an interval
// isolating its time as a root of its own certificate polynomial, its
// multiplicity and its order relation to the event before it. An independent
// checker (proofs/check-certificate) verifies it from the scene alone.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/detail/kernel/zpoly.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/scene.hpp"

namespace kvd::kinetic {

struct Event_order {
  struct Entry {
    Certificate_key key;
    zpoly::ZPoly polynomial;  // primitive, positive where the certificate is in force
    std::size_t motions;      // the motions it is made of: 0 the scene's, k those after motion change k - 1
  };
  // A certificate failing at an instant: its id and an interval isolating the instant.
  struct Root {
    std::size_t certificate;  // into `certificates`
    mpq_class lo, hi;         // the closed interval holds exactly one distinct root of the polynomial
    int multiplicity;
  };
  struct Event : Root {
    bool equal_to_previous;  // "=", else "<"
    bool collision;
  };
  // X-collide: `objects` take their new `motions` (reversed) at the rational
  // `time`, before the instant at which `failing` fail, where they touch.
  struct Motion_change {
    std::size_t after_events;  // the events processed before it
    mpq_class time;
    std::vector<Root> failing;  // the batch at the instant of contact, not processed
    std::vector<std::size_t> objects;
    std::vector<scene::Motion> motions;
    std::string contact;  // which features met, in words
  };
  std::vector<Entry> certificates;  // one per distinct (key, polynomial, motions)
  std::vector<Event> events;
  // The ids in force from the start, after each batch and after each motion change.
  std::vector<std::vector<std::size_t>> intervals;
  std::vector<Motion_change> motion_changes;
};

// [lo, hi] around the root t of p holding no other distinct root of p (lo =
// hi when t is rational), from t's canonical interval, so that it does not
// depend on how far comparisons refined t.
std::pair<mpq_class, mpq_class> isolating_interval(const zpoly::ZPoly& p, const Exact_time& t);
// The multiplicity of t as a root of p (0 when it is none).
int root_multiplicity(const Exact_kernel& k, const zpoly::ZPoly& p, const Exact_time& t);

// Records an exact simulation as an Event_order: pass it to simulate(). A
// reversal that adds objects at the instant of the previous one is a motion
// change of its own, at the same time.
class Event_order_recorder : public Observer<Exact_kernel> {
public:
  void in_force(const Exact_time& now, const std::vector<Certificate<Exact_kernel::Poly>>& certs) override;
  void batch(const Batch<Exact_time>& b, bool collision) override;
  void reversal(const Reversal<Exact_time>& r) override;
  // The record; the recorder is spent.
  Event_order take() { return std::move(order_); }

private:
  std::size_t id(const Certificate_key& key, const zpoly::ZPoly& p);
  // The failure of the certificate in force named `f` at t.
  Event_order::Root root(const Failure& f, const Exact_time& t) const;

  Exact_kernel k_;
  Event_order order_;
  std::map<std::tuple<Certificate_key, std::size_t, zpoly::ZPoly>, std::size_t> ids_;  // by key, motions and polynomial
  std::map<Certificate_key, std::vector<std::size_t>> current_;  // the ids in force, by key
};

}  // namespace kvd::kinetic
