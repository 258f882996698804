#include "cgal_roots.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Polynomial_type_generator.h>

#include <utility>

namespace kvd::oracle {

namespace {
using AK = CGAL::Algebraic_kernel_d_1<CGAL::Gmpz>;
using Polynomial_1 = AK::Polynomial_1;
using Algebraic_real_1 = AK::Algebraic_real_1;
using Bound = AK::Bound;

CGAL::Gmpz to_cgal(const mpz_class& z) { return CGAL::Gmpz(z.get_mpz_t()); }
Bound to_cgal(const mpq_class& q) { return Bound(to_cgal(q.get_num()), to_cgal(q.get_den())); }

Polynomial_1 to_cgal(const std::vector<mpz_class>& c) {
  std::vector<CGAL::Gmpz> v;
  for (const auto& x : c) v.push_back(to_cgal(x));
  return Polynomial_1(v.begin(), v.end());
}
}  // namespace

struct Cgal_roots::Impl {
  AK kernel;
  std::vector<std::pair<Algebraic_real_1, int>> roots;
};

Cgal_roots::Cgal_roots(const std::vector<mpz_class>& coefficients) : impl_(std::make_unique<Impl>()) {
  impl_->kernel.solve_1_object()(to_cgal(coefficients), std::back_inserter(impl_->roots));
}
Cgal_roots::~Cgal_roots() = default;
Cgal_roots::Cgal_roots(Cgal_roots&&) noexcept = default;
Cgal_roots& Cgal_roots::operator=(Cgal_roots&&) noexcept = default;

std::size_t Cgal_roots::size() const { return impl_->roots.size(); }
int Cgal_roots::multiplicity(std::size_t i) const { return impl_->roots.at(i).second; }

int Cgal_roots::compare(std::size_t i, const mpq_class& r) const {
  return static_cast<int>(impl_->kernel.compare_1_object()(impl_->roots.at(i).first, to_cgal(r)));
}

int Cgal_roots::compare(std::size_t i, const std::vector<mpz_class>& q, const mpq_class& lo,
                        const mpq_class& hi) const {
  const Algebraic_real_1 x = impl_->kernel.construct_algebraic_real_1_object()(to_cgal(q), to_cgal(lo), to_cgal(hi));
  return static_cast<int>(impl_->kernel.compare_1_object()(impl_->roots.at(i).first, x));
}

int Cgal_roots::sign_at(std::size_t i, const std::vector<mpz_class>& f) const {
  return static_cast<int>(impl_->kernel.sign_at_1_object()(to_cgal(f), impl_->roots.at(i).first));
}

std::optional<std::size_t> Cgal_roots::next_sign_change_after(const mpq_class& r) const {
  const Bound b = to_cgal(r);
  for (std::size_t i = 0; i < impl_->roots.size(); ++i)
    if (impl_->roots[i].second % 2 == 1 && impl_->kernel.compare_1_object()(impl_->roots[i].first, b) == CGAL::LARGER)
      return i;
  return std::nullopt;
}

std::optional<std::size_t> Cgal_roots::next_sign_change_after_root(std::size_t j) const {
  for (std::size_t i = j + 1; i < impl_->roots.size(); ++i)
    if (impl_->roots[i].second % 2 == 1) return i;
  return std::nullopt;
}

double Cgal_roots::to_double(std::size_t i) const { return CGAL::to_double(impl_->roots.at(i).first); }

}  // namespace kvd::oracle
