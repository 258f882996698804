// Google Benchmark micro-benchmarks: the first sign-changing root after the
// instant a certificate was made, for every distinct certificate polynomial
// an exact simulation puts in force, by the exact kernel's isolator and by
// CGAL's Algebraic_kernel_d_1 (solve, then the first root of odd
// multiplicity after the instant). Both are asked at the same rational
// instant: the upper end of the making instant's isolating interval.
//
//   kvd_microbench [--scene FILE] [--events N] [Google Benchmark flags]
//
// Defaults: data/uniform-scale-50.json (run from the repository), 100 events.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "cgal_roots.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/detail/kernel/zpoly.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/scene_io.hpp"

namespace {

struct Query {
  kvd::Poly<mpq_class> p;
  kvd::zpoly::ZPoly z;
  mpq_class after;
  kvd::Exact_time at;  // `after` as the kernel's time, made once outside the timed loop
};

// Every distinct certificate polynomial put in force, with the instant it was made.
class Collector : public kvd::kinetic::Observer<kvd::Exact_kernel> {
public:
  std::vector<Query> queries;
  void in_force(const kvd::Exact_time& now, const std::vector<kvd::kinetic::Certificate<kvd::Exact_kernel::Poly>>& certs) override {
    const mpq_class after = now.upper();
    for (const auto& c : certs)
      for (const auto& p : c.polys)
        if (seen_.insert(p.coefficients()).second) queries.push_back({p, kvd::zpoly::to_zpoly(p), after, kvd::Exact_time(after)});
  }
  void batch(const kvd::kinetic::Batch<kvd::Exact_time>&, bool) override {}

private:
  std::set<std::vector<mpq_class>> seen_;
};

std::vector<Query>& queries() {
  static std::vector<Query> q;
  return q;
}

void ours(benchmark::State& state) {
  const kvd::Exact_kernel k;
  for (auto _ : state)
    for (const Query& q : queries()) benchmark::DoNotOptimize(k.next_root(q.p, q.at));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(queries().size()));
}

void cgal(benchmark::State& state) {
  for (auto _ : state)
    for (const Query& q : queries()) {
      const kvd::oracle::Cgal_roots roots(q.z);
      benchmark::DoNotOptimize(roots.next_sign_change_after(q.after));
    }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(queries().size()));
}

BENCHMARK(ours)->Name("next_root/certificate_polynomials/exact_kernel")->Unit(benchmark::kMillisecond);
BENCHMARK(cgal)->Name("next_root/certificate_polynomials/cgal_algebraic_kernel_d_1")->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  std::string scene = "data/uniform-scale-50.json";
  std::size_t events = 100;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--scene") && i + 1 < argc) scene = argv[++i];
    else if (!std::strcmp(argv[i], "--events") && i + 1 < argc) events = std::strtoul(argv[++i], nullptr, 10);
    else rest.push_back(argv[i]);
  }
  int rest_count = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_count, rest.data());
  if (benchmark::ReportUnrecognizedArguments(rest_count, rest.data())) return 2;
  try {
    kvd::kinetic::Options o;
    o.max_events = events;
    o.validate = kvd::kinetic::Validation::none;
    Collector collector;
    kvd::kinetic::simulate(kvd::Exact_kernel(), kvd::scene::load_scene(scene), o, &collector);
    queries() = std::move(collector.queries);
  } catch (const std::exception& e) {
    std::cerr << "kvd_microbench: " << scene << ": " << e.what() << "\n";
    return 2;
  }
  std::cerr << "kvd_microbench: " << queries().size() << " distinct certificate polynomials from " << scene << "\n";
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
