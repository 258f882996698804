// kvd certify SCENE --out FILE: the exact simulation's event-order
// certificate (proofs/event-order-certificate.md); a segment scene's is
// written by segment_certify.cpp.
#include <iostream>

#include "cli.hpp"
#include "json_out.hpp"
#include "kvd/kinetic/event_order.hpp"
#include "kvd/scene/scene_io.hpp"
#include "segment_commands.hpp"

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
    "For a kvd-segments/1 scene: the exact kinetic cylindrical BSP (seed 003,\n"
    "as kvd simulate runs it) and a kvd-segment-event-order/1 certificate: the\n"
    "scene, every certificate in force (an x order, a side or the order of two\n"
    "lines at a point, with its sign and factor polynomials), every failure\n"
    "with an interval isolating its time and its order relation to the one\n"
    "before, and the certificates in force between consecutive batches. Takes\n"
    "--events, --until and --validate every|none.\n"
    "\n"
    "FILE is written completely or not at all. Exit status: 0 on success, 1 on a\n"
    "failed validation (nothing written), 2 on bad input.\n";

// The layout of json_lines: the certificates, events, intervals and motion
// changes one a line; the scene as the scene writer lays it out.
std::string document(const scene::Scene& s, const kinetic::Event_order& order, const std::optional<mpq_class>& end,
                     const char* stopped_by) {
  using Order = kinetic::Event_order;
  const auto certificate = [&](std::size_t id) {
    const auto& c = order.certificates[id];
    Json polynomial = Json::array();
    for (const auto& a : c.polynomial) polynomial.push_back(a.get_str());
    return Json{{"kind", kinetic::to_string(c.key.type)}, {"features", kinetic::features(c.key)}, {"polynomial", polynomial}};
  };
  const auto root = [&](const Order::Root& r) {
    Json j = {{"certificate", r.certificate}};
    j.update(certificate(r.certificate));
    j["interval"] = Json::array({r.lo.get_str(), r.hi.get_str()});
    j["multiplicity"] = r.multiplicity;
    return j;
  };
  Json certificates = Json::array();
  for (std::size_t i = 0; i < order.certificates.size(); ++i) {
    certificates.push_back(certificate(i));
    certificates.back()["motions"] = order.certificates[i].motions;
  }
  Json events = Json::array();
  for (const auto& e : order.events) {
    events.push_back(root(e));
    events.back()["order"] = e.equal_to_previous ? "=" : "<";
    events.back()["collision"] = e.collision;
  }
  Json intervals = Json::array();
  for (const auto& active : order.intervals) intervals.push_back({{"active", active}});
  Json changes = Json::array();
  for (const auto& c : order.motion_changes) {
    Json failing = Json::array(), motions = Json::array();
    for (const auto& r : c.failing) failing.push_back(root(r));
    for (const auto& m : c.motions) motions.push_back(verbatim(scene::write_motion(m)));
    changes.push_back({{"after_events", c.after_events},
                       {"time", c.time.get_str()},
                       {"failing", failing},
                       {"objects", c.objects},
                       {"motions", motions},
                       {"contact", c.contact}});
  }
  const Json doc = {{"format", "kvd-event-order/2"},
                    {"scene", verbatim(scene::write_scene(s))},
                    {"certificate_set", "reduced"},
                    {"start", s.start.get_str()},
                    {"end", end ? Json(end->get_str()) : Json(nullptr)},
                    {"stopped_by", stopped_by},
                    {"certificates", certificates},
                    {"events", events},
                    {"intervals", intervals},
                    {"motion_changes", changes}};
  return json_lines(doc) + "\n";
}

}  // namespace

int certify(Args& args) {
  Scene_args sa;
  kinetic::Options o;
  o.validate = kinetic::Validation::none;
  std::optional<std::string> out;
  std::vector<std::string> triangle_only;  // flags a segment scene refuses
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << certify_help;
      return 0;
    }
    if (a == "--events") o.max_events = args.unsigned_value(a);
    else if (a == "--until") o.until = exact_option("certify", a, args.value(a));
    else if (a == "--out") out = args.value(a);
    else if (a == "--collisions") {
      o.collisions = collisions_option("certify", args.value(a));
      triangle_only.push_back(a);
    }
    else if (a == "--validate") o.validate = validation_option("certify", args.value(a));
    else if (a == "--json" || !sa.take(args, a)) args.unknown(a);
  }
  if (!out) throw Usage_error("kvd certify: missing --out FILE (see kvd certify --help)");
  const std::string text = sa.read_text("certify");
  if (segments::scene_format(text) == "kvd-segments/1") {
    if (sa.load.allow_intersecting) triangle_only.push_back("--allow-intersecting");
    refuse_triangle_flags("certify", triangle_only);
    if (o.validate == kinetic::Validation::end)
      throw Usage_error("kvd certify: --validate end: a segment scene takes every or none");
    return segment_certify(sa, text, {*out, o.max_events, o.until, o.validate == kinetic::Validation::every});
  }
  const scene::Scene s = sa.read_scene("certify", text);
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
