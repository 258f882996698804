#include "report.hpp"

#include <mpfr.h>

#include <algorithm>
#include <cstdio>

namespace kvd::cli {

std::string approx(double d) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  return buf;
}

std::string fixed(double x, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

namespace {
// q in MPFR at 64 bits: its exponent range has no underflow for our errors.
struct Wide {
  mpfr_t v;
  explicit Wide(const mpq_class& q) {
    mpfr_init2(v, 64);
    mpfr_set_q(v, q.get_mpq_t(), MPFR_RNDN);
  }
  ~Wide() { mpfr_clear(v); }
};
}  // namespace

std::string scientific(const mpq_class& q, int digits) {
  if (q == 0) return "0";
  Wide w(q);
  char* text = nullptr;
  mpfr_asprintf(&text, ("%." + std::to_string(digits) + "Re").c_str(), w.v);
  std::string out(text);
  mpfr_free_str(text);
  return out;
}

double log10_of(const mpq_class& q) {
  Wide w(q);
  mpfr_log10(w.v, w.v, MPFR_RNDN);
  return mpfr_get_d(w.v, MPFR_RNDN);
}

const char* stop_name(kinetic::Stop s) {
  switch (s) {
    case kinetic::Stop::events: return "events";
    case kinetic::Stop::limit: return "limit";
    case kinetic::Stop::exhausted: return "exhausted";
    case kinetic::Stop::collision: return "collision";
    case kinetic::Stop::stuck: return "stuck";
  }
  return "?";
}

std::string recovery_text(const kinetic::Recovery& r) {
  return std::to_string(r.failed_builds) + " failed builds, " + std::to_string(r.refires) + " repeated batches, " +
         std::to_string(r.stale_trees) + " stale trees; " +
         std::to_string(r.rebuilds) + " trees adopted (" + std::to_string(r.zones_skipped) + " past a rounding zone), " +
         std::to_string(r.unrepaired) + " left unrepaired";
}

}  // namespace kvd::cli
