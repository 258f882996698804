// kvd bench SUITE: the benchmark suites (src/bench/).
#include <iostream>

#include "bench.hpp"
#include "cli.hpp"

namespace kvd::cli {

namespace {
const char* const bench_help =
    "usage: kvd bench SUITE [options]\n"
    "\n"
    "suites:\n"
    "  accuracy   error against run time of the floating-point kernels\n"
    "  thesis     the thesis's Figures 8.4-8.9 for our implementation\n"
    "  update     the local update against the rebuild (thesis chapter 7)\n"
    "  cost       exact against double, the interval filter, next_root\n"
    "  aeg        the BSP of segments against the bounds of seed 003\n"
    "  aeg-cost   the cost of an event of the kinetic BSP of segments against n\n"
    "\n"
    "Every suite takes --help. Timings are medians of one run on this machine;\n"
    "nothing is asserted about them.\n";
}  // namespace

int bench(Args& args) {
  if (args.done()) throw Usage_error(std::string("kvd bench: missing SUITE\n") + bench_help);
  const std::string suite = args.next();
  if (suite == "--help" || suite == "-h") {
    std::cout << bench_help;
    return 0;
  }
  Args rest = args.remaining("bench " + suite);
  if (suite == "accuracy") return kvd::bench::accuracy(rest);
  if (suite == "thesis") return kvd::bench::thesis(rest);
  if (suite == "update") return kvd::bench::update(rest);
  if (suite == "cost") return kvd::bench::cost(rest);
  if (suite == "aeg") return kvd::bench::aeg(rest);
  if (suite == "aeg-cost") return kvd::bench::aeg_cost(rest);
  throw Usage_error("kvd bench: unknown suite '" + suite + "' (see kvd bench --help)");
}

}  // namespace kvd::cli
