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
#include <utility>
#include <vector>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kernel/zpoly.hpp"
#include "kvd/kinetic/simulation.hpp"

namespace kvd::kinetic {

struct Event_order {
  struct Entry {
    Certificate_type type;
    std::string features;
    zpoly::ZPoly polynomial;  // primitive, positive where the certificate is in force
  };
  struct Event {
    std::size_t certificate;  // into `certificates`
    mpq_class lo, hi;         // the closed interval holds exactly one distinct root of the polynomial
    int multiplicity;
    bool equal_to_previous;   // "=", else "<"
    bool collision;
  };
  std::vector<Entry> certificates;  // one per distinct (type, features, polynomial)
  std::vector<Event> events;
  std::vector<std::vector<std::size_t>> intervals;  // the ids in force, from the start and after each batch
};

// Records an exact simulation as an Event_order: pass it to simulate().
class Event_order_recorder : public Observer<Exact_kernel> {
public:
  void in_force(const Exact_time& now, const std::vector<Certificate<Exact_kernel::Poly>>& certs) override;
  void batch(const Batch<Exact_time>& b, bool collision) override;
  // The record; the recorder is spent.
  Event_order take() { return std::move(order_); }

private:
  std::size_t id(Certificate_type type, const std::string& features, const zpoly::ZPoly& p);

  Exact_kernel k_;
  Event_order order_;
  std::map<std::string, std::size_t> ids_;  // by features and coefficients
  std::map<std::string, std::vector<std::size_t>> current_;  // the ids in force, by features
};

}  // namespace kvd::kinetic
