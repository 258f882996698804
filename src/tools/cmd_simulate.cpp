// kvd simulate SCENE: the kinetic KVD with the full certificate set.
#include <cstdio>
#include <iostream>

#include "cli.hpp"
#include "kvd/kinetic/full_simulation.hpp"

namespace kvd::cli {

namespace {
const char* const simulate_help =
    "usage: kvd simulate SCENE [--events N] [--no-validate] [--seed S] [--json]\n"
    "\n"
    "Runs the kinetic KVD from the scene's start, with the exact kernel, the\n"
    "full certificate set (every sign the construction evaluated) and the\n"
    "reference update (rebuild just after each event), until the scene's end,\n"
    "the last event, or N events (default 100). Events at the same algebraic\n"
    "time are one batch. After every event the tree in force before it is\n"
    "compared with a fresh build at a rational time strictly between the two\n"
    "events; a difference (a missed event) is a failed check.\n"
    "\n"
    "  --json   {\"events\": [{\"time\": EXACT, \"approx\": DECIMAL, \"failing\": N,\n"
    "           \"certificates\": N, \"changed\": BOOL}, ...], \"valid\": BOOL}\n"
    "\n"
    "Exit status: 0 on success, 1 on a failed validation, 2 on bad input.\n";

std::string approx(double d) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  return buf;
}
}  // namespace

int simulate(Args& args) {
  Scene_args sa;
  kinetic::Full_options o;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << simulate_help;
      return 0;
    }
    if (a == "--events") o.max_events = args.unsigned_value(a);
    else if (a == "--no-validate") o.validate = false;
    else if (!sa.take(args, a)) args.unknown(a);
  }
  const scene::Scene s = sa.load_scene("simulate");
  const kinetic::Full_simulation sim = kinetic::simulate_full(s, o);
  if (sa.json) std::cout << "{\"events\": [";
  for (std::size_t i = 0; i < sim.events.size(); ++i) {
    const auto& e = sim.events[i];
    if (sa.json)
      std::cout << (i ? ", " : "") << "{\"time\": " << json_string(e.time.to_string())
                << ", \"approx\": " << json_string(approx(e.time.to_double())) << ", \"failing\": " << e.failing
                << ", \"certificates\": " << e.certificates << ", \"changed\": " << (e.changed ? "true" : "false") << "}";
    else
      std::cout << "event " << i + 1 << " at t = " << approx(e.time.to_double()) << " (" << e.time.to_string()
                << "): " << e.failing << " of " << e.certificates << " certificates fail, tree "
                << (e.changed ? "changed" : "unchanged") << "\n";
  }
  if (sa.json) std::cout << "], \"valid\": " << (sim.valid ? "true" : "false") << "}\n";
  if (!sim.valid) {
    std::cerr << "kvd simulate: validation failed: " << sim.failure << "\n";
    return 1;
  }
  return 0;
}

}  // namespace kvd::cli
