// The measurements of kvd bench thesis: each calls the library once, or a
// few times for a median, and adds its values to the results, with one
// progress line on stderr.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>

#include "cli.hpp"
#include "kvd/bsp/autopartition.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kinetic/certificate.hpp"
#include "kvd/query/visibility.hpp"
#include "report.hpp"
#include "sweep.hpp"
#include "thesis.hpp"

namespace kvd::bench::thesis_suite {

namespace {

std::string label(const Where& w) {
  return "kvd bench thesis: " + w.figure + ", " + w.family + " " + std::to_string(w.size) + ", " + w.kernel + ": ";
}

template <class K>
typename K::Time instant(const K& k, const mpq_class& t) {
  return k.time(from_rational<typename K::FT>(t));
}

// The end of a run's span as a rational: the value of a floating-point
// time; for an exact one, the lower end of its isolating interval refined to
// a width of 2^-64 of its size (the value itself when rational). Only the
// instants of the rebuilds depend on it.
mpq_class span_end(const Exact_time& t) {
  while (!t.is_rational() && ((t.upper() - t.lower()) << 64) > abs(t.upper())) t.refine();
  return t.lower();
}
mpq_class span_end(double t) { return to_rational(t); }
mpq_class span_end(const Mpfr_number& t) { return to_rational(t); }

template <class K>
void construction_in(const K& k, const Where& w, const scene::Scene& s, Results& r) {
  std::vector<double> ms;
  tree::Tree_statistics st;
  for (int i = 0; i < repetitions; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const predicates::Classifier<K> c(k, s);
    const tree::Kvd_tree t = cli::build_tree("bench thesis", s.name, c, instant(k, s.start));
    ms.push_back(ms_since(start));
    st = t.statistics();
  }
  const double construction_ms = cli::median(ms);
  r.add(w, "p_nodes", static_cast<double>(st.p_nodes));
  r.add(w, "e_nodes", static_cast<double>(st.e_nodes));
  r.add(w, "t_nodes", static_cast<double>(st.t_nodes));
  r.add(w, "nodes", static_cast<double>(st.nodes));
  r.add(w, "height", static_cast<double>(st.height));
  r.add(w, "construction_ms", construction_ms);
  std::cerr << label(w) << st.nodes << " nodes, height " << st.height << ", " << cli::fixed(construction_ms, 1)
            << " ms\n";
}

// Equation 8.1: rebuilding the KVD, or the BSP, at K instants of the span
// [start, end] instead of the kinetic run's updates. One rebuild's cost is
// the median over instants evenly spaced inside the span; the KVD's share
// one classifier, whose per-feature polynomials are cached, as the
// simulation's rebuilds do.
template <class K>
void gain_in(const K& k, const Where& w, const scene::Scene& s, const mpq_class& end, double kinetic_ms,
             std::size_t batches, Results& r) {
  const predicates::Classifier<K> c(k, s);
  std::vector<double> kvd_ms, bsp_ms;
  for (int j = 0; j < rebuild_instants; ++j) {
    const mpq_class t = s.start + (end - s.start) * mpq_class(2 * j + 1, 2 * rebuild_instants);
    auto start = std::chrono::steady_clock::now();
    try {
      tree::build(c, instant(k, t));
      kvd_ms.push_back(ms_since(start));
    } catch (const tree::Build_error&) {
      // Rounding put a fragment across a triangle's plane: no tree at this
      // instant in a floating-point kernel, so no cost either.
    }
    start = std::chrono::steady_clock::now();
    bsp::autopartition(s, t);
    bsp_ms.push_back(ms_since(start));
  }
  Where g = w;
  g.figure = "gain";
  r.add(g, "span", mpq_class(end - s.start).get_d());
  r.add(g, "batches", static_cast<double>(batches));
  r.add(g, "kinetic_update_ms", kinetic_ms);
  const double bsp = cli::median(bsp_ms);
  r.add(g, "bsp_rebuild_ms", bsp);
  for (std::size_t samples : sampling_counts)
    r.add(g, "bsp_gain_" + std::to_string(samples) + "_ms", static_cast<double>(samples) * bsp - kinetic_ms);
  std::cerr << label(g) << "kinetic " << cli::fixed(kinetic_ms, 1) << " ms, BSP rebuild " << cli::fixed(bsp, 2)
            << " ms";
  if (!kvd_ms.empty()) {
    const double kvd = cli::median(kvd_ms);
    r.add(g, "kvd_rebuild_ms", kvd);
    for (std::size_t samples : sampling_counts)
      r.add(g, "kvd_gain_" + std::to_string(samples) + "_ms", static_cast<double>(samples) * kvd - kinetic_ms);
    std::cerr << ", KVD rebuild " << cli::fixed(kvd, 2) << " ms";
  }
  std::cerr << "\n";
}

// The certificates in force at the start, by the thesis's groups; returns
// their number.
template <class Time>
double record_certificates(const Where& w, const kinetic::Simulation<Time>& sim, Results& r) {
  using kinetic::Certificate_type;
  const auto count = [&](Certificate_type t) {
    return static_cast<double>(sim.initial_certificates[static_cast<std::size_t>(t)]);
  };
  double total = 0;
  for (std::size_t n : sim.initial_certificates) total += static_cast<double>(n);
  r.add(w, "pp_certificates", count(Certificate_type::VV) + count(Certificate_type::IV) + count(Certificate_type::II));
  r.add(w, "ve_certificates", count(Certificate_type::VE));
  r.add(w, "vt_certificates", count(Certificate_type::VT) + count(Certificate_type::TT));
  r.add(w, "et_certificates", count(Certificate_type::ET));
  r.add(w, "certificates", total);
  return total;
}

template <class K>
auto run(const K& k, const scene::Scene& s, std::size_t events) {
  kinetic::Options o;
  o.max_events = events;
  o.validate = kinetic::Validation::none;
  return kinetic::simulate(k, s, o);
}

template <class K>
void simulation_in(const K& k, const Where& w, const scene::Scene& s, std::size_t events, bool gain, Results& r) {
  const auto sim = run(k, s, events);
  // Figure 8.5 is the certificates of the all-moving scenes at the start.
  Where certificates = w;
  if (w.figure == "8.6") certificates.figure = "8.5";
  const double total = record_certificates(certificates, sim, r);

  const cli::Update_costs u = cli::update_costs(sim);
  const double n = static_cast<double>(sim.batches.size());
  r.add(w, "events", static_cast<double>(sim.failures));
  r.add(w, "batches", n);
  r.add(w, "simultaneous_batches", static_cast<double>(sim.simultaneous_batches));
  r.add(w, "time_reached", k.to_double(sim.time_reached));
  if (sim.limit) r.add(w, "time_limit", sim.limit->get_d());
  r.add(w, std::string("stopped_by_") + cli::stop_name(sim.stopped), 1);
  r.add(w, "recovery_detected", static_cast<double>(sim.recovery.detected()));
  r.add(w, "construction_ms", 1000 * sim.construction_seconds);
  r.add(w, "total_update_ms", u.total);
  r.add(w, "average_update_ms", u.average);
  r.add(w, "max_update_ms", u.max);
  r.add(w, "stddev_update_ms", u.stddev);
  r.add(w, "average_certificate_ms", u.certificate_average);
  r.add(w, "tree_share", u.tree_share);
  r.add(w, "certificate_share", u.certificate_share);
  std::cerr << label(w) << total << " certificates at the start, " << sim.failures << " events in " << n
            << " batches, average update " << cli::fixed(u.average, 2) << " ms\n";
  if (gain) gain_in(k, w, s, span_end(sim.time_reached), u.total, sim.batches.size(), r);
}

}  // namespace

void construction(const Where& w, const scene::Scene& s, Results& r) {
  cli::with_kernel("bench thesis", w.kernel, [&](const auto& k) {
    construction_in(k, w, s, r);
    return 0;
  });
}

void simulation(const Where& w, const scene::Scene& s, std::size_t events, bool gain, Results& r) {
  cli::with_kernel("bench thesis", w.kernel, [&](const auto& k) {
    simulation_in(k, w, s, events, gain, r);
    return 0;
  });
}

void certificates(const Where& w, const scene::Scene& s, Results& r) {
  cli::with_kernel("bench thesis", w.kernel, [&](const auto& k) {
    std::cerr << label(w) << record_certificates(w, run(k, s, 0), r) << " certificates at the start\n";
    return 0;
  });
}

void bsp_construction(const Where& w, const scene::Scene& s, Results& r) {
  std::vector<double> ms;
  std::size_t fragments = 0;
  for (int i = 0; i < repetitions; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const bsp::Tree t = bsp::autopartition(s, s.start);
    ms.push_back(ms_since(start));
    fragments = t.fragments();
  }
  r.add(w, "bsp_construction_ms", cli::median(ms));
  r.add(w, "bsp_fragments", static_cast<double>(fragments));
  std::cerr << label(w) << "BSP " << fragments << " fragments, " << cli::fixed(cli::median(ms), 2) << " ms\n";
}

void culling(const Where& w, const scene::Scene& s, Results& r) {
  // As kvd order --cull: the viewpoint becomes the decomposition point z.
  scene::Scene seen = s;
  seen.z = {{scene::QPoly(viewpoint[0]), scene::QPoly(viewpoint[1]), scene::QPoly(viewpoint[2]), scene::QPoly(1)}};
  const Exact_kernel k;
  const predicates::Classifier<Exact_kernel> c(k, seen);
  const tree::Kvd_tree t = cli::build_tree("bench thesis", s.name, c, Exact_time(seen.start));
  const query::Culling culled = query::back_to_front_culled(c, t, seen.start);
  r.add(w, "triangle_nodes_culled", static_cast<double>(culled.triangle_nodes_culled));
  r.add(w, "triangle_nodes_total", static_cast<double>(culled.triangle_nodes_total));
  r.add(w, "tree_nodes_culled", static_cast<double>(culled.tree_nodes_culled));
  r.add(w, "tree_nodes_total", static_cast<double>(culled.tree_nodes_total));
  std::cerr << label(w) << culled.triangle_nodes_culled << " of " << culled.triangle_nodes_total
            << " triangle nodes culled\n";
}

void degrees(const Where& w, const scene::Scene& s, Results& r) {
  const Exact_kernel k;
  const predicates::Classifier<Exact_kernel> c(k, s);
  const Exact_time start(s.start);
  const tree::Kvd_tree t = cli::build_tree("bench thesis", s.name, c, start);
  std::map<int, std::size_t> histogram;
  std::size_t polynomials = 0;
  const auto certificates = kinetic::reduced_certificates(c, t, start);
  for (const auto& cert : certificates)
    for (const auto& p : cert.polys) {
      ++histogram[p.degree()];
      ++polynomials;
    }
  // proofs/degree-bounds.md, table 3, the reduced set's largest row (II):
  // D with rigid translations and fixed directions (section 4), 8D + dx + 3dz
  // in general.
  const auto degree_of = [](const scene::Motion_point& p) {
    int d = 0;
    for (int i = 0; i < 4; ++i) d = std::max(d, p[i].degree());
    return d;
  };
  bool translations = s.x[3].degree() < 0 && s.z[3].degree() < 0 && degree_of(s.x) == 0 && degree_of(s.z) == 0;
  for (const scene::Object& o : s.objects)
    translations = translations && (o.motion.kind == scene::Motion::Kind::none ||
                                    o.motion.kind == scene::Motion::Kind::translation);
  const int d = s.max_motion_degree(), dx = degree_of(s.x), dz = degree_of(s.z);
  r.add(w, "certificates", static_cast<double>(certificates.size()));
  r.add(w, "polynomials", static_cast<double>(polynomials));
  for (const auto& [degree, n] : histogram) r.add(w, "degree_" + std::to_string(degree), static_cast<double>(n));
  r.add(w, "D", d);
  r.add(w, "dx", dx);
  r.add(w, "dz", dz);
  r.add(w, "translations", translations);
  r.add(w, "bound", translations ? d : 8 * d + dx + 3 * dz);
  std::cerr << label(w) << polynomials << " certificate polynomials, largest degree "
            << (histogram.empty() ? 0 : histogram.rbegin()->first) << "\n";
}

}  // namespace kvd::bench::thesis_suite
