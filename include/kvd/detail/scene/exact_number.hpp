// Exact numbers as the scene format spells them: integer `-?[0-9]+`, decimal
// `-?[0-9]+(\.[0-9]+)?([eE][+-]?[0-9]+)?`, fraction `-?[0-9]+/[0-9]+` with a
// non-zero denominator. Nothing else is a number ("+1", ".5", "NaN", spaces).
#pragma once

#include <gmpxx.h>

#include <optional>
#include <string>
#include <string_view>

namespace kvd::scene {

// Decimal exponents beyond this magnitude are rejected: 1e100000 would be a
// number of a hundred thousand digits.
inline constexpr long max_exponent = 10000;
// A number's digits (numerator and denominator, or integer and fraction
// parts together) are capped alike, at the size 1e10000 spells.
inline constexpr std::size_t max_digits = 10001;

// The exact rational the text denotes, or none with `why` set.
std::optional<mpq_class> parse_exact_number(std::string_view text, std::string& why);

// The canonical text of a rational: "-7/2", "3".
std::string exact_text(const mpq_class& q);

}  // namespace kvd::scene
