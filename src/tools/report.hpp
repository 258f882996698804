// Number formats and record pieces that several kvd commands print.
#pragma once

#include <gmpxx.h>

#include <string>

#include "kvd/kinetic/simulation.hpp"

namespace kvd::cli {

// 17 significant digits: a double read back exactly.
std::string approx(double d);
// `digits` digits after the point.
std::string fixed(double x, int digits);

// A non-negative rational in scientific notation with three significant
// digits ("1.25e-310": no underflow), and its base-10 logarithm (-inf for 0).
std::string scientific(const mpq_class& q);
double log10_of(const mpq_class& q);

// A floating-point run's recovery counts, as a JSON object and in words.
std::string recovery_json(const kinetic::Recovery& r);
std::string recovery_text(const kinetic::Recovery& r);

}  // namespace kvd::cli
