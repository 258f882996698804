// kvd certify SCENE --out FILE: the exact simulation's event-order
// certificate (proofs/event-order-certificate.md).
#include <iostream>

#include "cli.hpp"
#include "kvd/kinetic/event_order.hpp"
#include "kvd/scene/scene_io.hpp"

namespace kvd::cli {

namespace {
const char* const certify_help =
    "usage: kvd certify SCENE --out FILE [--events N] [--until T] [--seed S]\n"
    "                   [--collisions reverse|stop] [--validate every|end|none]\n"
    "                   [--allow-intersecting]\n"
    "\n"
    "Runs the exact kinetic KVD (reduced certificates, as kvd simulate) and\n"
    "writes an event-order certificate to FILE: the scene, every certificate\n"
    "polynomial in force between consecutive instants, every event with an\n"
    "interval isolating its time, its multiplicity and its order relation to\n"
    "the event before, and every motion change: triangles about to meet have\n"
    "their motions reversed (X-collide) at a rational time before the contact,\n"
    "and the file holds the contact, that time and the new motions.\n"
    "proofs/check-certificate FILE verifies it independently.\n"
    "Format: proofs/event-order-certificate.md.\n"
    "\n"
    "  --events N       stop after the batch or motion change that reaches N\n"
    "                   failures, or N motion changes (default 100)\n"
    "  --until T        stop after the last batch at a time <= T (exact)\n"
    "  --collisions C   reverse (default), or stop at the first contact\n"
    "  --validate V     check the tree against fresh builds: every, end or none\n"
    "                   (default none; the certificate does not rely on it)\n"
    "\n"
    "FILE is written completely or not at all. Exit status: 0 on success, 1 on a\n"
    "failed validation (nothing written), 2 on bad input.\n";

std::string integers(const zpoly::ZPoly& p) {
  std::string out = "[";
  for (std::size_t i = 0; i < p.size(); ++i) out += (i ? ", " : "") + json_string(p[i].get_str());
  return out + "]";
}

template <class T, class Show>
std::string array(const std::vector<T>& v, Show show) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + show(v[i]);
  return out + "]";
}

std::string document(const scene::Scene& s, const kinetic::Event_order& order, const std::optional<mpq_class>& end,
                     const char* stopped_by) {
  using Order = kinetic::Event_order;
  auto kind_features = [&](std::size_t id) {
    const auto& c = order.certificates[id];
    return "\"kind\": " + json_string(kinetic::to_string(c.key.type)) + ", \"features\": " + json_string(kinetic::features(c.key)) +
           ", \"polynomial\": " + integers(c.polynomial);
  };
  auto root = [&](const Order::Root& r) {
    return "\"certificate\": " + std::to_string(r.certificate) + ", " + kind_features(r.certificate) +
           ", \"interval\": [" + json_string(r.lo.get_str()) + ", " + json_string(r.hi.get_str()) +
           "], \"multiplicity\": " + std::to_string(r.multiplicity);
  };
  const auto number = [](std::size_t i) { return std::to_string(i); };
  // One item per line: "[\n a,\n b\n]", or "[]".
  const auto lines = [](std::size_t n, const auto& item) {
    if (n == 0) return std::string("[]");
    std::string out = "[";
    for (std::size_t i = 0; i < n; ++i) out += (i ? ",\n " : "\n ") + item(i);
    return out + "\n]";
  };
  const auto certificate = [&](std::size_t i) {
    return "{" + kind_features(i) + ", \"motions\": " + std::to_string(order.certificates[i].motions) + "}";
  };
  const auto event = [&](std::size_t i) {
    const auto& e = order.events[i];
    return "{" + root(e) + ", \"order\": \"" + (e.equal_to_previous ? "=" : "<") +
           "\", \"collision\": " + (e.collision ? "true" : "false") + "}";
  };
  const auto interval = [&](std::size_t i) { return "{\"active\": " + array(order.intervals[i], number) + "}"; };
  const auto change = [&](std::size_t i) {
    const auto& c = order.motion_changes[i];
    return "{\"after_events\": " + std::to_string(c.after_events) + ", \"time\": " + json_string(c.time.get_str()) +
           ", \"failing\": " + array(c.failing, [&](const Order::Root& r) { return "{" + root(r) + "}"; }) +
           ", \"objects\": " + array(c.objects, number) + ", \"motions\": " + array(c.motions, scene::write_motion) +
           ", \"contact\": " + json_string(c.contact) + "}";
  };
  return "{\n\"format\": \"kvd-event-order/2\",\n\"scene\": " + scene::write_scene(s) +
         ",\n\"certificate_set\": \"reduced\",\n\"start\": " + json_string(s.start.get_str()) +
         ",\n\"end\": " + (end ? json_string(end->get_str()) : "null") + ",\n\"stopped_by\": " + json_string(stopped_by) +
         ",\n\"certificates\": " + lines(order.certificates.size(), certificate) +
         ",\n\"events\": " + lines(order.events.size(), event) +
         ",\n\"intervals\": " + lines(order.intervals.size(), interval) +
         ",\n\"motion_changes\": " + lines(order.motion_changes.size(), change) + "\n}\n";
}

}  // namespace

