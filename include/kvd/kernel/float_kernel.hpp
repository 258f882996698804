// The floating-point kernels: the thesis's own arithmetic, kept on purpose.
//
// Float_kernel<FT> is the one implementation behind Double_kernel and
// Mpfr_kernel. A value whose magnitude is at most epsilon counts as zero, and
// two instants closer than epsilon are equal (the thesis's epsilon, absolute).
// These kernels never fall back to exact arithmetic: they are what the exact
// kernel is compared against.
#pragma once

#include <optional>
#include <string>

#include "kvd/kernel/mpfr_number.hpp"
#include "kvd/kernel/poly.hpp"

namespace kvd {

template <class FT_>
class Float_kernel {
public:
  using FT = FT_;
  using Poly = kvd::Poly<FT>;
  using Time = FT;

  explicit Float_kernel(FT epsilon) : epsilon_(std::move(epsilon)) {}
  const FT& epsilon() const { return epsilon_; }

  int sign(const FT& x) const;
  Time time(const FT& x) const { return x; }
  // Equal when |a - b| <= epsilon.
  int compare(const Time& a, const Time& b) const { return sign(a - b); }
  int sign_at(const Poly& p, const Time& t) const { return sign(p(t)); }
  // The sign of the first derivative whose value at t is not within epsilon
  // of zero; 0 when all are.
  int sign_after(const Poly& p, const Time& t) const;
  // The smallest computed sign-changing root r of p with compare(r, after) > 0.
  std::optional<Time> next_root(const Poly& p, const Time& after) const;

  double to_double(const Time& t) const;
  // 17 significant digits.
  std::string to_string(const Time& t) const;

private:
  FT epsilon_;
};

class Double_kernel : public Float_kernel<double> {
public:
  static constexpr const char* name = "double";
  static constexpr double default_epsilon = 1e-9;
  explicit Double_kernel(double epsilon = default_epsilon) : Float_kernel<double>(epsilon) {}
};

class Mpfr_kernel : public Float_kernel<Mpfr_number> {
public:
  static constexpr const char* name = "mpfr";
  static constexpr unsigned default_bits = 128;
  // Sets this thread's MPFR precision to `bits` (see Mpfr_number). The default
  // epsilon is 2^(-bits/2), the rule that gives about 1e-8 at double's 53 bits.
  explicit Mpfr_kernel(unsigned bits = default_bits);
  Mpfr_kernel(unsigned bits, const Mpfr_number& epsilon);
  unsigned bits() const { return bits_; }
  // The precision that the text BITS of a kernel name "mpfr:BITS" names:
  // digits only (no sign, space or suffix), 2 to 65536; none otherwise.
  static std::optional<unsigned> bits_named(const std::string& text) {
    if (text.empty() || text.size() > 5 || text.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    const unsigned long bits = std::stoul(text);
    if (bits < 2 || bits > 65536) return std::nullopt;
    return static_cast<unsigned>(bits);
  }

private:
  unsigned bits_;
};

extern template class Poly<Mpfr_number>;
extern template class Float_kernel<double>;
extern template class Float_kernel<Mpfr_number>;

}  // namespace kvd
