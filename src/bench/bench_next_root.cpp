// Median microseconds per next_root call: the exact kernel's own isolator
// against CGAL's Algebraic_kernel_d_1 used directly (solve, then take the
// first sign-changing root after the query), on the same random polynomials.
//
//   kvd_bench_next_root [--degrees 2,4,8] [--count N] [--bits B] [--seed S]
//                       [--family dense|cluster] [--json]
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cgal_roots.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "random_poly.hpp"

namespace {

struct Options {
  std::vector<int> degrees{2, 4, 8};
  int count = 300;
  unsigned long bits = 64;
  unsigned long seed = 1;
  std::string family = "dense";
  bool json = false;
};

[[noreturn]] void usage(int status) {
  (status == 0 ? std::cout : std::cerr)
      << "usage: kvd_bench_next_root [--degrees 2,4,8] [--count N] [--bits B] [--seed S]\n"
         "                           [--family dense|cluster] [--json]\n"
         "Median microseconds per next_root(p, 0): exact kernel vs CGAL's isolator.\n";
  std::exit(status);
}

long parse_number(const char* s) {
  char* end = nullptr;
  const long v = std::strtol(s, &end, 10);
  if (*s == '\0' || *end != '\0' || v <= 0) {
    std::cerr << "kvd_bench_next_root: expected a positive integer, got '" << s << "'\n";
    std::exit(2);
  }
  return v;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage(2);
      return argv[++i];
    };
    if (a == "--help" || a == "-h") usage(0);
    else if (a == "--json") o.json = true;
    else if (a == "--count") o.count = static_cast<int>(parse_number(value()));
    else if (a == "--bits") o.bits = static_cast<unsigned long>(parse_number(value()));
    else if (a == "--seed") o.seed = static_cast<unsigned long>(parse_number(value()));
    else if (a == "--family") {
      o.family = value();
      if (o.family != "dense" && o.family != "cluster") usage(2);
    } else if (a == "--degrees") {
      o.degrees.clear();
      std::stringstream ss(value());
      for (std::string d; std::getline(ss, d, ',');) o.degrees.push_back(static_cast<int>(parse_number(d.c_str())));
    } else usage(2);
  }
  return o;
}

template <class F>
double micros(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const kvd::Exact_kernel k;
  const mpq_class after(0);
  nlohmann::ordered_json results = nlohmann::ordered_json::array();
  if (!o.json) std::cout << "degree  ours_us  cgal_us  cgal/ours  disagreements\n";
  for (std::size_t di = 0; di < o.degrees.size(); ++di) {
    const int d = o.degrees[di];
    kvd::testing::Random_polys rnd(o.seed * 1000 + static_cast<unsigned long>(d));
    std::vector<double> ours, cgal;
    int disagreements = 0;
    for (int i = 0; i < o.count; ++i) {
      const kvd::zpoly::ZPoly z = o.family == "dense" ? rnd.dense(d, o.bits) : rnd.cluster(d, 110, 0, o.bits);
      const kvd::Poly<mpq_class> p = kvd::zpoly::to_poly(z);
      std::optional<kvd::Exact_time> r;
      ours.push_back(micros([&] { r = k.next_root(p, kvd::Exact_time(after)); }));
      std::optional<kvd::oracle::Cgal_roots> roots;
      std::optional<std::size_t> idx;
      cgal.push_back(micros([&] {
        roots.emplace(z);
        idx = roots->next_sign_change_after(after);
      }));
      // Not timed: both must have found the same root.
      const bool same = r && idx ? (r->is_rational() ? roots->compare(*idx, r->rational())
                                                     : roots->compare(*idx, r->polynomial(), r->lower(), r->upper())) == 0
                                 : (!r && !idx);
      disagreements += !same;
    }
    const double mo = median(ours), mc = median(cgal);
    if (o.json)
      results.push_back(
          {{"degree", d}, {"median_us_exact_kernel", mo}, {"median_us_cgal", mc}, {"disagreements", disagreements}});
    else
      std::printf("%6d %8.1f %8.1f %10.2f %14d\n", d, mo, mc, mc / mo, disagreements);
    if (disagreements) std::cerr << "kvd_bench_next_root: " << disagreements << " disagreements at degree " << d << "\n";
  }
  if (o.json)
    std::cout << nlohmann::ordered_json{{"family", o.family}, {"bits", o.bits}, {"count", o.count},
                                        {"results", results}}.dump()
              << "\n";
  return 0;
}
