// The thesis's reduced certificate set (thesis 6.4), node by node. "Walls" are found by proximity (thesis 6.4): for a point, the
// nearest ancestor P-cuts along y (the intersection cuts stored at ancestor
// E-nodes included, thesis 6.4.2), the nearest ancestor E-cuts along x and
// the nearest ancestor T-cuts along z, on each side. Distances are compared
// exactly, just after the current time; a tie keeps every tied wall, so the
// set only grows in degenerate cases. Formulas: proofs/certificates.md.
#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "kvd/geometry/plucker.hpp"
#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/detail/kinetic/reduced_upkeep.hpp"
#include "kvd/detail/kinetic/positive.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "wall_filter.hpp"

namespace kvd::kinetic {

namespace {
using SV = symbolic::Symbolic_vertex;
using SP = symbolic::Symbolic_plane;
using SE = symbolic::Symbolic_edge;
}  // namespace

std::vector<SV> intersection_walls(const tree::Node& n) {
  std::vector<SV> out;
  if (const auto* e = std::get_if<tree::Edge_fragment>(&n.fragment))
    for (const SV& end : {e->a, e->b})
      if (end.kind == SV::Kind::intersection) out.push_back(end);
  std::ranges::sort(out);  // the fragment's ends in either order
  return out;
}

bool names_walls(const tree::Node& n) {
  if (std::holds_alternative<SV>(n.fragment)) return true;
  const auto* e = std::get_if<tree::Edge_fragment>(&n.fragment);
  return e && (e->a.kind == SV::Kind::intersection || e->b.kind == SV::Kind::intersection);
}

template <class K>
class Reduced_maker<K>::Impl {
  using P = typename K::Poly;
  using FT = typename K::FT;

public:
  Impl(const predicates::Classifier<K>& c, const tree::Kvd_tree& t, const typename K::Time& now)
      : c_(c), t_(t), now_(now), s_(c.motion().scene()), y_{{P(), P(FT(1)), P(), P()}} {
    if constexpr (std::is_same_v<K, Exact_kernel>)
      if (c.kernel().filtered()) filter_ = std::make_unique<Wall_filter>(now);
  }

  std::vector<Certificate<P>> of_node(int n, const std::vector<int>& path, std::vector<Certificate<P>>* held,
                                      const std::set<Certificate_key>& failed) {
    at_ = n;
    path_ = &path;
    held_ = held;
    failed_ = &failed;
    visit(n);
    std::vector<Certificate<P>> out;
    for (auto& [key, cert] : made_) out.push_back(std::move(cert));
    made_.clear();
    return out;
  }

private:
  // What a wall certifies: the side of `vertex` against `plane`, or, for II,
  // against the P-cut through the intersection point `other`.
  struct Spec {
    Certificate_type type;
    SV vertex;
    std::optional<SP> plane;
    SV other{};
  };
  // A P-wall (along y) is a cut of the tree or an intersection cut through
  // an intersection point; E- and T-walls are neither.
  struct Wall {
    const Plane4<P>* plane;  // the classifier's: it outlives the walk
    Spec spec;
    std::optional<SP> cut{};
    std::optional<SV> through{};
  };

  const tree::Node& node(int i) const { return t_.nodes[static_cast<std::size_t>(i)]; }

  void visit(int n) {
    const tree::Node& nd = node(n);
    if (const auto* v = std::get_if<SV>(&nd.fragment)) return point_node(*v);
    if (const auto* e = std::get_if<tree::Edge_fragment>(&nd.fragment)) return edge_node(nd.cut, *e);
    triangle_node(nd.cut, std::get<tree::Triangle_fragment>(nd.fragment));
  }

  // Thesis 6.4.1: a vertex against the six walls of its cell.
  void point_node(const SV& v) {
    const SP pv{SP::Kind::P, v.ids[0]};
    std::vector<Wall> p_walls, e_walls, t_walls;
    for (int a : *path_) {
      const SP& cut = node(a).cut;
      switch (cut.kind) {
        case SP::Kind::P: p_walls.push_back({&c_.plane_poly(cut), {Certificate_type::VV, v, cut}, cut}); break;
        case SP::Kind::E:
          e_walls.push_back({&c_.plane_poly(cut), {Certificate_type::VE, v, cut}});
          for (const SV& s : intersection_walls(node(a))) p_walls.push_back({&p_cut(s), {Certificate_type::IV, s, pv}, {}, s});
          break;
        case SP::Kind::T: t_walls.push_back({&c_.plane_poly(cut), {Certificate_type::VT, v, cut}}); break;
      }
    }
    const Point4<P>& at = c_.point_poly(v);
    nearest(at, y_, p_walls, end_of_walk(y_, p_pencil()));
    nearest(at, c_.motion().x(), e_walls, end_of_walk(c_.motion().x(), finite(c_.motion().z())));
    nearest(at, c_.motion().z(), t_walls, end_of_walk(c_.motion().z(), false));
  }

