// Median microseconds per next_root call: the exact kernel's own isolator
// against CGAL's Algebraic_kernel_d_1 used directly (solve, then take the
// first sign-changing root after the query), on the same random polynomials.
//
//   kvd_bench_next_root [--degrees 2,4,8] [--count N] [--bits 64,200] [--seed S]
//                       [--family dense|cluster] [--json] [--out DIR]
//
// With --out, also writes DIR/next-root.md and DIR/next-root.csv.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
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
  std::vector<unsigned long> bits{64};
  unsigned long seed = 1;
  std::string family = "dense";
  bool json = false;
  std::string out;  // empty: no files
};

[[noreturn]] void usage(int status) {
  (status == 0 ? std::cout : std::cerr)
      << "usage: kvd_bench_next_root [--degrees 2,4,8] [--count N] [--bits 64,200] [--seed S]\n"
         "                           [--family dense|cluster] [--json] [--out DIR]\n"
         "Median microseconds per next_root(p, 0): exact kernel vs CGAL's isolator,\n"
         "on N random polynomials (default 300) per degree and coefficient size.\n"
         "--out DIR also writes DIR/next-root.md and DIR/next-root.csv.\n"
         "Exit status: 0, 1 if the two disagree on a root, 2 on bad input.\n";
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
    else if (a == "--bits") {
      o.bits.clear();
      std::stringstream ss(value());
      for (std::string b; std::getline(ss, b, ',');) o.bits.push_back(static_cast<unsigned long>(parse_number(b.c_str())));
    } else if (a == "--out") o.out = value();
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

struct Row {
  unsigned long bits;
  int degree;
  double ours_us, cgal_us;
  int disagreements;
};

Row measure(const Options& o, const kvd::Exact_kernel& k, unsigned long bits, int d) {
  const mpq_class after(0);
  const kvd::Exact_time at(after);
  kvd::testing::Random_polys rnd(o.seed * 1000 + static_cast<unsigned long>(d));
  std::vector<double> ours, cgal;
  int disagreements = 0;
  for (int i = 0; i < o.count; ++i) {
    const kvd::zpoly::ZPoly z = o.family == "dense" ? rnd.dense(d, bits) : rnd.cluster(d, 110, 0, bits);
    const kvd::Poly<mpq_class> p = kvd::zpoly::to_poly(z);
    std::optional<kvd::Exact_time> r;
    ours.push_back(micros([&] { r = k.next_root(p, at); }));
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
  return {bits, d, median(ours), median(cgal), disagreements};
}

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

std::string markdown(const Options& o, const std::vector<Row>& rows) {
  std::string out = "## next_root against CGAL\n\n`kvd_bench_next_root` (" + o.family + " family, " +
                    std::to_string(o.count) +
                    " random polynomials per row, seed " + std::to_string(o.seed) +
                    "): `next_root(p, 0)` by the exact kernel, against CGAL's `Algebraic_kernel_d_1` solving p and "
                    "taking its first sign-changing root after 0. Median microseconds per call, one run; every "
                    "root is checked to agree.\n\n"
                    "| coefficients | degree | exact kernel µs | CGAL µs | CGAL / ours | disagreements |\n"
                    "|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows)
    out += "| " + std::to_string(r.bits) + " bits | " + std::to_string(r.degree) + " | " + fixed(r.ours_us, 2) +
           " | " + fixed(r.cgal_us, 1) + " | " + fixed(r.cgal_us / r.ours_us, 1) + " | " +
           std::to_string(r.disagreements) + " |\n";
  return out;
}

std::string csv(const std::vector<Row>& rows) {
  std::string out = "bits,degree,exact_kernel_us,cgal_us,speedup,disagreements\n";
  for (const Row& r : rows)
    out += std::to_string(r.bits) + "," + std::to_string(r.degree) + "," + fixed(r.ours_us, 3) + "," +
           fixed(r.cgal_us, 3) + "," + fixed(r.cgal_us / r.ours_us, 2) + "," + std::to_string(r.disagreements) + "\n";
  return out;
}

void write(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  if (!f) {
    std::cerr << "kvd_bench_next_root: cannot write " << path << "\n";
    std::exit(2);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const kvd::Exact_kernel k;
  std::vector<Row> rows;
  for (unsigned long bits : o.bits)
    for (int d : o.degrees) {
      rows.push_back(measure(o, k, bits, d));
      const Row& r = rows.back();
      if (r.disagreements)
        std::cerr << "kvd_bench_next_root: " << r.disagreements << " disagreements at degree " << d << ", " << bits
                  << " bits\n";
    }
  if (o.json) {
    nlohmann::ordered_json results = nlohmann::ordered_json::array();
    for (const Row& r : rows)
      results.push_back({{"bits", r.bits}, {"degree", r.degree}, {"median_us_exact_kernel", r.ours_us},
                         {"median_us_cgal", r.cgal_us}, {"disagreements", r.disagreements}});
    std::cout << nlohmann::ordered_json{{"family", o.family}, {"count", o.count}, {"results", results}}.dump() << "\n";
  } else {
    std::cout << markdown(o, rows);
  }
  if (!o.out.empty()) {
    write(o.out + "/next-root.md", markdown(o, rows));
    write(o.out + "/next-root.csv", csv(rows));
  }
  for (const Row& r : rows)
    if (r.disagreements) return 1;
  return 0;
}
