// The parts of the scene writers that the formats share (kvd-scene/1 and
// kvd-segments/1): exact numbers as strings, polynomials as arrays (a
// constant as a plain number string), and the project's pretty printing.
#pragma once

#include <gmpxx.h>

#include <nlohmann/json.hpp>
#include <string>

#include "kvd/kernel/poly.hpp"

namespace kvd::scene {

using Json_out = nlohmann::ordered_json;

Json_out number_json(const mpq_class& q);
Json_out poly_json(const Poly<mpq_class>& p);
// The document with a newline after it: a value stays on one line when it
// fits in 100 columns, otherwise one member or item a line.
std::string pretty_json(const Json_out& doc);

}  // namespace kvd::scene