  // Thesis 6.4.2 and 6.4.3: an edge fragment's endpoints. An intersection
  // endpoint is an (implicit) intersection cut with its own P-walls.
  void edge_node(const SP& cut, const tree::Edge_fragment& f) {
    for (const SV& end : {f.a, f.b}) {
      if (end.kind == SV::Kind::thread) emit({Certificate_type::VE, SV::endpoint(end.ids[1]), cut});
      if (end.kind != SV::Kind::intersection) continue;
      edge_edge(end);
      std::vector<Wall> p_walls;
      for (int a : *path_) {
        const SP& above = node(a).cut;
        if (above.kind == SP::Kind::P) p_walls.push_back({&c_.plane_poly(above), {Certificate_type::IV, end, above}, above});
        if (above.kind != SP::Kind::E) continue;
        for (const SV& s : intersection_walls(node(a)))
          p_walls.push_back({&p_cut(s), {Certificate_type::II, end, std::nullopt, s}, {}, s});
      }
      const SV& other = end == f.a ? f.b : f.a;
      if (other.kind == SV::Kind::intersection)
        p_walls.push_back({&p_cut(other), {Certificate_type::II, end, std::nullopt, other}, {}, other});
      nearest(c_.position(end), y_, p_walls, end_of_walk(y_, p_pencil()));
    }
  }

  // Thesis 6.4.4: a P-cut through a vertex that is not the triangle's own
  // crosses the fragment; the triangle must not reach that vertex.
  void triangle_node(const SP& cut, const tree::Triangle_fragment& f) {
    const auto& own = s_.triangles[cut.id];
    for (const SE& side : f.sides)
      if (side.kind == SE::Kind::pt && side.a != own[0] && side.a != own[1] && side.a != own[2])
        emit({Certificate_type::TT, SV::endpoint(side.a), cut});
  }

  // ET (thesis 6.3.5): edge e meets the E-plane of e_j in s; the certificate
  // fails when the lines of e and e_j meet, det(a, b, c, d) = 0. Formula 6.7
  // carries the extra factor of the plane of e_j against z, which is left
  // out (proofs/certificates.md). Identically coplanar edges fall back to the
  // classification of s against a triangle of e_j, which the perturbation
  // decides.
  void edge_edge(const SV& s) {
    const SP against{SP::Kind::E, s.ids[1]};
    const Certificate_key key{Certificate_type::ET, s, against};
    if (known(key)) return;
    const P& lines = c_.edge_lines(s.ids[0], s.ids[1]);
    add(key, lines.is_zero() ? c_.value(s, SP{SP::Kind::T, s_.edge_triangles[s.ids[1]].front()}) : lines, {s},
        {SP{SP::Kind::E, s.ids[0]}, against});
  }

  // Which stage decided a sign of the walk (the exact kernel's statistics).
  void count(bool by_filter) const {
    if constexpr (std::is_same_v<K, Exact_kernel>) {
      if (!filter_) return;
      Stage_counts& n = c_.kernel().statistics().walk;
      ++(by_filter ? n.filter : n.exact);
    }
  }

  // The implicit P-cut through an intersection point: x ∨ z ∨ s, as SP(V).
  const Plane4<P>& p_cut(const SV& s) const { return c_.p_plane_through(s); }

  // Where the walk along v + μ d leaves space (the walk's end), if anywhere:
  // at μ = ∞ when d is a direction, at μ = -v_W / d_W when d is a point; or
  // never, when the walls form a pencil about a finite line or point (the
  // P-cuts about L = x ∨ z, the E-cuts about a Euclidean z): the walk then
  // goes round the pencil through μ = ∞, as the cell's walls do.
  enum class End { at_infinity, at_point, none };
  End end_of_walk(const Point4<P>& d, bool pencil) const {
    if (pencil) return End::none;
    return d[3].is_zero() ? End::at_infinity : End::at_point;
  }
  bool finite(const Point4<P>& p) const { return !p[3].is_zero(); }
  bool p_pencil() const { return finite(c_.motion().x()) || finite(c_.motion().z()); }

