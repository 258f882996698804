// How often each stage of the exact kernel's filtered predicates decided
// (DESIGN.md section 3): the interval filter, or exact arithmetic after it
// could not; for classifications also the derivative and perturbation rules
// (DESIGN.md section 4), which run only after the exact value is zero.
#pragma once

namespace kvd {

struct Stage_counts {
  long filter = 0, exact = 0, after = 0, perturbation = 0;
};

struct Filter_statistics {
  Stage_counts classify;  // rule 2 by filter or exactly; rules 3 and 4 (incidence is not a sign)
  Stage_counts sign_at;   // Exact_kernel::sign_at (sign_after calls it)
  Stage_counts compare;   // Exact_kernel::compare of two algebraic instants
  // The reduced certificates' walks (src/kinetic/wall_filter.hpp): a wall's
  // side and the order of two walls, by the filter or by polynomials.
  Stage_counts walk;
};

}  // namespace kvd
