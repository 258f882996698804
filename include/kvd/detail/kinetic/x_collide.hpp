// The collision policy of a run (thesis 7.3.3, detail/kinetic/collision.hpp):
// whether a batch's failures are contacts, and X-collide's response, which
// reverses the motions of the objects meeting.
#pragma once

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kvd/detail/kinetic/builder.hpp"
#include "kvd/detail/kinetic/collision.hpp"
#include "kvd/detail/kinetic/in_force.hpp"
#include "kvd/geometry/plucker.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/predicates/in_triangle.hpp"

namespace kvd::kinetic {

template <class K>
class X_collide {
  using Time = typename K::Time;
  using FT = typename K::FT;

public:
  X_collide(const K& k, Collisions policy) : k_(k), policy_(policy) {}

  // The contacts among the certificates `failing` at t: VT, ET or TT
  // certificates whose vertex lies in the triangle of another object at t
  // (an object's own features lie in its faces' planes by construction),
  // and any certificate whose vertex lands at t in the plane of a vertical
  // triangle of another object named by its plane, where the two objects
  // meet in that plane (vertical_contact). The contacts are named in
  // certificate-key order.
  std::optional<Meeting> contact(const predicates::Classifier<K>& c, const scene::Scene& s, const In_force<K>& in_force,
                                 const std::vector<std::size_t>& failing, const Time& t) const {
    Meeting m;
    std::string features, flat;
    std::map<std::pair<std::size_t, std::size_t>, bool> tested;
    // Named in key order: the queue's order among simultaneous failures is its own.
    std::vector<std::size_t> by_key = failing;
    std::ranges::sort(by_key, [&](std::size_t a, std::size_t b) { return in_force[a].key < in_force[b].key; });
    for (std::size_t id : by_key) {
      const auto& cert = in_force[id];
      std::string* named = &features;
      std::vector<std::size_t> objects;
      if (may_collide(cert.key.type)) {
        const Touch th = touch(s, cert.vertices, cert.planes);
        objects = contact_objects(s, th);
        if (objects.size() < 2 || !predicates::in_closed_triangle(c, th.vertex, th.triangle, t)) objects.clear();
      }
      if (objects.empty()) {
        objects = vertical_contact(c, s, cert.key, t, tested);
        if (objects.empty()) continue;
        named = &flat;
      }
      m.objects.insert(m.objects.end(), objects.begin(), objects.end());
      *named += (named->empty() ? "" : ", ") + std::string(to_string(cert.key.type)) + " " + kinetic::features(cert.key);
    }
    if (m.objects.empty()) return std::nullopt;
    std::ranges::sort(m.objects);
    m.objects.erase(std::unique(m.objects.begin(), m.objects.end()), m.objects.end());
    if (!features.empty()) m.error = "a vertex or an edge reaches a triangle (" + features + ")";
    if (!flat.empty())
      m.error += std::string(m.error.empty() ? "" : "; ") +
                 "a triangle lands in the plane of a vertical triangle and meets it (" + flat + ")";
    return m;
  }

