// kvd bench cost: what exactness costs against double (issue-level targets:
// at most 1.5x for the build and per event), how often the exact kernel's
// interval filter decides, and the time of next_root on the certificate
// polynomials a simulation makes (asked after a rational instant: the
// algebraic-instant paths are not timed). Generated uniform-scale scenes,
// all moving linearly, seed 1; the runs of a size interleaved, repeated,
// medians. Writes cost.csv, cost.md and, with gnuplot, cost.svg.
#include "cost.hpp"

#include <chrono>
#include <iostream>
#include <set>

#include "bench.hpp"
#include "cli.hpp"
#include "gnuplot.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kernel/float_kernel.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/tree/build.hpp"
#include "report.hpp"
#include "sweep.hpp"

namespace kvd::bench {

namespace {

using namespace cost_suite;

const char* const cost_help =
    "usage: kvd bench cost [--sizes N,N,...] [--events N] [--repeats N] [--out DIR]\n"
    "\n"
    "The price of exactness: for each size, the scene of kvd generate\n"
    "uniform-scale --triangles N --seed 1 (all moving linearly), with\n"
    "  the build          of the KVD at the start: exact, exact without the\n"
    "                     interval filter (--no-filter), and double\n"
    "  the simulation     of the first N certificate failures (default 200),\n"
    "                     reduced set, no validation: the update time per\n"
    "                     failure as kvd simulate reports it (tree,\n"
    "                     certificates, queue and the record of the tree;\n"
    "                     taking failures off the queue and collision\n"
    "                     responses are not timed), exact and double\n"
    "  the filter         how often each stage of the exact kernel decided,\n"
    "                     in one exact build, and in one exact simulation\n"
    "                     with its first build and certificates\n"
    "  next_root          on every distinct certificate polynomial that\n"
    "                     simulation put in force, asked at the upper end of\n"
    "                     the instant it was made: microseconds per call\n"
    "The runs of a size are interleaved and repeated (--repeats, default 3);\n"
    "times are medians. Writes DIR/cost.csv, DIR/cost.md (also to stdout) and,\n"
    "with gnuplot on the PATH, DIR/cost.svg (the exact / double ratios against\n"
    "N); progress goes to stderr, one line per size and repetition.\n"
    "\n"
    "  --sizes    numbers of triangles (default 25,50,100,200,400,800)\n"
    "  --events   certificate failures per simulation (default 200)\n"
    "  --repeats  repetitions of each size's runs, 1 to 100 (default 3)\n"
    "  --out      the output directory (default bench-out), created if needed\n"
    "\n"
    "Exit status: 0 on success, 2 on bad input.\n";

// The build at the start in ms, and the tree's node count.
template <class K>
std::pair<double, std::size_t> build(const K& k, const scene::Scene& s) {
  const auto start = std::chrono::steady_clock::now();
  const predicates::Classifier<K> c(k, s);
  const tree::Kvd_tree t = tree::build(c, k.time(from_rational<typename K::FT>(s.start)));
  return {ms_since(start), t.statistics().nodes};
}

kinetic::Options options(const Config& c) {
  kinetic::Options o;
  o.max_events = c.events;
  o.validate = kinetic::Validation::none;
  return o;
}

// The whole update time per certificate failure, ms.
template <class K>
double per_event(const K& k, const scene::Scene& s, const Config& c) {
  const auto sim = kinetic::simulate(k, s, options(c));
  return sim.failures ? cli::update_costs(sim).total / static_cast<double>(sim.failures) : 0;
}

struct Query {
  Exact_kernel::Poly p;
  Exact_time after;
};

// Every distinct certificate polynomial put in force, with the rational
// upper end of the instant it was made.
class Collector : public kinetic::Observer<Exact_kernel> {
public:
  std::vector<Query> queries;
  void in_force(const Exact_time& now, const std::vector<kinetic::Certificate<Exact_kernel::Poly>>& certs) override {
    for (const auto& cert : certs)
      for (const auto& p : cert.polys)
        if (seen_.insert(p.coefficients()).second) queries.push_back({p, Exact_time(now.upper())});
  }
  void batch(const kinetic::Batch<Exact_time>&, bool) override {}

private:
  std::set<std::vector<mpq_class>> seen_;
};

// Microseconds per next_root call over all the queries, looped for at
// least 50 ms.
double next_root_us(const std::vector<Query>& queries) {
  if (queries.empty()) return 0;
  const Exact_kernel k;
  std::size_t calls = 0;
  const auto start = std::chrono::steady_clock::now();
  double ms = 0;
  while (ms < 50) {
    for (const Query& q : queries) static_cast<void>(k.next_root(q.p, q.after));
    calls += queries.size();
    ms = ms_since(start);
  }
  return 1000 * ms / static_cast<double>(calls);
}

Size measure(std::size_t n, const Config& c) {
  std::cerr << "kvd bench cost: generating " << n << " triangles\n";
  const scene::Scene s = generated("cost", "uniform-scale", n, 1, 1);
  Size size;
  size.triangles = n;
  // Untimed: the filter's statistics and the certificate polynomials.
  {
    const Exact_kernel k;
    size.nodes = build(k, s).second;
    size.build_stages = k.statistics();
  }
  std::vector<Query> queries;
  {
    const Exact_kernel k;
    Collector collector;
    const auto sim = kinetic::simulate(k, s, options(c), &collector);
    size.simulate_stages = k.statistics();
    size.events = sim.failures;
    size.batches = sim.batches.size();
    queries = std::move(collector.queries);
  }
  size.polynomials = queries.size();
  for (const Query& q : queries) {
    size.linear_polynomials += q.p.degree() == 1;
    size.max_degree = std::max(size.max_degree, q.p.degree());
  }
  std::vector<double> exact, unfiltered, dbl, event_exact, event_double, roots;
  for (int r = 0; r < c.repeats; ++r) {
    exact.push_back(build(Exact_kernel(), s).first);
    unfiltered.push_back(build(Exact_kernel(false), s).first);
    if (size.double_failure.empty()) {
      try {
        dbl.push_back(build(Double_kernel(), s).first);
        event_double.push_back(per_event(Double_kernel(), s, c));
      } catch (const tree::Build_error& e) {
        size.double_failure = e.what();
      }
    }
    event_exact.push_back(per_event(Exact_kernel(), s, c));
    roots.push_back(next_root_us(queries));
    std::cerr << "kvd bench cost: " << n << " triangles, repetition " << r + 1 << " of " << c.repeats
              << ": build exact " << cli::fixed(exact.back(), 1) << " ms, double "
              << (dbl.empty() ? std::string("-") : cli::fixed(dbl.back(), 1)) << " ms; per event exact "
              << cli::fixed(event_exact.back(), 3) << " ms, double "
              << (event_double.empty() ? std::string("-") : cli::fixed(event_double.back(), 3)) << " ms\n";
  }
  size.build_exact = cli::median(exact);
  size.build_unfiltered = cli::median(unfiltered);
  size.event_exact = cli::median(event_exact);
  size.next_root_us = cli::median(roots);
  if (size.double_failure.empty()) {
    size.build_double = cli::median(dbl);
    size.event_double = cli::median(event_double);
  } else {
    std::cerr << "kvd bench cost: " << n << " triangles, double: " << size.double_failure << "\n";
  }
  return size;
}

}  // namespace

int cost(cli::Args& args) {
  Config c;
  while (!args.done()) {
    const std::string& a = args.next();
    if (a == "--help" || a == "-h") {
      std::cout << cost_help;
      return 0;
    }
    if (a == "--sizes") c.sizes = sizes_option("cost", args.value(a));
    else if (a == "--events") c.events = args.unsigned_value(a);
    else if (a == "--repeats") {
      const std::size_t r = args.unsigned_value(a);
      if (r < 1 || r > 100) throw cli::Usage_error("kvd bench cost: --repeats must be between 1 and 100");
      c.repeats = static_cast<int>(r);
    } else if (a == "--out") c.out = args.value(a);
    else args.unknown(a);
  }
  make_out("cost", c.out);

  std::vector<Size> sizes;
  for (std::size_t n : c.sizes) sizes.push_back(measure(n, c));
  cli::write_atomically("bench cost", c.out + "/cost.csv", csv(sizes));
  cli::write_atomically("bench cost", c.out + "/cost-plot.dat", plot_data(sizes));
  const bool plotted = run_gnuplot("cost", c.out + "/cost.gp", gnuplot_script(c), {c.out + "/cost.svg"});
  const std::string md = markdown(c, sizes, plotted);
  cli::write_atomically("bench cost", c.out + "/cost.md", md);
  std::cout << md;
  std::cerr << "kvd bench cost: wrote " << c.out << "/cost.md, " << c.out << "/cost.csv"
            << (plotted ? ", " + c.out + "/cost.svg" : std::string()) << "\n";
  return 0;
}

}  // namespace kvd::bench
