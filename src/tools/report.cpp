#include "report.hpp"

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

std::string recovery_json(const kinetic::Recovery& r) {
  return "{\"failed_builds\": " + std::to_string(r.failed_builds) + ", \"refires\": " +
         std::to_string(r.refires) + ", \"stale_trees\": " + std::to_string(r.stale_trees) +
         ", \"rebuilds\": " + std::to_string(r.rebuilds) + ", \"unrepaired\": " + std::to_string(r.unrepaired) + "}";
}

std::string recovery_text(const kinetic::Recovery& r) {
  return std::to_string(r.failed_builds) + " failed builds, " + std::to_string(r.refires) + " repeated batches, " +
         std::to_string(r.stale_trees) + " stale trees; " +
         std::to_string(r.rebuilds) + " rebuilds later, " + std::to_string(r.unrepaired) + " left unrepaired";
}

}  // namespace kvd::cli
