#include "kvd/detail/scene/exact_number.hpp"

namespace kvd::scene {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Consumes [0-9]+ at s[i...]; returns the digits, empty if none.
std::string_view digits(std::string_view s, std::size_t& i) {
  const std::size_t b = i;
  while (i < s.size() && is_digit(s[i])) ++i;
  return s.substr(b, i - b);
}

mpz_class integer_of(std::string_view d) { return mpz_class(std::string(d), 10); }

}  // namespace

std::optional<mpq_class> parse_exact_number(std::string_view s, std::string& why) {
  std::size_t i = 0;
  const bool negative = i < s.size() && s[i] == '-';
  if (negative) ++i;
  const std::string_view whole = digits(s, i);
  if (whole.empty()) {
    why = "not a number (expected an integer, a decimal or a fraction such as \"-7/2\")";
    return std::nullopt;
  }
  // Digits beyond the cap are refused before any arithmetic: a number's size,
  // like its exponent, bounds the cost of everything computed from it.
  const auto too_long = [&](std::size_t n) {
    if (n <= max_digits) return false;
    why = "a number of more than " + std::to_string(max_digits) + " digits";
    return true;
  };
  if (too_long(whole.size())) return std::nullopt;
  mpq_class value;
  if (i < s.size() && s[i] == '/') {
    ++i;
    const std::string_view den = digits(s, i);
    if (den.empty() || i != s.size()) {
      why = "not a number (a fraction is -?[0-9]+/[0-9]+)";
      return std::nullopt;
    }
    if (too_long(whole.size() + den.size())) return std::nullopt;
    const mpz_class d = integer_of(den);
    if (d == 0) {
      why = "a fraction with a zero denominator";
      return std::nullopt;
    }
    value = mpq_class(integer_of(whole), d);
    value.canonicalize();
  } else {
    std::string mantissa(whole);
    long fraction_digits = 0;
    if (i < s.size() && s[i] == '.') {
      ++i;
      const std::string_view frac = digits(s, i);
      if (frac.empty()) {
        why = "not a number (a decimal point must be followed by digits)";
        return std::nullopt;
      }
      if (too_long(whole.size() + frac.size())) return std::nullopt;
      mantissa += frac;
      fraction_digits = static_cast<long>(frac.size());
    }
    long exponent = 0;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
      ++i;
      const bool exp_negative = i < s.size() && s[i] == '-';
      if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
      const std::string_view e = digits(s, i);
      if (e.empty()) {
        why = "not a number (an exponent needs digits)";
        return std::nullopt;
      }
      // Compare digit strings first: the exponent text may be arbitrarily long.
      std::string_view trimmed = e.substr(std::min(e.find_first_not_of('0'), e.size()));
      if (trimmed.size() > 6 || (exponent = std::stol(std::string(trimmed.empty() ? "0" : trimmed))) > max_exponent) {
        why = "exponent of magnitude above " + std::to_string(max_exponent);
        return std::nullopt;
      }
      if (exp_negative) exponent = -exponent;
    }
    if (i != s.size()) {
      why = "not a number (unexpected '" + std::string(1, s[i]) + "')";
      return std::nullopt;
    }
    const long shift = exponent - fraction_digits;
    mpz_class ten_power;
    mpz_ui_pow_ui(ten_power.get_mpz_t(), 10, static_cast<unsigned long>(shift < 0 ? -shift : shift));
    value = shift >= 0 ? mpq_class(integer_of(mantissa) * ten_power) : mpq_class(integer_of(mantissa), ten_power);
    value.canonicalize();
  }
  if (negative) value = -value;
  return value;
}

std::string exact_text(const mpq_class& q) { return q.get_str(); }

}  // namespace kvd::scene
