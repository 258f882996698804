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
      out.push_back({type_of(v, p), symbolic::to_string(v) + " " + symbolic::to_string(p), holder.at(p), std::move(polys), {v}, {p}});
  }
  return out;
}

#define KVD_INSTANTIATE_FULL_CERTIFICATES(K)                                                                  \
  template std::vector<Certificate<K::Poly>> full_certificates<K>(const predicates::Classifier<K>&, \
                                                                  const tree::Kvd_tree&, tree::Evaluated, const K::Time&);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_FULL_CERTIFICATES)

}  // namespace kvd::kinetic
