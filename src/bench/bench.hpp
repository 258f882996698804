// The suites of `kvd bench`, each a command of its own.
#pragma once

#include "cli.hpp"

namespace kvd::bench {

// kvd bench accuracy: error against run time of the floating-point kernels.
int accuracy(cli::Args& args);
// kvd bench thesis: the thesis's Figures 8.4-8.9 for our implementation.
int thesis(cli::Args& args);
// kvd bench update: the local update against the rebuild, with and without
// kept certificates.
int update(cli::Args& args);
// kvd bench cost: exact against double, the filter's statistics, next_root.
int cost(cli::Args& args);
// kvd bench aeg: the cylindrical BSP of segments (seed 003) against its bounds.
int aeg(cli::Args& args);
// kvd bench aeg-cost: the cost of an event of the kinetic BSP of segments
// against n, in signs decided and nodes made.
int aeg_cost(cli::Args& args);

}  // namespace kvd::bench
