#include "kvd/detail/kernel/descartes.hpp"

namespace kvd {

namespace {

// Roots in (lo, hi); lo_is_root / hi_is_root say whether an endpoint is itself
// a root of q, in which case the interval cannot be handed out as an isolating
// interval (the invariant of Exact_time wants q non-zero at both ends) and is
// bisected further: the root inside is strictly inside, so this terminates.
bool isolate(const zpoly::ZPoly& q, const mpq_class& lo, const mpq_class& hi, bool lo_is_root,
             bool hi_is_root, const std::function<bool(const Exact_time&)>& visit) {
  const int v = zpoly::descartes_bound(q, lo, hi);
  if (v == 0) return false;
  if (v == 1 && !lo_is_root && !hi_is_root) return visit(Exact_time::algebraic(q, lo, hi));
  const mpq_class mid = (lo + hi) / 2;
  const bool mid_is_root = zpoly::sign_at(q, mid) == 0;
  if (isolate(q, lo, mid, lo_is_root, mid_is_root, visit)) return true;
  if (mid_is_root && visit(Exact_time(mid))) return true;
  return isolate(q, mid, hi, mid_is_root, hi_is_root, visit);
}

}  // namespace

bool isolate_real_roots(const zpoly::ZPoly& q, const mpq_class& lo, const mpq_class& hi,
                        const std::function<bool(const Exact_time&)>& visit) {
  if (zpoly::degree(q) < 1 || !(lo < hi)) return false;
  return isolate(q, lo, hi, zpoly::sign_at(q, lo) == 0, zpoly::sign_at(q, hi) == 0, visit);
}

}  // namespace kvd