  // The walls nearest to point v on each side of it, walking along the line
  // v + μ d: μ = -dot(H, v) / dot(H, d) with v scaled to W >= 0. Walls
  // parallel to d are never met; a wall through v is kept (its certificate
  // is empty when v lies on it by construction). The walk upwards goes from
  // μ = 0 to +∞ and on from -∞ (unless it ended), the walk downwards from 0
  // to -∞ and on from +∞, each until its end (proofs/certificates.md, 3).
  void nearest(const Point4<P>& v, const Point4<P>& d, const std::vector<Wall>& walls, End end) {
    const int wv = v[3].is_zero() ? 1 : c_.lex_sign(v[3], now_);
    if constexpr (std::is_same_v<K, Exact_kernel>) {
      if (filter_) {
        filter_->set_point(v, wv < 0);
        filter_->set_direction(d);
      }
    }
    struct Hit {
      const Wall* wall;
      std::optional<P> f{}, g{};  // made only when the filter's bounds cannot decide
      std::optional<Bounds> f_bounds{}, g_bounds{};
      int sg = 0, side = 0;  // side: the sign of μ
    };
    const auto f_of = [&](Hit& h) -> const P& {
      if (!h.f) h.f = wv < 0 ? P(-dot(*h.wall->plane, v)) : dot(*h.wall->plane, v);
      return *h.f;
    };
    const auto g_of = [&](Hit& h) -> const P& {
      if (!h.g) h.g = dot(*h.wall->plane, d);
      return *h.g;
    };
    // The sign of the bounds, or else of the polynomial just after now.
    const auto sign = [&](const std::optional<Bounds>& b, auto&& exact) {
      const int s = Wall_filter::sign(b);
      count(s != 0);
      return s != 0 ? s : c_.lex_sign(exact(), now_);
    };
    // sign(μ_a - μ_b) = sign(f_b g_a - f_a g_b) · sign(g_a g_b)
    auto compare = [&](Hit& a, Hit& b) {
      int s = Wall_filter::cross_sign(a.f_bounds, a.g_bounds, b.f_bounds, b.g_bounds);
      count(s != 0);
      if (s == 0) s = c_.lex_sign(f_of(b) * g_of(a) - f_of(a) * g_of(b), now_);
      return s * a.sg * b.sg;
    };
    std::vector<Hit> hits;
    for (const Wall& w : walls) {
      Hit h{&w};
      if constexpr (std::is_same_v<K, Exact_kernel>) {
        if (filter_) {
          h.f_bounds = filter_->at_point(*w.plane);
          h.g_bounds = filter_->at_direction(*w.plane);
        }
      }
      const int sg = sign(h.g_bounds, [&]() -> const P& { return g_of(h); });
      if (sg == 0) continue;
      const int side = -sign(h.f_bounds, [&]() -> const P& { return f_of(h); }) * sg;
      if (side == 0) {
        emit(w.spec);
        continue;
      }
      h.sg = sg;
      h.side = side;
      hits.push_back(std::move(h));
    }
    // The end of the walk at a point, as a hit: μ_end = -v_W / d_W.
    std::optional<Hit> stop;
    if (end == End::at_point) {
      const int sg = c_.lex_sign(d[3], now_);
      stop = Hit{nullptr, wv < 0 ? P(-v[3]) : v[3], d[3], std::nullopt, std::nullopt, sg,
                 -c_.lex_sign(v[3], now_) * wv * sg};
    }
    for (int dir : {-1, +1}) {
      // The walk in direction dir meets first the walls on its own side
      // (nearest first), then, past ±∞, those on the other side (farthest
      // first); a wall beyond the walk's end is never met.
      auto reached = [&](Hit& h) {
        if (end == End::none) return true;
        if (end == End::at_infinity || h.side != stop->side) return h.side == dir;
        return compare(h, *stop) * dir < 0;  // before the end, on the end's own leg
      };
      for (int leg : {dir, -dir}) {
        std::vector<Hit*> best;
        for (Hit& h : hits) {
          if (h.side != leg || !reached(h)) continue;
          const int cmp = best.empty() ? -dir : compare(h, *best.front());
          if (cmp * dir < 0) best.assign(1, &h);
          else if (cmp == 0) best.push_back(&h);
        }
        for (const Hit* h : best) {
          emit(h->wall->spec);
          for (Hit& other : hits)
            if (other.side == leg && reached(other) && std::ranges::find(best, &other) == best.end())
              keep_order(*h->wall, *other.wall);
        }
        if (!best.empty()) break;
      }
    }
  }