  // X-collide for the meeting `m` found at `collision`, the instant of
  // `batch`, with the tree in force since `now`: reverses the objects'
  // motions in `s` at a time r strictly between `now` and `collision`, where
  // the tree in force is valid, and records the motion change in `sim`. A
  // second contact at the same instant before any batch reverses its other
  // objects at the same r. The step taken; none when the run stops instead:
  // Collisions::stop, an unknown contact, or a contact of objects already
  // reversed for this instant.
  std::optional<Reversal<Time>> respond(scene::Scene& s, Simulation<Time>& sim, const In_force<K>& in_force,
                                        const Time& now, const Time& collision, const Batch<Time>& batch,
                                        const Meeting& m) const {
    if (policy_ != Collisions::reverse) return std::nullopt;
    std::vector<std::size_t> objects = m.objects;
    std::erase_if(objects, [&](std::size_t o) { return !s.is_moving(o); });  // reversing changes nothing
    auto& changes = sim.motion_changes;
    const bool again = !changes.empty() && changes.back().batches_before == sim.batches.size() &&
                       k_.compare(changes.back().collision, collision) == 0;
    if (again)
      std::erase_if(objects, [&](std::size_t o) { return std::ranges::binary_search(changes.back().objects, o); });
    if (objects.empty()) return std::nullopt;
    const std::optional<mpq_class> r = again ? std::optional(changes.back().time) : reversal_time(in_force, now, collision);
    if (!r) return std::nullopt;
    if (again) changes.back().contact += "; " + m.error;
    else changes.push_back({*r, collision, {}, {}, sim.batches.size(), m.error});
    Motion_change<Time>& record = changes.back();
    Reversal<Time> step{*r, batch, objects, {}, m.error};
    for (std::size_t o : objects) {
      s.objects[o].motion = scene::reversed(s.objects[o].motion, *r);
      step.motions.push_back(s.objects[o].motion);
      const auto at = std::ranges::upper_bound(record.objects, o) - record.objects.begin();
      record.objects.insert(record.objects.begin() + at, o);
      record.motions.insert(record.motions.begin() + at, s.objects[o].motion);
    }
    return step;
  }

  // The failures of a batch that may be contacts, in words.
  static std::string colliding(const Batch<Time>& b) {
    std::string out;
    for (const Failure& f : b.failing)
      if (may_collide(f.type)) out += std::string(out.empty() ? "; failing: " : ", ") + to_string(f.type) + " " + kinetic::features(f);
    return out;
  }

private:
  // Case (iv) of proofs/collision_response.md. A failing certificate names
  // a vertex v (on a feature of object A) against a plane that names a
  // triangle (T), an edge (E) or a vertex (P). Of that feature's triangles,
  // take each k of another object B that is vertical for good (its plane
  // contains z at every t) and holds v in its plane at t. (The plane named
  // is k's own when v lands flat: P(w) for a wall in y = const, E(e) for an
  // edge of k, T(k); or another, as when v reaches a corner w of k.) It is
  // a contact when v is a scene vertex lying in the closed triangle k, or
  // when a triangle of A and a triangle of B both lie in k's plane at t and
  // meet there
  // (predicates::coplanar_triangles_meet: a pane may cross a wall with no
  // corner inside it; and the certificate that fails may name another
  // triangle of either object than the two that meet). Signs at t only.
  // `tested` keeps the answer of the second test per (k, A) within a batch.
  // The two objects, or none.
  std::vector<std::size_t> vertical_contact(const predicates::Classifier<K>& c, const scene::Scene& s,
                                            const Certificate_key& key, const Time& t,
                                            std::map<std::pair<std::size_t, std::size_t>, bool>& tested) const {
    using SP = symbolic::Symbolic_plane;
    using SV = symbolic::Symbolic_vertex;
    const auto* plane = std::get_if<SP>(&key.against);
    if (!plane) return {};
    const std::size_t a = object_of(s, key.vertex);
    std::vector<std::size_t> named;  // the triangles of the plane's feature
    const auto at_edge = [&](std::size_t e) {
      named.insert(named.end(), s.edge_triangles[e].begin(), s.edge_triangles[e].end());
    };
    if (plane->kind == SP::Kind::T) named.push_back(plane->id);
    else if (plane->kind == SP::Kind::E) at_edge(plane->id);
    else
      for (std::size_t e : s.vertex_edges[plane->id]) at_edge(e);
    std::ranges::sort(named);
    named.erase(std::unique(named.begin(), named.end()), named.end());
    for (std::size_t tri : named) {
      const std::size_t b = s.triangle_object[tri];
      if (b == a) continue;  // an object's own features
      const auto& in_plane = c.plane_poly(SP{SP::Kind::T, tri});
      // Asked of the polynomial, which costs no sign at t (so a scene
      // without vertical triangles evaluates nothing more).
      if (!c.vanishes(dot(in_plane, c.motion().z()))) continue;  // not vertical for good
      const Point4<typename K::Poly>& v = c.position(key.vertex);
      if (k_.sign_at(v[3], t) == 0) return {};  // at infinity, or made by planes that coincide at t
      if (k_.sign_at(dot(in_plane, v), t) != 0) continue;  // v not in it at t
      bool meet = key.vertex.kind == SV::Kind::endpoint && predicates::in_closed_triangle(c, key.vertex, tri, t);
      if (!meet) {
        const auto [at, fresh] = tested.try_emplace({tri, a}, false);
        if (fresh) at->second = meet_in_plane(c, s, a, tri, t);
        meet = at->second;
      }
      if (meet) return {std::min(a, b), std::max(a, b)};
    }
    return {};
  }

