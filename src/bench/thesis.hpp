// kvd bench thesis, private to the suite: thesis.cpp reads the options,
// loads every scene and runs the measurements of thesis_measure.cpp;
// thesis_report.cpp writes them out next to the thesis's own numbers,
// which thesis_values.cpp holds.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "kvd/scene/scene.hpp"

namespace kvd::bench::thesis_suite {

inline const std::vector<std::string> families{"uniform-scale", "uniform-density"};
// K of equation 8.1: rebuilds at K evenly spaced instants of the kinetic run's span.
inline constexpr std::array<std::size_t, 3> sampling_counts{10, 100, 1000};
// Construction times are the median of `repetitions` builds; the rebuild
// cost of equation 8.1 the median over `rebuild_instants` instants.
inline constexpr int repetitions = 3;
inline constexpr int rebuild_instants = 5;

struct Config {
  std::vector<std::size_t> sizes{25, 50, 100};
  std::size_t events = 200;
  // Larger scenes get the construction, certificate, BSP and culling
  // figures only: their simulations and sampled rebuilds take minutes.
  std::size_t simulate_up_to = 200;
  std::vector<std::size_t> simulated_sizes() const {
    std::vector<std::size_t> out;
    for (std::size_t n : sizes)
      if (n <= simulate_up_to) out.push_back(n);
    return out;
  }
  std::vector<std::string> kernels{"exact", "double"};
  std::string data = "data", out = "bench-out";
  // The kernel of the thesis's figures; the others only in the cost of exactness.
  const std::string& reference() const { return kernels.front(); }
};

// What a value measures: a row of thesis.csv without its quantity and value.
// `figure` is the thesis's figure ("8.4" ... "8.9"), or "gain" (equation
// 8.1), "static" (no triangle moving), "degrees" (certificate polynomials).
struct Where {
  std::string figure, family;
  std::size_t size = 0;
  std::string kernel;
};

struct Measurement {
  Where where;
  std::string quantity;
  double value;
};

class Results {
public:
  void add(const Where& w, const std::string& quantity, double value) { rows_.push_back({w, quantity, value}); }
  std::optional<double> get(const Where& w, const std::string& quantity) const {
    for (const Measurement& m : rows_)
      if (m.quantity == quantity && m.where.figure == w.figure && m.where.family == w.family &&
          m.where.size == w.size && m.where.kernel == w.kernel)
        return m.value;
    return std::nullopt;
  }
  const std::vector<Measurement>& all() const { return rows_; }

private:
  std::vector<Measurement> rows_;
};

// Figure 8.4: the KVD at the scene's start in w.kernel; node counts, height
// and construction_ms (classifier and build, the median of three).
void construction(const Where& w, const scene::Scene& s, Results& r);
// Figures 8.5-8.7: kinetic::simulate without validation up to `events`
// certificate failures; with `gain`, also the rebuild costs of equation 8.1
// over the run's span (figure "gain").
void simulation(const Where& w, const scene::Scene& s, std::size_t events, bool gain, Results& r);
// Figure 8.5 alone: the certificates in force at the start.
void certificates(const Where& w, const scene::Scene& s, Results& r);
// Figure 8.8: the baseline auto-partition BSP at the scene's start, the median of three.
void bsp_construction(const Where& w, const scene::Scene& s, Results& r);
// Figure 8.9: occlusion culling from `viewpoint`, exact.
inline constexpr std::array<int, 3> viewpoint{50, -100, 50};
void culling(const Where& w, const scene::Scene& s, Results& r);
// The degree of every polynomial of the reduced certificates at the scene's
// start (exact), and its bound in proofs/degree-bounds.md.
void degrees(const Where& w, const scene::Scene& s, Results& r);

// The thesis's value of `quantity` (its figure, family and size), as it
// prints it; none where it gives none.
std::optional<std::string> thesis_value(const std::string& figure, const std::string& family,
                                        const std::string& quantity, std::size_t size);

std::string csv(const Results& r);
// With `plotted`, thesis.md shows the plots.
std::string markdown(const Config& c, const Results& r, bool plotted);
// The plots' data (thesis-plot.dat) and the gnuplot script writing
// thesis-construction.svg and thesis-update.svg into c.out.
std::string plot_data(const Config& c, const Results& r);
std::string gnuplot_script(const Config& c);

}  // namespace kvd::bench::thesis_suite
