// The kinetic KVD with the full certificate set and the reference update
// (DESIGN.md section 5): the certificates are every sign the construction
// evaluated; the next event is the smallest sign-changing root, after the
// current time, of any of their polynomials, found and ordered exactly; an
// event batch is every certificate failing at that same algebraic time; the
// update rebuilds the tree valid just after it.
//
// Validation: the tree in force between two consecutive events must be the
// tree built at a rational time strictly between them; a difference means an
// event was missed. Exact kernel only: it needs exact times and a rational
// strictly between two of them.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/scene/scene.hpp"

namespace kvd::kinetic {

struct Full_event {
  Exact_time time;
  std::size_t failing = 0;       // certificates (distinct polynomials) failing at this time
  std::size_t certificates = 0;  // distinct certificate polynomials before the event
  bool changed = false;          // whether the tree just after differs from the tree before
};

struct Full_simulation {
  std::vector<Full_event> events;
  bool valid = true;
  std::string failure;  // the first validation failure, in words
};

struct Full_options {
  std::size_t max_events = 100;
  bool validate = true;
};

// Runs from the scene's start until its end (if any), no events are left,
// or max_events.
Full_simulation simulate_full(const scene::Scene& s, const Full_options& options);

// A rational strictly between a < b.
mpq_class rational_between(const Exact_time& a, const Exact_time& b);

}  // namespace kvd::kinetic