  // Whether a triangle of object `a` and one of the object of triangle `k`
  // both lie in k's plane at t and meet there.
  bool meet_in_plane(const predicates::Classifier<K>& c, const scene::Scene& s, std::size_t a, std::size_t k,
                     const Time& t) const {
    const auto& plane = c.plane_poly(symbolic::Symbolic_plane{symbolic::Symbolic_plane::Kind::T, k});
    // An object's triangles are consecutive ids (file order).
    const auto in_plane = [&](std::size_t object) {
      // (std::equal_range: clang 14 cannot build libstdc++ 12's ranges version.)
      const auto [first, last] = std::equal_range(s.triangle_object.begin(), s.triangle_object.end(), object);
      std::vector<std::size_t> out;
      for (auto i = first; i != last; ++i) {
        const std::size_t tri = static_cast<std::size_t>(i - s.triangle_object.begin());
        const auto in = [&](std::size_t u) { return k_.sign_at(dot(plane, c.motion().vertex(u)), t) == 0; };
        if (std::ranges::all_of(s.triangles[tri], in)) out.push_back(tri);
      }
      return out;
    };
    const std::vector<std::size_t> mine = in_plane(a);
    if (mine.empty()) return false;
    for (std::size_t theirs : in_plane(s.triangle_object[k]))
      for (std::size_t own : mine)
        if (predicates::coplanar_triangles_meet(c, own, theirs, t)) return true;
    return false;
  }

  // kinetic::reversal_time, moved past any root of a certificate in force
  // (so that the tree in force is valid at r with the old motions and,
  // positions being continuous, with the new ones); none when a
  // floating-point run cannot separate the collision from now, or finds a
  // root of a certificate at every instant it tries (its epsilon swamps
  // them: with mpfr:8 this went on for ever, each try closer to c with a
  // longer rational). The exact kernel moves past each root once.
  std::optional<mpq_class> reversal_time(const In_force<K>& in_force, const Time& now, const Time& collision) const {
    Exact_time a = exact(now);
    const Exact_time c = exact(collision);
    if constexpr (!std::is_same_v<K, Exact_kernel>)
      if (a.upper() >= c.lower()) return std::nullopt;
    for (int tries = 0;; ++tries) {
      if constexpr (!std::is_same_v<K, Exact_kernel>)
        if (tries == floating_point_tries) return std::nullopt;
      const mpq_class r = kinetic::reversal_time(a, c);
      const Time at = k_.time(from_rational<FT>(r));
      bool root = false;
      in_force.for_each([&](const auto& cert) {
        root = root || std::ranges::any_of(cert.polys, [&](const auto& q) { return k_.sign_at(q, at) == 0; });
      });
      if (!root) return r;
      a = Exact_time(r);
    }
  }

  static constexpr int floating_point_tries = 64;

  static Exact_time exact(const Exact_time& t) { return t; }
  template <class T>
  static Exact_time exact(const T& t) { return Exact_time(to_rational(t)); }

  const K& k_;
  Collisions policy_;
};

}  // namespace kvd::kinetic
