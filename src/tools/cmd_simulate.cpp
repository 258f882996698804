// kvd simulate SCENE: the kinetic KVD with the full certificate set.
#include <cstdio>
#include <iostream>

#include "cli.hpp"
#include "kvd/kinetic/full_simulation.hpp"

namespace kvd::cli {

namespace {
const char* const simulate_help =
    "usage: kvd simulate SCENE [--events N] [--until T] [--validate every|end|none] [--seed S]\n"
    "                    [--trace FILE] [--json]\n"
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
    "stop the simulation with a message and status 0.\n"
    "\n"
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

// JSON Lines, one per certificate failure, in batch order.
std::string trace_lines(const kinetic::Full_simulation& sim) {
  std::string out;
  for (std::size_t b = 0; b < sim.events.size(); ++b) {
    const auto& e = sim.events[b];
    const std::string head = "{\"batch\": " + std::to_string(b) + ", \"time\": " + json_string(e.time.to_string()) +
                             ", \"interval\": [" + json_string(e.time.lower().get_str()) + ", " +
                             json_string(e.time.upper().get_str()) + "], \"approx\": " + json_string(approx(e.time.to_double()));
    for (const auto& [v, p] : e.failing_certificates) {
      const char* plane = p.kind == symbolic::Symbolic_plane::Kind::P ? "P" : p.kind == symbolic::Symbolic_plane::Kind::E ? "E" : "T";
      out += head + ", \"certificate\": " + json_string(std::string(kind_name(v.kind)) + "/" + plane) +
             ", \"vertex\": " + json_string(symbolic::to_string(v)) + ", \"plane\": " + json_string(symbolic::to_string(p)) +
             "}\n";
    }
  }
  return out;
}

}  // namespace

int simulate(Args& args) {
  Scene_args sa;
  kinetic::Full_options o;
  std::optional<std::string> trace;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << simulate_help;
      return 0;
    }
    if (a == "--events") o.max_events = args.unsigned_value(a);
    else if (a == "--trace") trace = args.value(a);
    else if (a == "--until") o.until = exact_option("simulate", a, args.value(a));
    else if (a == "--validate") {
      const std::string& v = args.value(a);
      if (v == "every") o.validate = kinetic::Validation::every;
      else if (v == "end") o.validate = kinetic::Validation::end;
      else if (v == "none") o.validate = kinetic::Validation::none;
      else throw Usage_error("kvd simulate: --validate expects every, end or none");
    }
    else if (!sa.take(args, a)) args.unknown(a);
  }
  const scene::Scene s = sa.load_scene("simulate");
  const kinetic::Full_simulation sim = kinetic::simulate_full(s, o);
  if (trace) write_atomically("simulate", *trace, trace_lines(sim));
  if (sa.json) std::cout << "{\"batches\": [";
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
  if (sa.json)
    std::cout << "], \"events\": " << sim.failures << ", \"simultaneous_batches\": " << sim.simultaneous_batches
              << ", \"collisions\": " << (sim.collision ? 1 : 0) << ", \"validation_failures\": " << sim.validation_failures
              << ", \"time_reached\": " << json_string(approx(sim.time_reached.to_double()))
              << ", \"time_reached_exact\": " << json_string(sim.time_reached.to_string())
              << ", \"structure_hash\": " << json_string(sim.structure_hash) << "}\n";
  else
    std::cout << sim.failures << " certificate failures in " << sim.events.size() << " batches ("
              << sim.simultaneous_batches << " simultaneous), time reached " << approx(sim.time_reached.to_double())
              << ", structure " << sim.structure_hash << "\n";
  if (sim.collision) std::cerr << "kvd simulate: " << *sim.collision << "\n";
  if (!sim.valid()) {
    std::cerr << "kvd simulate: validation failed: " << sim.failure << "\n";
    return 1;
  }
  return 0;
}

}  // namespace kvd::cli