  // The nearest P-wall stays the nearest while the farther ones on its side
  // stay behind it. Between two cuts of the tree that is the tree's own
  // invariant (the deeper cut on one side of a point is the nearer: its
  // vertex is certified in its own cell); an intersection cut is no node of
  // the tree, so its order against the nearest wall is certified here, as
  // an IV or II certificate between the two walls' points
  // (proofs/certificates.md, section 3).
  void keep_order(const Wall& nearest, const Wall& farther) {
    if (nearest.through && farther.through) {
      const auto [a, b] = std::minmax(*nearest.through, *farther.through);
      emit({Certificate_type::II, a, std::nullopt, b});
    } else if (nearest.through && farther.cut) {
      emit({Certificate_type::IV, *nearest.through, *farther.cut});
    } else if (nearest.cut && farther.through) {
      emit({Certificate_type::IV, *farther.through, *nearest.cut});
    }
  }

  // A key met again at the node is made once (the first wins, and would be
  // the same certificate).
  void emit(const Spec& s) {
    if (s.plane) {
      const Certificate_key key{s.type, s.vertex, *s.plane};
      if (!known(key)) add(key, c_.value(s.vertex, *s.plane), {s.vertex}, {*s.plane});
      return;
    }
    // II (thesis 6.3.7): two intersection points at the same height.
    const Certificate_key key{s.type, s.vertex, s.other};
    if (!known(key)) add(key, dot(p_cut(s.other), c_.position(s.vertex)), {s.vertex, s.other}, {});
  }

  // Whether the node has its certificate under `key` already: made, or now
  // moved from `held_`, where a key that did not fail is taken.
  bool known(const Certificate_key& key) {
    if (made_.contains(key)) return true;
    if (!held_) return false;
    const auto it = std::ranges::lower_bound(*held_, key, {}, &Certificate<P>::key);
    if (it == held_->end() || it->key != key || it->polys.empty() || failed_->contains(key)) return false;
    made_.emplace(key, std::move(*it));
    return true;
  }

  void add(const Certificate_key& key, const P& q, std::vector<SV> vertices, std::vector<SP> planes) {
    Certificate<P> cert{key, at_, {}, std::move(vertices), std::move(planes)};
    append_positive(c_, q, now_, cert.polys);
    if (!cert.polys.empty()) made_.emplace(key, std::move(cert));
  }

  const predicates::Classifier<K>& c_;
  const tree::Kvd_tree& t_;
  const typename K::Time& now_;
  const scene::Scene& s_;
  const Point4<P> y_;  // the direction along which P-cuts are stacked
  const std::vector<int>* path_ = nullptr;  // the ancestors of the node visited, root first
  int at_ = -1;                             // the node visited
  std::vector<Certificate<P>>* held_ = nullptr;         // certificates to take rather than make
  const std::set<Certificate_key>* failed_ = nullptr;  // keys never taken from held_
  std::map<Certificate_key, Certificate<P>> made_;
  std::unique_ptr<Wall_filter> filter_;  // the exact kernel's, when its filter is on
};

template <class K>
Reduced_maker<K>::Reduced_maker(const predicates::Classifier<K>& c, const tree::Kvd_tree& t, const typename K::Time& now)
    : impl_(std::make_unique<Impl>(c, t, now)) {}
template <class K>
Reduced_maker<K>::~Reduced_maker() = default;
template <class K>
std::vector<Certificate<typename K::Poly>> Reduced_maker<K>::of_node(int n, const std::vector<int>& path,
                                                                   std::vector<Certificate<typename K::Poly>>* held,
                                                                   const std::set<Certificate_key>& failed) {
  return impl_->of_node(n, path, held, failed);
}

#define KVD_INSTANTIATE_REDUCED_MAKER(K) template class Reduced_maker<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_REDUCED_MAKER)

}  // namespace kvd::kinetic
