// Number formats and record pieces that several kvd commands print.
#pragma once

#include <string>

#include "kvd/kinetic/simulation.hpp"

namespace kvd::cli {

// 17 significant digits: a double read back exactly.
std::string approx(double d);
// `digits` digits after the point.
std::string fixed(double x, int digits);

// A floating-point run's recovery counts, as a JSON object and in words.
std::string recovery_json(const kinetic::Recovery& r);
std::string recovery_text(const kinetic::Recovery& r);

}  // namespace kvd::cli
