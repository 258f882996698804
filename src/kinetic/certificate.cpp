#include "kvd/kinetic/certificate.hpp"

#include <algorithm>
#include <map>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/detail/kinetic/positive.hpp"

namespace kvd::kinetic {

const char* to_string(Certificate_type t) {
  switch (t) {
    case Certificate_type::VV: return "VV";
    case Certificate_type::VE: return "VE";
    case Certificate_type::VT: return "VT";
    case Certificate_type::ET: return "ET";
    case Certificate_type::IV: return "IV";
    case Certificate_type::II: return "II";
    case Certificate_type::TT: return "TT";
    case Certificate_type::other: return "other";
  }
  return "?";
}

bool may_collide(Certificate_type t) {
  return t == Certificate_type::VT || t == Certificate_type::ET || t == Certificate_type::TT;
}

std::string features(const Certificate_key& k) {
  const auto* plane = std::get_if<symbolic::Symbolic_plane>(&k.against);
  if (k.type == Certificate_type::ET && plane && plane->kind == symbolic::Symbolic_plane::Kind::E)
    return "E(" + std::to_string(k.vertex.ids[0]) + ") E(" + std::to_string(k.vertex.ids[1]) + ")";
  if (plane) return symbolic::to_string(k.vertex) + " " + symbolic::to_string(*plane);
  return symbolic::to_string(k.vertex) + " P(" + symbolic::to_string(std::get<symbolic::Symbolic_vertex>(k.against)) + ")";
}

bool printed_before(const Certificate_key& a, const Certificate_key& b) {
  if (a.type != b.type) return a.type < b.type;
  return features(a) < features(b);
}

namespace {

bool names_object(const scene::Scene& s, const symbolic::Symbolic_vertex& v, std::size_t object) {
  bool named = false;
  symbolic::for_each_feature(
      v, [&](std::size_t i) { named = named || s.vertex_object[i] == object; },
      [&](std::size_t i) { named = named || s.edge_object[i] == object; },
      [&](std::size_t i) { named = named || s.triangle_object[i] == object; });
  return named;
}

bool names_object(const scene::Scene& s, const symbolic::Symbolic_plane& p, std::size_t object) {
  using PK = symbolic::Symbolic_plane::Kind;
  switch (p.kind) {
    case PK::P: return s.vertex_object[p.id] == object;
    case PK::E: return s.edge_object[p.id] == object;
    case PK::T: return s.triangle_object[p.id] == object;
  }
  return true;
}

}  // namespace

bool names_object(const scene::Scene& s, const Certificate_key& k, std::size_t object) {
  return names_object(s, k.vertex, object) ||
         std::visit([&](const auto& against) { return names_object(s, against, object); }, k.against);
}

std::size_t Certificate_key_hash::operator()(const Certificate_key& k) const noexcept {
  const symbolic::Symbolic_hash h;
  const std::size_t against = std::visit([&](const auto& a) { return h(a); }, k.against);
  return h.mix(h.mix(h.mix(static_cast<std::size_t>(k.type), h(k.vertex)), k.against.index()), against);
}

namespace {

// The thesis's name for a classification, where it has one.
Certificate_type type_of(const symbolic::Symbolic_vertex& v, const symbolic::Symbolic_plane& p) {
  using VK = symbolic::Symbolic_vertex::Kind;
  using PK = symbolic::Symbolic_plane::Kind;
  if (v.kind == VK::endpoint)
    return p.kind == PK::P ? Certificate_type::VV : p.kind == PK::E ? Certificate_type::VE : Certificate_type::VT;
  if (v.kind == VK::intersection && p.kind == PK::P) return Certificate_type::IV;
  if (v.kind == VK::intersection && p.kind == PK::T) return Certificate_type::ET;
  return Certificate_type::other;
}

}  // namespace

template <class K>
std::vector<Certificate<typename K::Poly>> full_certificates(const predicates::Classifier<K>& c,
                                                             const tree::Kvd_tree& t, tree::Evaluated evaluated,
                                                             const typename K::Time& now) {
  std::map<symbolic::Symbolic_plane, int> holder;
  for (std::size_t i = 0; i < t.nodes.size(); ++i) holder.try_emplace(t.nodes[i].cut, static_cast<int>(i));
  // A classification evaluated for several fragments is one certificate.
  std::sort(evaluated.begin(), evaluated.end());
  evaluated.erase(std::unique(evaluated.begin(), evaluated.end()), evaluated.end());
  std::vector<Certificate<typename K::Poly>> out;
  for (const auto& [v, p] : evaluated) {
    auto polys = positive(c, c.certificate(v, p), now);
    if (!polys.empty())
      out.push_back({{type_of(v, p), v, p}, holder.at(p), std::move(polys), {v}, {p}});
  }
  return out;
}

#define KVD_INSTANTIATE_FULL_CERTIFICATES(K)                                                                  \
  template std::vector<Certificate<K::Poly>> full_certificates<K>(const predicates::Classifier<K>&, \
                                                                  const tree::Kvd_tree&, tree::Evaluated, const K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_FULL_CERTIFICATES)

}  // namespace kvd::kinetic
