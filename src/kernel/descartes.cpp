#include "kvd/detail/kernel/descartes.hpp"

#include <algorithm>
#include <deque>
#include <memory>
#include <vector>

namespace kvd {

namespace {

using zpoly::ZPoly;

// Descartes' bound for (0, 1): the sign variations of (1+x)^n q(1/(1+x)).
int variations_on_unit(const ZPoly& q, ZPoly& scratch) {
  scratch.assign(q.rbegin(), q.rend());
  zpoly::taylor_shift_one(scratch);
  return zpoly::variations(scratch);
}

// Divides p by the largest power of two dividing every coefficient (same
// roots, same signs), which keeps the bisection's numbers from growing by n
// bits per level.
void remove_common_power_of_two(ZPoly& p) {
  mp_bitcnt_t z = ~mp_bitcnt_t(0);
  for (const auto& c : p)
    if (c != 0) z = std::min(z, mpz_scan1(c.get_mpz_t(), 0));
  if (z == 0 || z == ~mp_bitcnt_t(0)) return;
  for (auto& c : p) mpz_fdiv_q_2exp(c.get_mpz_t(), c.get_mpz_t(), z);
}

// Vincent–Collins–Akritas bisection on the unit interval. A node is the
// dyadic cell (m/2^k, (m+1)/2^k) of (0, 1) with its polynomial
// 2^(kn) Q((m + x)/2^k), whose roots in (0, 1) are Q's roots in the cell; a
// child's polynomial is made from its parent's (x -> x/2, then a Taylor shift
// for the right half) instead of from q. Cells and answers are those of
// bisecting (lo, hi) and applying Descartes' rule to q on each cell.
//
// The buffers live in per-thread workspaces, reused from call to call: a
// query then allocates almost nothing once its depth has been reached before.
// A visitor that isolates again (nested) takes the next workspace.
class Bisection {
  struct Workspace {
    mpz_class m;
    ZPoly scratch;
    std::deque<ZPoly> right;  // the right half's polynomial, per depth (growing keeps references)
  };

public:
  Bisection(const ZPoly& q, const mpq_class& lo, const mpq_class& hi,
            const std::function<bool(const Exact_time&)>& visit)
      : q_(q), lo_(lo), width_(hi - lo), visit_(visit), w_(acquire()) {
    mpz_set_ui(w_.m.get_mpz_t(), 0);
  }
  ~Bisection() { --in_use_; }
  Bisection(const Bisection&) = delete;
  Bisection& operator=(const Bisection&) = delete;

  // Roots in the cell (m/2^k, (m+1)/2^k), m held in the workspace, whose
  // polynomial is `node`; lo_is_root / hi_is_root say whether an end of the
  // cell is itself a root of q, in which case the cell cannot be handed out
  // as an isolating interval (Exact_time wants q non-zero at both ends) and
  // is bisected further: the root inside is strictly inside, so this
  // terminates. Leaves m as it found it.
  bool run(ZPoly& node, unsigned long k, bool lo_is_root, bool hi_is_root) {
    const int v = variations_on_unit(node, w_.scratch);
    if (v == 0) return false;
    if (v == 1 && !lo_is_root && !hi_is_root) return visit_(Exact_time::algebraic(q_, at(0, k), at(1, k)));
    // Left half: 2^n node(x/2).
    const std::size_t n = node.size() - 1;
    for (std::size_t i = 0; i < n; ++i) mpz_mul_2exp(node[i].get_mpz_t(), node[i].get_mpz_t(), n - i);
    remove_common_power_of_two(node);
    if (w_.right.size() <= k) w_.right.resize(k + 1);
    ZPoly& right = w_.right[k];
    right = node;
    zpoly::taylor_shift_one(right);
    const bool mid_is_root = right[0] == 0;  // the right half's value at 0
    mpz_mul_2exp(w_.m.get_mpz_t(), w_.m.get_mpz_t(), 1);
    bool found = run(node, k + 1, lo_is_root, mid_is_root) ||
                 (mid_is_root && visit_(Exact_time(at(1, k + 1))));
    if (!found) {
      mpz_add_ui(w_.m.get_mpz_t(), w_.m.get_mpz_t(), 1);
      found = run(right, k + 1, mid_is_root, hi_is_root);
      mpz_sub_ui(w_.m.get_mpz_t(), w_.m.get_mpz_t(), 1);
    }
    mpz_fdiv_q_2exp(w_.m.get_mpz_t(), w_.m.get_mpz_t(), 1);
    return found;
  }

private:
  static Workspace& acquire() {
    if (pool_.size() <= in_use_) pool_.push_back(std::make_unique<Workspace>());
    return *pool_[in_use_++];
  }

  // lo + width (m + d) / 2^k
  mpq_class at(unsigned long d, unsigned long k) const {
    mpq_class f(w_.m + d);
    mpq_div_2exp(f.get_mpq_t(), f.get_mpq_t(), k);
    return lo_ + width_ * f;
  }

  const ZPoly& q_;
  mpq_class lo_, width_;
  const std::function<bool(const Exact_time&)>& visit_;
  Workspace& w_;
  static thread_local std::vector<std::unique_ptr<Workspace>> pool_;
  static thread_local std::size_t in_use_;
};

thread_local std::vector<std::unique_ptr<Bisection::Workspace>> Bisection::pool_;
thread_local std::size_t Bisection::in_use_ = 0;

}  // namespace

bool isolate_real_roots(const ZPoly& q, const mpq_class& lo, const mpq_class& hi,
                        const std::function<bool(const Exact_time&)>& visit) {
  if (zpoly::degree(q) < 1 || !(lo < hi)) return false;
  // x = lo + (hi - lo) s maps s in (0,1) to (lo,hi); with lo = a/c, hi - lo = b/c:
  const mpz_class c = lo.get_den() * hi.get_den();
  const mpz_class a = lo.get_num() * hi.get_den();
  const mpz_class b = hi.get_num() * lo.get_den() - a;
  ZPoly unit = zpoly::compose_linear(q, a, b, c);  // degree n: its leading coefficient is q_n b^n
  Bisection bisection(q, lo, hi, visit);
  return bisection.run(unit, 0, zpoly::sign_at(q, lo) == 0, zpoly::sign_at(q, hi) == 0);
}

}  // namespace kvd