int certify(Args& args) {
  Scene_args sa;
  kinetic::Options o;
  o.validate = kinetic::Validation::none;
  std::optional<std::string> out;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << certify_help;
      return 0;
    }
    if (a == "--events") o.max_events = args.unsigned_value(a);
    else if (a == "--until") o.until = exact_option("certify", a, args.value(a));
    else if (a == "--out") out = args.value(a);
    else if (a == "--collisions") o.collisions = collisions_option("certify", args.value(a));
    else if (a == "--validate") o.validate = validation_option("certify", args.value(a));
    else if (a == "--json" || !sa.take(args, a)) args.unknown(a);
  }
  if (!out) throw Usage_error("kvd certify: missing --out FILE (see kvd certify --help)");
  const scene::Scene s = sa.load_scene("certify");
  if (o.until) require_in_span("certify", "--until", *o.until, s);
  o.progress = progress_every_few_seconds("kvd certify");
  kinetic::Event_order_recorder recorder;
  const Exact_kernel k;
  const auto sim = with_disjoint_triangles("certify", *sa.path, [&] { return kinetic::simulate(k, s, o, &recorder); });
  if (!sim.valid()) {
    std::cerr << "kvd certify: validation failed: " << sim.failure << "\n";
    return 1;
  }
  // Why the run stopped decides the last interval: up to the time limit, up
  // to +infinity when nothing fails any more, none after the last event.
  using kinetic::Stop;
  const char* stopped_by = sim.stopped == Stop::collision ? "collision"
                           : sim.stopped == Stop::events  ? "events"
                           : sim.limit                    ? "until"
                                                          : "exhausted";
  kinetic::Event_order order = recorder.take();
  std::optional<mpq_class> end;
  if (sim.stopped == Stop::events) {
    order.intervals.pop_back();  // in force after the last batch, up to an event not processed
  } else if (sim.stopped != Stop::collision && sim.limit) {
    // A batch exactly at the limit is the last event: no interval follows.
    if (!sim.batches.empty() && k.compare(sim.batches.back().time, Exact_time(*sim.limit)) == 0)
      order.intervals.pop_back();
    else end = sim.limit;
  }
  write_atomically("certify", *out, document(s, order, end, stopped_by));
  std::size_t batches = 0;
  for (const auto& e : order.events) batches += !e.equal_to_previous;
  std::cout << "kvd certify: " << order.events.size() << " events in " << batches << " batches, "
            << order.motion_changes.size() << " motion changes, " << order.certificates.size()
            << " certificate polynomials, stopped by " << stopped_by
            << (sim.collision ? " (" + *sim.collision + ")" : "") << "; wrote " << *out << "\n";
  return 0;
}

}  // namespace kvd::cli
