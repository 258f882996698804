// kvd simulate SCENE: the kinetic KVD, its events and the statistics of
// thesis Figures 8.5-8.7.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli.hpp"
#include "json_out.hpp"
#include "report.hpp"
#include "segment_commands.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/scene_io.hpp"

namespace kvd::cli {

namespace {
const char* const simulate_help =
    "usage: kvd simulate SCENE [--events N] [--until T] [--validate every|end|none] [--seed S]\n"
    "                    [--kernel exact|double|mpfr:BITS] [--epsilon E] [--no-filter]\n"
    "                    [--certificates reduced|full] [--queue tree|heap]\n"
    "                    [--update local|reinsert|subtree|rebuild] [--upkeep local|all]\n"
    "                    [--collisions reverse|stop]\n"
    "                    [--trace FILE] [--list] [--json]\n"
    "                    [--allow-intersecting]\n"
    "\n"
    "Runs the kinetic KVD from the scene's start, until the scene's end, the last event, the\n"
    "batch holding the N-th certificate failure (default 100), or the last batch\n"
    "at a time <= T. Failures at the same algebraic time are one batch. With\n"
    "--validate every (the default), the tree in force between two batches is\n"
    "compared with a fresh build at a rational time strictly between them (a\n"
    "difference is a missed event: a failed check); with end, only before the\n"
    "last batch. Prints the statistics of the thesis's Figures\n"
    "8.5-8.7; on a long run, progress goes to stderr every two seconds.\n"
    "\n"
    "  --update U        local (default): the thesis's local update (thesis 7.3),\n"
    "                    which moves the sites of the failing certificates'\n"
    "                    features within the subtree of the nodes that decided\n"
    "                    them, re-cutting only the cells their walls swept;\n"
    "                    reinsert: the same sites dragged out of the whole\n"
    "                    tree and inserted again from the root; rebuild: the\n"
    "                    reference, a build just after each batch. Segment\n"
    "                    scenes take local (the frontier replay where it\n"
    "                    applies), subtree (the subtrees of the failures'\n"
    "                    topmost nodes replayed whole) or rebuild\n"
    "  --upkeep U        local (default): after a batch only the nodes whose\n"
    "                    cut, fragment or ancestors changed, or that hold a failed\n"
    "                    certificate, make their reduced certificates again; all:\n"
    "                    every node (the reference)\n"
    "  --collisions C    reverse (default): triangles that meet reverse both\n"
    "                    objects' motions at a rational time just before (thesis\n"
    "                    7.3.3, X-collide) and the run goes on; --events N also\n"
    "                    bounds the number of these motion changes; stop: the run\n"
    "                    stops at the collision with a message and status 0\n"
    "  --certificates S  reduced (default): the thesis's set (thesis 6.4);\n"
    "                    full: every sign the construction evaluated (implies\n"
    "                    --update rebuild, the build being what evaluates them);\n"
    "                    segment scenes: kept (default) or paper, below\n"
    "  --queue Q         tree (default): the kinetic priority queue in the KVD\n"
    "                    (thesis 6.5); heap: a mutable pairing heap\n"
    "  --kernel K        exact (default); double or mpfr:BITS group the failures\n"
    "                    within epsilon of the earliest (the thesis's\n"
    "                    epsilon-minimum) and validate at midpoints\n"
    "  --no-filter       exact kernel: every sign in exact arithmetic, without the\n"
    "                    interval filter in front (the same run, slower)\n"
    "  --epsilon E       that epsilon (default 1e-9 for double, 2^(-BITS/2) for mpfr)\n"
    "                    A floating-point run repairs a tree that rounding made\n"
    "                    inconsistent (a build that throws, a batch repeating\n"
    "                    itself, a tree that validation finds stale) by rebuilding,\n"
    "                    and counts it under \"recovery\"\n"
    "  --trace FILE      one JSON line per certificate failure and per motion change\n"
    "                    (format in the README)\n"
    "  --list            one line per batch\n"
    "  --json   {\"kernel\": K, \"certificate_set\": S, \"queue\": Q, \"batch_list\": [{\"time\": EXACT,\n"
    "           \"approx\": DECIMAL, \"failing\": N, \"certificates\": N, \"changed\": BOOL,\n"
    "           \"scope\": \"subtree\"|\"whole\"|\"widened\"|null, \"nodes_touched\": N,\n"
    "           \"nodes_changed\": N, \"nodes_recomputed\": N,\n"
    "           \"certificates_recomputed\": N}, ...],\n"
    "           \"motion_changes\": [{\"time\": EXACT, \"approx\",\n"
    "           \"collision\": EXACT, \"collision_approx\", \"objects\": [ID, ...], \"motions\": [...],\n"
    "           \"batches_before\": N, \"tree_changed\": BOOL, \"contact\": TEXT}, ...], \"update\": U,\n"
    "           \"nodes_touched\": {\"median\", \"changed_median\", \"below_10_share\",\n"
    "           \"scopes\": {\"subtree\", \"whole\", \"widened\"}} (null with\n"
    "           rebuild; changed: the larger of the cuts and fragments the batch\n"
    "           made and those it removed),\n"
    "           \"certificates_recomputed\": {\"median\", \"nodes_median\", \"total\"},\n"
    "           \"events\": N, \"batches\": N, \"simultaneous_batches\": N, \"collisions\": N,\n"
    "           \"stopped\": events|limit|exhausted|collision|stuck, \"validation\": every|end|none,\n"
    "           \"validations\": N (trees compared with a fresh build),\n"
    "           \"validation_failures\": N, \"time_reached\": DECIMAL, \"time_reached_exact\": EXACT\n"
    "           (the last batch's time; the span's end or --until when no event is left before it),\n"
    "           \"structure_hash\": HEX, \"certificates_by_type\": {...}, \"events_by_type\": {...},\n"
    "           \"construction_ms\": X, \"update_ms\": {\"average\", \"max\", \"stddev\",\n"
    "           \"median\", \"tree_median\"},\n"
    "           \"recovery\": {\"failed_builds\", \"refires\", \"stale_trees\", \"rebuilds\", \"zones_skipped\",\n"
    "           \"unrepaired\"},\n"
    "           \"tree_update_share\": X, \"certificate_update_share\": X,\n"
    "           \"filter\": {...} (the exact kernel's filter statistics, README; null otherwise)}\n"
    "  --allow-intersecting\n"
    "           accept triangles that intersect at the start time\n"
    "\n"
    "For a kvd-segments/1 scene: the kinetic cylindrical BSP (seed 003, section\n"
    "3.1). Its certificates are the signs the construction evaluated; each\n"
    "failure is a vertex, edge, intersection or flip event; the tree just after\n"
    "a batch is made by replaying the construction in the subtree of each\n"
    "topmost node where a failing certificate was decided (--update local, the\n"
    "default; a flip replays the cells the turning segment cuts) or by building\n"
    "the whole tree again\n"
    "(--update rebuild). With --certificates paper (exact kernel; the\n"
    "default is kept), the run holds only seed 003's own set instead: one\n"
    "certificate per transient node, per endpoint (its neighbours above and\n"
    "below) and per segment (a flip), each a few signs with exact failure\n"
    "times; flips alone at their instant, in leaves apart, are turned in\n"
    "place as the paper's section 3.1.4 does (flips_in_place); a batch\n"
    "whose certificates changed only signs one segment's steps decide (two\n"
    "walls crossing, an endpoint passing through a segment; several apart)\n"
    "decides that segment's steps again and remakes only the cells of the\n"
    "tree before it whose arrivals changed (frontier_replays); any other\n"
    "batch makes again the\n"
    "subtrees its failing certificates name, keeping the old cells below\n"
    "whose arrivals did not change or changed only by a wall renamed (the\n"
    "paper's LeftShave and splits are not implemented),\n"
    "and --list names the certificates that fail and counts those made\n"
    "again (certificates_made; Lemma 3.1: O(1) at an event), the signs\n"
    "decided, those asked again in the batch (repeated) and where the\n"
    "decided ones went (signs_by: the guards over the changing segments'\n"
    "own steps and over other segments' steps, ties, certificates, the\n"
    "endpoints' leaves, walls renamed; the rest made cuts). Takes\n"
    "--events, --until, --validate every|none, --update, --certificates,\n"
    "--kernel, --epsilon, --no-filter, --list, --json\n"
    "(failures_by_event, changed_batches_by_event, batches, validations,\n"
    "update_ms, nodes_rebuilt, batch_list, recovery). In the floating-point\n"
    "kernels a construction whose signs contradict each other is built again\n"
    "at now, then at now + 2^i epsilon (recovery: failed_builds, rebuilds;\n"
    "stopped: stuck when none succeeds).\n"
    "\n"
    "Exit status: 0 on success, 1 on a failed validation or a floating-point run\n"
    "stuck at one instant or unable to start (its rounding makes triangles\n"
    "cross that the exact kernel keeps apart), 2 on bad input.\n";

// The canonical isolating interval of an exact time; a floating-point time
// is its own.
std::pair<std::string, std::string> interval(const Exact_kernel&, const Exact_time& t) {
  const auto [lo, hi] = t.canonical_interval();
  return {lo.get_str(), hi.get_str()};
}
template <class K>
std::pair<std::string, std::string> interval(const K& k, const typename K::Time& t) {
  return {k.to_string(t), k.to_string(t)};
}

// A motion change as JSON; the motions keep the scene writer's layout.
template <class K>
Json motion_change_json(const K& k, const kinetic::Motion_change<typename K::Time>& c) {
  Json motions = Json::array();
  for (const auto& m : c.motions) motions.push_back(verbatim(scene::write_motion(m)));
  return {{"time", c.time.get_str()},
          {"approx", approx(c.time.get_d())},
          {"collision", k.to_string(c.collision)},
          {"collision_approx", approx(k.to_double(c.collision))},
          {"objects", c.objects},
          {"motions", motions},
          {"batches_before", c.batches_before},
          {"tree_changed", c.tree_changed},
          {"contact", c.contact}};
}

// JSON Lines, one per certificate failure and one per motion change, in the
// order of the run.
template <class K>
std::string trace_lines(const K& k, const kinetic::Simulation<typename K::Time>& sim) {
  std::string out;
  kinetic::in_run_order(
      sim,
      [&](std::size_t c) {
        Json line = {{"motion_change", c}};
        line.update(motion_change_json(k, sim.motion_changes[c]));
        out += json_line(line) + "\n";
      },
      [&](std::size_t b) {
        const auto& e = sim.batches[b];
        const auto [lo, hi] = interval(k, e.time);
        for (const auto& f : e.failing)
          out += json_line({{"batch", b},
                            {"time", k.to_string(e.time)},
                            {"interval", Json::array({lo, hi})},
                            {"approx", approx(k.to_double(e.time))},
                            {"certificate", kinetic::to_string(f.type)},
                            {"nodes", kinetic::features(f)}}) +
                 "\n";
      });
  return out;
}

std::string by_type_text(const kinetic::Type_counts& counts) {
  std::string out;
  std::size_t total = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    total += counts[i];
    if (counts[i]) out += std::string(" ") + kinetic::to_string(static_cast<kinetic::Certificate_type>(i)) + " " + std::to_string(counts[i]);
  }
  return std::to_string(total) + (out.empty() ? "" : " (" + out.substr(1) + ")");
}

// Why the run stopped, in words.
template <class K>
std::string stop_text(const K& k, const kinetic::Simulation<typename K::Time>& sim, const kinetic::Options& o) {
  switch (sim.stopped) {
    case kinetic::Stop::events: return "the event limit (--events " + std::to_string(o.max_events) + ")";
    case kinetic::Stop::limit:
      return "the time limit " + sim.limit->get_str() +
             (o.until && *o.until == *sim.limit ? " (--until)" : " (the scene's end)") + ": no failure before it";
    case kinetic::Stop::exhausted: return "no certificate fails any more";
    case kinetic::Stop::collision: return "a collision (--collisions stop, or no reversal possible)";
    case kinetic::Stop::stuck:
      return "stuck at t = " + approx(k.to_double(sim.time_reached)) + ": a batch repeats without advancing";
  }
  return "?";
}

// Which trees were checked against a fresh build, and what was found.
template <class Time>
std::string validation_text(const kinetic::Simulation<Time>& sim, const kinetic::Options& o) {
  if (o.validate == kinetic::Validation::none) return "none (--validate none)";
  return std::string(o.validate == kinetic::Validation::every ? "every batch" : "the last batch") + ", " +
         std::to_string(sim.validations) + " trees compared with a fresh build, " +
         std::to_string(sim.validation_failures) + " mismatches";
}

template <class K>
int report(const K& k, const scene::Scene& s, const kinetic::Options& o, const std::optional<std::string>& trace,
           bool list, bool json) {
  const auto sim = kinetic::simulate(k, s, o);
  if (trace) write_atomically("simulate", *trace, trace_lines(k, sim));
  const Update_costs u = update_costs(sim);
  const char* set = o.certificates == kinetic::Certificate_set::reduced ? "reduced" : "full";
  const char* queue = o.queue == kinetic::Queue_kind::tree ? "tree" : "heap";
  const char* update = o.update == kinetic::Update::local      ? "local"
                       : o.update == kinetic::Update::reinsert ? "reinsert"
                                                               : "rebuild";
  const bool local = o.update != kinetic::Update::rebuild;
  const Touched touched = nodes_touched(sim);
  const Recomputed recomputed = certificates_recomputed(sim);
  const std::size_t collisions = sim.motion_changes.size() + (sim.collision ? 1 : 0);
  if (json) {
    Json batches = Json::array();
    for (const auto& e : sim.batches)
      batches.push_back({{"time", k.to_string(e.time)},
                         {"approx", approx(k.to_double(e.time))},
                         {"failing", e.failures()},
                         {"certificates", e.certificates},
                         {"changed", e.changed},
                         {"scope", e.scope == kinetic::Update_scope::none
                                       ? Json(nullptr)
                                       : Json(kinetic::update_scope_names[static_cast<std::size_t>(e.scope)])},
                         {"nodes_touched", e.nodes_touched},
                         {"nodes_changed", e.nodes_changed},
                         {"nodes_recomputed", e.nodes_recomputed},
                         {"certificates_recomputed", e.certificates_recomputed}});
    Json changes = Json::array();
    for (const auto& c : sim.motion_changes) changes.push_back(motion_change_json(k, c));
    const Json touched_json = local
                                  ? Json{{"median", decimal(fixed(touched.median, 1))},
                                         {"changed_median", decimal(fixed(touched.changed_median, 1))},
                                         {"below_10_share", decimal(fixed(touched.below_10_share, 3))},
                                         {"scopes", {{"subtree", touched.scopes[1]},
                                                     {"whole", touched.scopes[2]},
                                                     {"widened", touched.scopes[3]}}}}
                                  : Json(nullptr);
    const Json j = {
        {"kernel", kernel_label(k)},
        {"certificate_set", set},
        {"queue", queue},
        {"batch_list", batches},
        {"motion_changes", changes},
        {"update", update},
        {"nodes_touched", touched_json},
        {"certificates_recomputed",
         {{"median", decimal(fixed(recomputed.median, 1))},
          {"nodes_median", decimal(fixed(recomputed.nodes_median, 1))},
          {"total", recomputed.total}}},
        {"events", sim.failures},
        {"batches", sim.batches.size()},
        {"simultaneous_batches", sim.simultaneous_batches},
        {"collisions", collisions},
        {"stopped", stop_name(sim.stopped)},
        {"validation", validation_name(o.validate)},
        {"validations", sim.validations},
        {"validation_failures", sim.validation_failures},
        {"time_reached", approx(k.to_double(sim.time_reached))},
        {"time_reached_exact", k.to_string(sim.time_reached)},
        {"structure_hash", sim.structure_hash},
        {"certificates_by_type", type_counts_json(sim.initial_certificates)},
        {"events_by_type", type_counts_json(sim.failures_by_type)},
        {"construction_ms", decimal(fixed(1000 * sim.construction_seconds, 3))},
        {"update_ms",
         {{"average", decimal(fixed(u.average, 3))},
          {"max", decimal(fixed(u.max, 3))},
          {"stddev", decimal(fixed(u.stddev, 3))},
          {"median", decimal(fixed(u.median, 3))},
          {"tree_median", decimal(fixed(u.tree_median, 3))}}},
        {"recovery", recovery_json(sim.recovery)},
        {"tree_update_share", decimal(fixed(u.tree_share, 3))},
        {"certificate_update_share", decimal(fixed(u.certificate_share, 3))},
        {"filter", filter_json(k)}};
    std::cout << json_line(j) << "\n";
  } else {
    if (list)
      kinetic::in_run_order(
          sim,
          [&](std::size_t i) {
            const auto& c = sim.motion_changes[i];
            std::string objects;
            for (std::size_t o : c.objects) objects += (objects.empty() ? "" : ", ") + std::to_string(o);
            std::cout << "motion change at t = " << approx(c.time.get_d()) << " (" << c.time.get_str() << "): objects "
                      << objects << " reversed before meeting at t = " << approx(k.to_double(c.collision)) << "\n";
          },
          [&](std::size_t i) {
            const auto& e = sim.batches[i];
            std::cout << "batch " << i + 1 << " at t = " << approx(k.to_double(e.time)) << " (" << k.to_string(e.time)
                      << "): " << e.failures() << " of " << e.certificates << " certificates fail, tree "
                      << (e.changed ? "changed" : "unchanged") << ", " << e.certificates_recomputed
                      << " certificates recomputed\n";
          });
    std::cout << "kernel:        " << kernel_label(k) << ", " << set << " certificates, " << queue << " queue, " << update
              << " update\n"
              << "events:        " << sim.failures << " certificate failures in " << sim.batches.size() << " batches ("
              << sim.simultaneous_batches << " simultaneous)\n"
              << "time reached:  " << approx(k.to_double(sim.time_reached)) << "\n"
              << "stopped:       " << stop_text(k, sim, o) << "\n"
              << "validation:    " << validation_text(sim, o) << "\n"
              << (sim.motion_changes.empty() ? std::string()
                                             : "collisions:    " + std::to_string(sim.motion_changes.size()) +
                                                   " answered by reversing motions (X-collide)\n")
              << "structure:     " << sim.structure_hash << "\n"
              << "certificates:  " << by_type_text(sim.initial_certificates) << " at the start\n"
              << "events:        " << by_type_text(sim.failures_by_type) << "\n"
              << "construction:  " << fixed(1000 * sim.construction_seconds, 3) << " ms\n"
              << "update (ms):   average " << fixed(u.average, 3) << ", max " << fixed(u.max, 3) << ", stddev "
              << fixed(u.stddev, 3) << ", median " << fixed(u.median, 3) << " (tree " << fixed(u.tree_median, 3) << ")\n"
              << (local
                      ? "nodes touched: median " + fixed(touched.median, 1) + " per batch, " +
                            fixed(100 * touched.below_10_share, 1) + "% of batches below 10\n" +
                            "scopes:        " + std::to_string(touched.scopes[1]) + " batches in a subtree, " +
                            std::to_string(touched.scopes[2]) + " over the whole tree, " +
                            std::to_string(touched.scopes[3]) + " widened\n"
                      : std::string())
              << "recomputed:    median " << fixed(recomputed.median, 1) << " certificates per batch "
              << "at " << fixed(recomputed.nodes_median, 1) << " nodes, " << recomputed.total << " in all\n"
              << "update shares: tree " << fixed(u.tree_share, 2) << ", certificates " << fixed(u.certificate_share, 2)
              << "\n";
    if (sim.recovery.detected()) std::cout << "recovery:      " << recovery_text(sim.recovery) << "\n";
  }
  if (sim.collision) std::cerr << "kvd simulate: " << *sim.collision << "\n";
  if (sim.stopped == kinetic::Stop::stuck) {
    std::cerr << "kvd simulate: the " << kernel_label(k) << " run repeats a batch at t = " << approx(k.to_double(sim.time_reached))
              << " without advancing, and no repair moved past it: stopped\n";
    return 1;
  }
  if (!sim.valid()) {
    std::cerr << "kvd simulate: validation failed: " << sim.failure << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int simulate(Args& args) {
  Scene_args sa;
  kinetic::Options o;
  std::optional<std::string> trace;
  std::optional<mpq_class> epsilon;
  std::string kernel = "exact";
  bool list = false, filter = true;
  std::optional<kinetic::Update> update;
  std::optional<std::string> certificates;
  bool subtree = false;
  std::vector<std::string> triangle_only;  // flags a segment scene refuses
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << simulate_help;
      return 0;
    }
    for (const char* f : {"--trace", "--queue", "--upkeep", "--collisions"})
      if (a == f) triangle_only.push_back(a);
    if (a == "--events") o.max_events = args.unsigned_value(a);
    else if (a == "--kernel") kernel = args.value(a);
    else if (a == "--epsilon") epsilon = exact_option("simulate", a, args.value(a));
    else if (a == "--trace") trace = args.value(a);
    else if (a == "--list") list = true;
    else if (a == "--no-filter") filter = false;
    else if (a == "--until") o.until = exact_option("simulate", a, args.value(a));
    else if (a == "--certificates") certificates = args.value(a);  // read once the scene's format is known
    else if (a == "--queue")
      o.queue = choice_option<kinetic::Queue_kind>(
          "simulate", a, args.value(a), {{"tree", kinetic::Queue_kind::tree}, {"heap", kinetic::Queue_kind::heap}});
    else if (a == "--update") {
      const std::string v = args.value(a);
      subtree = v == "subtree";  // segment scenes only; the last --update holds
      update = subtree ? std::nullopt
                       : std::optional(choice_option<kinetic::Update>(
                             "simulate", a, v,
                             {{"local", kinetic::Update::local},
                              {"reinsert", kinetic::Update::reinsert},
                              {"rebuild", kinetic::Update::rebuild}}));
    }
    else if (a == "--upkeep")
      o.upkeep = choice_option<kinetic::Upkeep>(
          "simulate", a, args.value(a), {{"local", kinetic::Upkeep::local}, {"all", kinetic::Upkeep::all}});
    else if (a == "--collisions")
      o.collisions = collisions_option("simulate", args.value(a));
    else if (a == "--validate") o.validate = validation_option("simulate", args.value(a));
    else if (!sa.take(args, a)) args.unknown(a);
  }
  const std::string text = sa.read_text("simulate");
  if (segments::scene_format(text) == "kvd-segments/1") {
    const bool paper = certificates && choice_option<bool>("simulate", "--certificates", *certificates,
                                                           {{"kept", false}, {"paper", true}});
    if (paper && kernel != "exact")
      throw Usage_error("kvd simulate: --certificates paper runs in the exact kernel only");
    if (paper && (update || subtree))
      throw Usage_error("kvd simulate: --certificates paper has an update of its own; it takes no --update");
    if (sa.load.allow_intersecting) triangle_only.push_back("--allow-intersecting");
    refuse_triangle_flags("simulate", triangle_only);
    if (o.validate == kinetic::Validation::end)
      throw Usage_error("kvd simulate: --validate end: a segment scene takes every or none");
    if (update == kinetic::Update::reinsert)
      throw Usage_error("kvd simulate: --update reinsert: a segment scene takes local, subtree or rebuild");
    return segment_simulate(sa, text,
                            {o.max_events, o.until, o.validate == kinetic::Validation::every, kernel, epsilon, filter, list,
                             subtree                               ? segments::Segment_update::subtree
                             : update == kinetic::Update::rebuild ? segments::Segment_update::rebuild
                                                                  : segments::Segment_update::local,
                             paper});
  }
  if (certificates)
    o.certificates = choice_option<kinetic::Certificate_set>(
        "simulate", "--certificates", *certificates,
        {{"reduced", kinetic::Certificate_set::reduced}, {"full", kinetic::Certificate_set::full}});
  if (o.certificates == kinetic::Certificate_set::full && update && update != kinetic::Update::rebuild)
    throw Usage_error("kvd simulate: the full certificate set needs --update rebuild");
  o.update = update.value_or(o.certificates == kinetic::Certificate_set::full ? kinetic::Update::rebuild
                                                                            : kinetic::Update::local);
  if (subtree) throw Usage_error("kvd simulate: --update subtree: a triangle scene takes local, reinsert or rebuild");
  const scene::Scene s = sa.read_scene("simulate", text);
  if (o.until) require_in_span("simulate", "--until", *o.until, s);
  o.progress = progress_every_few_seconds("kvd simulate");
  return with_kernel(
      "simulate", kernel, [&](const auto& k) {
        require_representable(*sa.path, s, k);
        return with_disjoint_triangles_in("simulate", *sa.path, k, s, s.start,
                                          [&] { return report(k, s, o, trace, list, sa.json); });
      }, epsilon, filter);
}

}  // namespace kvd::cli
