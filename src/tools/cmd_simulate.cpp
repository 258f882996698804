// kvd simulate SCENE: the kinetic KVD with the full certificate set.
#include <cstdio>
#include <iostream>

#include "cli.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/kinetic/full_simulation.hpp"

namespace kvd::cli {

namespace {
const char* const simulate_help =
    "usage: kvd simulate SCENE [--events N] [--until T] [--validate every|end|none] [--seed S]\n"
    "                    [--kernel exact|double|mpfr:BITS] [--trace FILE] [--json]\n"
    "\n"
    "Runs the kinetic KVD from the scene's start, with the exact kernel, the\n"
    "full certificate set (every sign the construction evaluated) and the\n"
    "reference update (rebuild just after each event), until the scene's end,\n"
    "the last event, the batch holding the N-th certificate failure (default\n"
    "100), or the last batch at a time <= T. Failures at the same algebraic\n"
    "time are one batch. With --validate every (the default), the tree in force\n"
    "between two batches is compared with a fresh build at a rational time\n"
    "strictly between them (a difference is a missed event: a failed check);\n"
    "with end, only before the last batch. Triangles that meet (a collision)\n"
    "stop the simulation with a message and status 0. Progress goes to stderr\n"
    "every 100 batches.\n"
    "\n"
    "  --kernel K     exact (default); double or mpfr:BITS group the failures\n"
    "                 within the kernel's epsilon of the earliest (the thesis's\n"
    "                 epsilon-minimum) and validate at midpoints\n"
    "  --trace FILE   one JSON line per certificate failure (format in the README)\n"
    "  --json   {\"batches\": [{\"time\": EXACT, \"approx\": DECIMAL, \"failing\": N,\n"
    "           \"certificates\": N, \"changed\": BOOL}, ...], \"events\": N,\n"
    "           \"simultaneous_batches\": N, \"collisions\": N, \"validation_failures\": N,\n"
    "           \"time_reached\": DECIMAL, \"time_reached_exact\": EXACT, \"structure_hash\": HEX}\n"
    "\n"
    "Exit status: 0 on success, 1 on a failed validation, 2 on bad input.\n";

std::string approx(double d) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  return buf;
}
const char* kind_name(symbolic::Symbolic_vertex::Kind k) {
  using K = symbolic::Symbolic_vertex::Kind;
  switch (k) {
    case K::endpoint: return "endpoint";
    case K::intersection: return "intersection";
    case K::thread: return "thread";
    case K::internal_intersection: return "internal-intersection";
    case K::internal_thread: return "internal-thread";
    case K::axis: return "axis";
  }
  return "?";
}

// The isolating interval of an exact time; a floating-point time is its own.
std::pair<std::string, std::string> interval(const Exact_kernel&, const Exact_time& t) {
  return {t.lower().get_str(), t.upper().get_str()};
}
template <class K>
std::pair<std::string, std::string> interval(const K& k, const typename K::Time& t) {
  return {k.to_string(t), k.to_string(t)};
}

// JSON Lines, one per certificate failure, in batch order.
template <class K>
std::string trace_lines(const K& k, const kinetic::Full_simulation<typename K::Time>& sim) {
  std::string out;
  for (std::size_t b = 0; b < sim.events.size(); ++b) {
    const auto& e = sim.events[b];
    const auto [lo, hi] = interval(k, e.time);
    const std::string head = "{\"batch\": " + std::to_string(b) + ", \"time\": " + json_string(k.to_string(e.time)) +
                             ", \"interval\": [" + json_string(lo) + ", " + json_string(hi) +
                             "], \"approx\": " + json_string(approx(k.to_double(e.time)));
    for (const auto& [v, p] : e.failing_certificates) {
      const char* plane = p.kind == symbolic::Symbolic_plane::Kind::P ? "P" : p.kind == symbolic::Symbolic_plane::Kind::E ? "E" : "T";
      out += head + ", \"certificate\": " + json_string(std::string(kind_name(v.kind)) + "/" + plane) +
             ", \"vertex\": " + json_string(symbolic::to_string(v)) + ", \"plane\": " + json_string(symbolic::to_string(p)) +
             "}\n";
    }
  }
  return out;
}

template <class K>
int report(const K& k, const scene::Scene& s, const kinetic::Full_options& o, const std::optional<std::string>& trace,
           bool json) {
  const auto sim = kinetic::simulate_full(k, s, o);
  if (trace) write_atomically("simulate", *trace, trace_lines(k, sim));
  if (json) std::cout << "{\"kernel\": " << json_string(K::name) << ", \"batches\": [";
  for (std::size_t i = 0; i < sim.events.size(); ++i) {
    const auto& e = sim.events[i];
    if (json)
      std::cout << (i ? ", " : "") << "{\"time\": " << json_string(k.to_string(e.time))
                << ", \"approx\": " << json_string(approx(k.to_double(e.time))) << ", \"failing\": " << e.failing()
                << ", \"certificates\": " << e.certificates << ", \"changed\": " << (e.changed ? "true" : "false") << "}";
    else
      std::cout << "event " << i + 1 << " at t = " << approx(k.to_double(e.time)) << " (" << k.to_string(e.time)
                << "): " << e.failing() << " of " << e.certificates << " certificates fail, tree "
                << (e.changed ? "changed" : "unchanged") << "\n";
  }
  if (json)
    std::cout << "], \"events\": " << sim.failures << ", \"simultaneous_batches\": " << sim.simultaneous_batches
              << ", \"collisions\": " << (sim.collision ? 1 : 0) << ", \"validation_failures\": " << sim.validation_failures
              << ", \"time_reached\": " << json_string(approx(k.to_double(sim.time_reached)))
              << ", \"time_reached_exact\": " << json_string(k.to_string(sim.time_reached))
              << ", \"structure_hash\": " << json_string(sim.structure_hash) << "}\n";
  else
    std::cout << sim.failures << " certificate failures in " << sim.events.size() << " batches ("
              << sim.simultaneous_batches << " simultaneous), time reached " << approx(k.to_double(sim.time_reached))
              << ", structure " << sim.structure_hash << "\n";
  if (sim.collision) std::cerr << "kvd simulate: " << *sim.collision << "\n";
  if (!sim.valid()) {
    std::cerr << "kvd simulate: validation failed: " << sim.failure << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int simulate(Args& args) {
  Scene_args sa;
  kinetic::Full_options o;
  std::optional<std::string> trace;
  std::string kernel = "exact";
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << simulate_help;
      return 0;
    }
    if (a == "--events") o.max_events = args.unsigned_value(a);
    else if (a == "--kernel") kernel = args.value(a);
    else if (a == "--trace") trace = args.value(a);
    else if (a == "--until") o.until = exact_option("simulate", a, args.value(a));
    else if (a == "--validate") {
      const std::string& v = args.value(a);
      if (v == "every") o.validate = kinetic::Validation::every;
      else if (v == "end") o.validate = kinetic::Validation::end;
      else if (v == "none") o.validate = kinetic::Validation::none;
      else throw Usage_error("kvd simulate: --validate expects every, end or none");
    } else if (!sa.take(args, a)) args.unknown(a);
  }
  const scene::Scene s = sa.load_scene("simulate");
  o.progress = [](std::size_t batches, std::size_t failures) {
    if (batches % 100 == 0) std::cerr << "kvd simulate: " << batches << " batches, " << failures << " failures\n";
  };
  return with_kernel("simulate", kernel, [&](const auto& k) { return report(k, s, o, trace, sa.json); });
}

}  // namespace kvd::cli
