// The collision policy of a run (thesis 7.3.3, detail/kinetic/collision.hpp):
// whether a batch's failures are contacts, and X-collide's response, which
// reverses the motions of the objects meeting.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "kvd/detail/kinetic/builder.hpp"
#include "kvd/detail/kinetic/collision.hpp"
#include "kvd/detail/kinetic/in_force.hpp"
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
  // (an object's own features lie in its faces' planes by construction).
  // The contacts are named in certificate-key order.
  std::optional<Meeting> contact(const predicates::Classifier<K>& c, const scene::Scene& s, const In_force<K>& in_force,
                                 const std::vector<std::size_t>& failing, const Time& t) const {
    Meeting m;
    std::string features;
    // Named in key order: the queue's order among simultaneous failures is its own.
    std::vector<std::size_t> by_key = failing;
    std::ranges::sort(by_key, [&](std::size_t a, std::size_t b) { return in_force[a].key < in_force[b].key; });
    for (std::size_t id : by_key) {
      const auto& cert = in_force[id];
      if (!may_collide(cert.key.type)) continue;
      const Touch th = touch(s, cert.vertices, cert.planes);
      const auto objects = contact_objects(s, th);
      if (objects.size() < 2 || !predicates::in_closed_triangle(c, th.vertex, th.triangle, t)) continue;
      m.objects.insert(m.objects.end(), objects.begin(), objects.end());
      features += (features.empty() ? "" : ", ") + std::string(to_string(cert.key.type)) + " " + kinetic::features(cert.key);
    }
    if (m.objects.empty()) return std::nullopt;
    std::ranges::sort(m.objects);
    m.objects.erase(std::unique(m.objects.begin(), m.objects.end()), m.objects.end());
    m.error = "a vertex or an edge reaches a triangle (" + features + ")";
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
