#include "kvd/detail/kinetic/collision.hpp"

#include <algorithm>

namespace kvd::kinetic {

using SP = symbolic::Symbolic_plane;
using SV = symbolic::Symbolic_vertex;

mpq_class simplest_rational(const mpq_class& lo, const mpq_class& hi) {
  if (lo <= 0 && hi >= 0) return 0;
  if (hi < 0) return -simplest_rational(-hi, -lo);
  // 0 < lo <= hi: an integer inside is the answer; otherwise lo and hi share
  // their integer part n and the answer is n + 1 / (simplest in the
  // reciprocals of the fractional parts).
  mpz_class n;
  mpz_cdiv_q(n.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());
  if (n <= hi) return mpq_class(n);
  n -= 1;
  mpq_class r = n + 1 / simplest_rational(1 / (hi - n), 1 / (lo - n));
  r.canonicalize();
  return r;
}

mpq_class reversal_time(const Exact_time& a, const Exact_time& c) {
  for (;;) {
    const mpq_class g = c.lower() - a.upper();
    if (g > 0 && 64 * (c.upper() - c.lower()) <= g) return simplest_rational(c.lower() - g / 16, c.lower() - g / 64);
    a.refine();
    c.refine();
  }
}

Touch touch(const scene::Scene& s, const std::vector<SV>& vertices, const std::vector<SP>& planes) {
  if (planes.front().kind == SP::Kind::T) return {vertices.front(), planes.front().id};
  return {vertices.front(), s.edge_triangles[planes.at(1).id].front()};
}

std::size_t object_of(const scene::Scene& s, const SV& v) {
  switch (v.kind) {
    case SV::Kind::endpoint: return s.vertex_object[v.ids[0]];
    case SV::Kind::intersection:
    case SV::Kind::thread: return s.edge_object[v.ids[0]];
    case SV::Kind::internal_intersection:
    case SV::Kind::internal_thread: return s.triangle_object[v.ids[2]];
    case SV::Kind::axis: return s.triangle_object[v.ids[0]];
    case SV::Kind::plumb: return s.triangle_object[v.ids[1]];
  }
  return s.vertex_object[v.ids[0]];
}

namespace {
std::vector<std::size_t> pair(std::size_t a, std::size_t b) {
  if (a == b) return {a};
  return a < b ? std::vector<std::size_t>{a, b} : std::vector<std::size_t>{b, a};
}
}  // namespace

std::vector<std::size_t> contact_objects(const scene::Scene& s, const Touch& touch) {
  return pair(object_of(s, touch.vertex), s.triangle_object[touch.triangle]);
}

std::vector<std::size_t> contact_objects(const scene::Scene& s, const tree::Contact& c) {
  return pair(symbolic::object_of(s, c.site), s.triangle_object[c.triangle]);
}

}  // namespace kvd::kinetic
