#include "kvd/predicates/classify.hpp"

#include "kvd/geometry/plucker.hpp"
#include "kvd/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/symbolic/incidence.hpp"

namespace kvd::predicates {

template <class K>
Classifier<K>::Classifier(const K& k, const scene::Scene& s)
    : k_(&k), motion_(symbolic::motion_geometry<typename K::FT>(s)), z_euclidean_(!s.z[3].is_zero()) {}

template <class K>
int Classifier<K>::lex_sign(const typename K::Poly& f, const typename K::Time& t) const {
  const int s = k_->sign_at(f, t);
  return s != 0 ? s : k_->sign_after(f, t);
}

template <class K>
const Plane4<typename K::Poly>& Classifier<K>::plane_poly(const symbolic::Symbolic_plane& p) const {
  auto it = planes_.find(p);
  if (it == planes_.end()) it = planes_.emplace(p, motion_.plane(p)).first;
  return it->second;
}

template <class K>
const Point4<typename K::Poly>& Classifier<K>::point_poly(const symbolic::Symbolic_vertex& v) const {
  auto it = points_.find(v);
  if (it == points_.end()) it = points_.emplace(v, motion_.point(v)).first;
  return it->second;
}

template <class K>
const symbolic::Scene_geometry<Poly<typename K::Poly>>& Classifier<K>::perturbed() const {
  if (!perturbed_) perturbed_.emplace(symbolic::perturbed(motion_));
  return *perturbed_;
}

template <class K>
Point4<typename K::Poly> Classifier<K>::position(const symbolic::Symbolic_vertex& given) const {
  const symbolic::Symbolic_vertex v = symbolic::canonical(motion_.scene(), given);
  Point4<typename K::Poly> x = point_poly(v);
  if (!(x[0].is_zero() && x[1].is_zero() && x[2].is_zero() && x[3].is_zero())) return x;
  const auto xe = perturbed().point(v);
  int order = -1;  // the lowest order of ε with a non-zero coordinate
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j <= xe[k].degree(); ++j)
      if (!xe[k][j].is_zero() && (order < 0 || j < order)) order = j;
  for (int k = 0; k < 4; ++k) x[k] = order < 0 ? typename K::Poly() : xe[k][order];
  return x;
}

template <class K>
std::vector<typename K::Poly> Classifier<K>::certificate(const symbolic::Symbolic_vertex& given,
                                                         const symbolic::Symbolic_plane& p) const {
  const symbolic::Symbolic_vertex v = symbolic::canonical(motion_.scene(), given);
  std::vector<typename K::Poly> out;
  if (symbolic::on_by_construction(motion_.scene(), v, p, z_euclidean_)) return out;
  const bool derived = v.kind != symbolic::Symbolic_vertex::Kind::endpoint;
  auto keep = [&](const typename K::Poly& q) {
    if (q.degree() >= 1) out.push_back(q);
  };
  const Point4<typename K::Poly>& x = point_poly(v);
  const typename K::Poly f = dot(plane_poly(p), x);
  if (!f.is_zero()) {
    keep(f);
    if (derived) keep(x[3]);
    return out;
  }
  const auto xe = perturbed().point(v);
  const auto fe = dot(perturbed().plane(p), xe);
  auto first_nonzero = [](const Poly<typename K::Poly>& e) {
    for (const auto& c : e.coefficients())
      if (!c.is_zero()) return c;
    return typename K::Poly();
  };
  keep(first_nonzero(fe));
  if (derived) keep(first_nonzero(xe[3]));
  return out;
}

template <class K>
Classification Classifier<K>::classify(const symbolic::Symbolic_vertex& given, const symbolic::Symbolic_plane& p,
                                       const typename K::Time& t) const {
  const symbolic::Symbolic_vertex v = symbolic::canonical(motion_.scene(), given);
  if (symbolic::on_by_construction(motion_.scene(), v, p, z_euclidean_)) return {0, Rule::incidence};
  const bool derived = v.kind != symbolic::Symbolic_vertex::Kind::endpoint;
  const Point4<typename K::Poly>& x = point_poly(v);
  const typename K::Poly f = dot(plane_poly(p), x);
  if (!f.is_zero()) {
    // A direction (W identically zero) counts as W > 0, as in kvd::side.
    const int w = derived && !x[3].is_zero() ? lex_sign(x[3], t) : 1;
    const int s = k_->sign_at(f, t);
    if (s != 0) return {s * w, Rule::value};
    return {k_->sign_after(f, t) * w, Rule::after};
  }
  // Rule 4: expand in ε; coefficients are polynomials in t.
  const auto xe = perturbed().point(v);
  const auto fe = dot(perturbed().plane(p), xe);
  int w = 1;
  if (derived)
    for (const auto& c : xe[3].coefficients())
      if (!c.is_zero()) {
        w = lex_sign(c, t);
        break;
      }
  for (const auto& c : fe.coefficients())
    if (!c.is_zero()) return {lex_sign(c, t) * w, Rule::perturbation};
  if (unresolved_++ < 16) unresolved_cases_.emplace_back(v, p);
  return {0, Rule::unresolved};
}

#define KVD_INSTANTIATE_CLASSIFIER(K) template class Classifier<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_CLASSIFIER)

}  // namespace kvd::predicates
