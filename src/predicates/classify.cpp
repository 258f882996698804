#include "kvd/predicates/classify.hpp"

#include <array>
#include <type_traits>

#include "classify_filter.hpp"
#include "kvd/geometry/plucker.hpp"
#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/symbolic/incidence.hpp"

namespace kvd::predicates {

namespace {

// The coefficients of the lowest order of ε in which some coordinate of a
// point or plane does not vanish identically (all zero if none does).
template <class Coefficient, class Vanishes>
std::array<Coefficient, 4> lowest_order(const std::array<Poly<Coefficient>, 4>& e, const Vanishes& vanishes) {
  int order = -1;
  for (const auto& x : e)
    for (int j = 0; j <= x.degree(); ++j)
      if (!vanishes(x[j]) && (order < 0 || j < order)) order = j;
  std::array<Coefficient, 4> out;
  for (std::size_t k = 0; k < 4; ++k) out[k] = order < 0 ? Coefficient() : e[k][order];
  return out;
}

// The coordinates of a point or plane at t, or, where k takes all four for
// zero there, their limit as t' -> t+: the lowest derivative at t that is not
// zero in every coordinate, the lowest-order term of the expansion in t' - t
// times a positive factor (so every side keeps its sign).
template <class K>
std::array<typename K::FT, 4> right_limit(const K& k, std::array<typename K::Poly, 4> c, const typename K::FT& t) {
  for (;;) {
    std::array<typename K::FT, 4> at;
    bool zero = true, constant = true;
    for (std::size_t i = 0; i < 4; ++i) {
      at[i] = c[i](t);
      zero = zero && k.sign(at[i]) == 0;
      constant = constant && c[i].degree() <= 0;
    }
    if (!zero || constant) return at;
    for (auto& x : c) x = x.derivative();
  }
}

}  // namespace

template <class K>
Classifier<K>::Classifier(const K& k, const scene::Scene& s)
    : k_(&k), motion_(symbolic::motion_geometry<typename K::FT>(s)), z_euclidean_(!s.z[3].is_zero()) {
  if constexpr (std::is_same_v<K, Exact_kernel>)
    if (k.filtered()) filter_ = std::make_shared<Classification_filter>(motion_);
}

template <class K>
int Classifier<K>::lex_sign(const typename K::Poly& f, const typename K::Time& t) const {
  const int s = k_->sign_at(f, t);
  return s != 0 ? s : k_->sign_after(f, t);
}

template <class K>
bool Classifier<K>::vanishes(const typename K::Poly& f, int from) const {
  const auto& c = f.coefficients();
  for (std::size_t i = static_cast<std::size_t>(from); i < c.size(); ++i)
    if (k_->sign(c[i]) != 0) return false;
  return true;
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
const typename K::Poly& Classifier<K>::edge_lines(std::size_t e1, std::size_t e2) const {
  auto it = edge_lines_.find({e1, e2});
  if (it == edge_lines_.end()) {
    const auto& a = motion_.scene().edges[e1];
    const auto& b = motion_.scene().edges[e2];
    it = edge_lines_
             .emplace(std::pair{e1, e2}, coplanar(motion_.vertex(a[0]), motion_.vertex(a[1]), motion_.vertex(b[0]),
                                                  motion_.vertex(b[1])))
             .first;
  }
  return it->second;
}

template <class K>
const symbolic::Scene_geometry<Poly<typename K::Poly>>& Classifier<K>::perturbed() const {
  if (!perturbed_) perturbed_.emplace(symbolic::perturbed(motion_));
  return *perturbed_;
}

template <class K>
const Point4<typename K::Poly>& Classifier<K>::position(const symbolic::Symbolic_vertex& v) const {
  auto it = positions_.find(v);
  if (it == positions_.end()) it = positions_.emplace(v, position_of(v)).first;
  return it->second;
}

template <class K>
const Plane4<typename K::Poly>& Classifier<K>::p_plane_through(const symbolic::Symbolic_vertex& v) const {
  auto it = p_planes_.find(v);
  if (it == p_planes_.end()) it = p_planes_.emplace(v, join(join(motion_.x(), motion_.z()), position(v))).first;
  return it->second;
}

template <class K>
Point4<typename K::Poly> Classifier<K>::position_of(const symbolic::Symbolic_vertex& given) const {
  const symbolic::Symbolic_vertex v = symbolic::canonical(motion_.scene(), given);
  Point4<typename K::Poly> x = point_poly(v);
  if (!(vanishes(x[0]) && vanishes(x[1]) && vanishes(x[2]) && vanishes(x[3]))) return x;
  return {lowest_order(perturbed().point(v).c, [this](const typename K::Poly& f) { return vanishes(f); })};
}

template <class K>
Point4<typename K::FT> Classifier<K>::position_after(const symbolic::Symbolic_vertex& v, const typename K::FT& t) const {
  return {right_limit(*k_, position(v).c, t)};
}

template <class K>
Plane4<typename K::FT> Classifier<K>::plane_after(const symbolic::Symbolic_plane& p, const typename K::FT& t) const {
  auto it = site_planes_.find(p);
  if (it == site_planes_.end()) {
    Plane4<typename K::Poly> m = plane_poly(p);
    if (vanishes(m[0]) && vanishes(m[1]) && vanishes(m[2]) && vanishes(m[3]))
      m = {lowest_order(perturbed().plane(p).c, [this](const typename K::Poly& f) { return vanishes(f); })};
    it = site_planes_.emplace(p, std::move(m)).first;
  }
  return {right_limit(*k_, it->second.c, t)};
}

template <class K>
const typename Classifier<K>::Deciding& Classifier<K>::deciding(const symbolic::Symbolic_vertex& v,
                                                                const symbolic::Symbolic_plane& p) const {
  const Pair key{v, p};
  if (const auto* d = deciding_.find(key)) return **d;
  auto d = std::make_unique<Deciding>(decide(v, p));
  return *(deciding_[key] = std::move(d));
}

template <class K>
typename Classifier<K>::Deciding Classifier<K>::decide(const symbolic::Symbolic_vertex& v,
                                                       const symbolic::Symbolic_plane& p) const {
  Deciding d;
  if (symbolic::on_by_construction(motion_.scene(), v, p, z_euclidean_)) {
    d.incident = true;
    return d;
  }
  const bool derived = v.kind != symbolic::Symbolic_vertex::Kind::endpoint;
  const Point4<typename K::Poly>& x = point_poly(v);
  d.value = dot(plane_poly(p), x);
  if (!vanishes(d.value)) {
    if (derived) d.w = x[3];
    return d;
  }
  // Rule 4: expand in ε; coefficients are polynomials in t.
  d.perturbed = true;
  auto first_nonzero = [this](const Poly<typename K::Poly>& e) {
    for (const auto& c : e.coefficients())
      if (!vanishes(c)) return c;
    return typename K::Poly();
  };
  const auto xe = perturbed().point(v);
  d.value = first_nonzero(dot(perturbed().plane(p), xe));
  if (derived) d.w = first_nonzero(xe[3]);
  return d;
}

template <class K>
const std::vector<typename K::Poly>& Classifier<K>::certificate(const symbolic::Symbolic_vertex& given,
                                                                const symbolic::Symbolic_plane& p) const {
  const symbolic::Symbolic_vertex v = symbolic::canonical(motion_.scene(), given);
  auto [it, fresh] = certificates_.try_emplace({v, p});
  if (fresh) {
    const Deciding& d = deciding(v, p);
    for (const auto* q : {&d.value, &d.w})
      if (q->degree() >= 1) it->second.push_back(*q);
  }
  return it->second;
}

template <class K>
Classification Classifier<K>::classify(const symbolic::Symbolic_vertex& given, const symbolic::Symbolic_plane& p,
                                       const typename K::Time& t) const {
  const symbolic::Symbolic_vertex v = symbolic::canonical(motion_.scene(), given);
  if constexpr (std::is_same_v<K, Exact_kernel>) {
    Stage_counts& n = k_->statistics().classify;
    if (filter_ && !symbolic::on_by_construction(motion_.scene(), v, p, z_euclidean_)) {
      if (const int s = filter_->side(v, p, t)) {
        ++n.filter;
        return {s, Rule::value};
      }
    }
    const Classification c = classify_exactly(v, p, t);
    switch (c.rule) {
      case Rule::incidence: break;
      case Rule::value: ++n.exact; break;
      case Rule::after: ++n.after; break;
      case Rule::perturbation:
      case Rule::unresolved: ++n.perturbation; break;
    }
    return c;
  } else {
    return classify_exactly(v, p, t);
  }
}

template <class K>
Classification Classifier<K>::classify_exactly(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p,
                                               const typename K::Time& t) const {
  const Deciding& d = deciding(v, p);
  if (d.incident) return {0, Rule::incidence};
  // A direction (W identically zero) counts as W > 0, as in kvd::side.
  const int w = vanishes(d.w) ? 1 : lex_sign(d.w, t);
  if (d.perturbed) {
    if (!vanishes(d.value)) return {lex_sign(d.value, t) * w, Rule::perturbation};
    if (unresolved_++ < 16) unresolved_cases_.emplace_back(v, p);
    return {0, Rule::unresolved};
  }
  const int s = k_->sign_at(d.value, t);
  if (s != 0) return {s * w, Rule::value};
  return {k_->sign_after(d.value, t) * w, Rule::after};
}

#define KVD_INSTANTIATE_CLASSIFIER(K) template class Classifier<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_CLASSIFIER)

}  // namespace kvd::predicates
