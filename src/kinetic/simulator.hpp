// The event loop of the kinetic KVD (kinetic/simulation.hpp), as a class
// that kvd::Kinetic_kvd steps (include/kvd/kvd.hpp; kinetic::simulate runs
// it to the end). Internal: not installed.
#pragma once

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <type_traits>

#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/detail/kinetic/collision.hpp"
#include "kvd/detail/kinetic/in_force.hpp"
#include "kvd/detail/kinetic/local_update.hpp"
#include "kvd/detail/kinetic/reduced_upkeep.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/predicates/classify.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/tree/compare.hpp"

namespace kvd::kinetic::detail {

// A time strictly between a < b: a rational in the exact kernel, the
// midpoint in the floating-point ones.
inline Exact_time between(const Exact_kernel&, const Exact_time& a, const Exact_time& b) {
  return Exact_time(rational_between(a, b));
}
template <class K>
typename K::Time between(const K&, const typename K::Time& a, const typename K::Time& b) {
  return (a + b) / typename K::FT(2);
}

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class K>
class Simulator {
  using Time = typename K::Time;
  using FT = typename K::FT;

public:
  Simulator(const K& k, const scene::Scene& s, const Options& o, Observer<K>* observer)
      : k_(k), scene_(s), o_(o), observer_(observer), queue_(make_queue(k, o.queue)), now_(k.time(from_rational<FT>(s.start))) {
    sim_.limit = o.until;
    if (s.end && (!sim_.limit || *s.end < *sim_.limit)) sim_.limit = *s.end;
    if (sim_.limit) limit_ = k.time(from_rational<FT>(*sim_.limit));
    make_classifiers();
  }

  // The tree at the start, its certificates and the queue.
  void start() {
    const auto start = std::chrono::steady_clock::now();
    {
      std::optional<tree::Kvd_tree> first = build_at(now_);
      if (!first) throw tree::Build_error(build_error_);  // the scene is not valid at its start
      current_ = std::move(*first);
    }
    make_certificates();
    sim_.construction_seconds = seconds_since(start);
    in_force_.for_each([&](const auto& cert) { ++sim_.initial_certificates[static_cast<std::size_t>(cert.key.type)]; });
  }

  // One step of the run: a batch processed, a motion change made, or (in a
  // floating-point kernel) a stale tree repaired. False when the run has
  // stopped (sim_.stopped says why; a stopped run stays stopped).
  bool step() {
    if (stopped_) return false;
    if (!step_once()) stopped_ = true;
    return !stopped_;
  }

  // What the run has done so far, with the time reached and the structure
  // hash of the tree in force; once it has stopped, the end of the
  // validation too (done once).
  const Simulation<Time>& finish() {
    if (finished_) return sim_;
    finished_ = stopped_;
    if (stopped_ && o_.validate == Validation::end && before_last_ && k_.compare(before_last_->first, now_) < 0)
      validate(before_last_->first, now_, before_last_->second);
    // A run whose next event lies past the limit, or that has none left, has
    // certified the tree in force up to the limit.
    const bool to_limit = stopped_ && (sim_.stopped == Stop::limit || sim_.stopped == Stop::exhausted);
    sim_.time_reached = to_limit && limit_ ? *limit_ : now_;
    sim_.structure_hash = tree::structure_hash(current_);
    return sim_;
  }
  // A flight-plan change: `object` moves by `motion` from the rational
  // instant `at` on, now <= at < the next event (and within the limit). The
  // tree in force is valid at `at`; it is rebuilt just after `at` under the
  // new motions (it changes only where the object jumps or a classification
  // the perturbation decided no longer vanishes). The certificates naming
  // the object's features are made again, with those of the nodes the
  // rebuild changed (seed 003, Lemma 3.1); the others keep their failure
  // times. Recorded as a motion change; throws
  // std::invalid_argument on a bad object, motion or instant, and
  // tree::Build_error (leaving the run as it was) when triangles would meet
  // just after `at`.
  void set_motion(std::size_t object, const scene::Motion& motion, const mpq_class& at) {
    if (stopped_) throw std::invalid_argument("set_motion: the run has stopped");
    if (object >= scene_.objects.size()) throw std::invalid_argument("set_motion: no object " + std::to_string(object));
    if (motion.kind == scene::Motion::Kind::vertices && motion.vertices.size() != scene_.objects[object].vertex_count)
      throw std::invalid_argument("set_motion: the motion gives " + std::to_string(motion.vertices.size()) +
                                  " vertices, the object has " + std::to_string(scene_.objects[object].vertex_count));
    const Time t = k_.time(from_rational<FT>(at));
    const std::optional<Time> next = queue_->first_time();
    if (k_.compare(t, now_) < 0 || (next && k_.compare(t, *next) >= 0) || past_limit(t))
      throw std::invalid_argument("set_motion: the instant " + at.get_str() +
                                  " is not in [now, next event) within the time limit");
    const scene::Motion old = scene_.objects[object].motion;
    scene_.objects[object].motion = motion;
    make_classifiers();
    const std::optional<bool> changed = rebuild_in_force(t);
    if (!changed) {
      scene_.objects[object].motion = old;
      make_classifiers();
      throw tree::Build_error("set_motion: at t = " + at.get_str() + ", " + build_error_);
    }
    now_ = t;
    sim_.motion_changes.push_back({at, t, {object}, {motion}, sim_.batches.size(), "flight-plan change", *changed});
    if (o_.validate == Validation::end) before_last_.reset();  // the tree in force now has new motions
    sim_.motion_changes.back().certificates_recomputed = remake_certificates_of(object);
    sim_.motion_changes.back().certificates = in_force_.size();
  }

  // The run so far, as it stands.
  const Simulation<Time>& so_far() const { return sim_; }
  const K& kernel() const { return k_; }
  const std::optional<Time>& limit() const { return limit_; }

  const Time& now() const { return now_; }
  // The time of the next batch; none when the next step stops the run.
  std::optional<Time> next_time() const {
    if (stopped_ || events_reached()) return std::nullopt;
    std::optional<Time> next = queue_->first_time();
    if (next && past_limit(*next)) return std::nullopt;
    return next;
  }
  const tree::Kvd_tree& tree() const { return current_; }
  const predicates::Classifier<K>& classifier() const { return *c_; }
  const scene::Scene& scene() const { return scene_; }
  std::vector<Certificate<typename K::Poly>> certificates() const {
    std::vector<Certificate<typename K::Poly>> out;
    in_force_.for_each([&](const auto& cert) { out.push_back(cert); });
    return out;
  }

private:
  bool events_reached() const {
    return sim_.failures >= o_.max_events || sim_.motion_changes.size() >= o_.max_events;
  }
  bool past_limit(const Time& t) const { return limit_ && k_.compare(t, *limit_) > 0; }

  bool step_once() {
    if (events_reached()) {
      sim_.stopped = Stop::events;
      sim_.next_failure = queue_->first_time();
      return false;
    }
    const std::optional<Time> next = queue_->first_time();
    if (!next) return false;  // Stop::exhausted
    if (past_limit(*next)) {
      sim_.stopped = Stop::limit;
      return false;
    }
    if (o_.validate == Validation::every) {
      auto stale = validate(now_, *next, current_);
      if constexpr (floating) {
        if (stale) {  // repaired: the queue now holds the fresh tree's certificates
          ++sim_.recovery.stale_trees;
          adopt(std::move(stale->second), std::move(stale->first));
          return true;
        }
      }
    }
    Batch<Time> batch;
    batch.certificates = in_force_.size();
    std::vector<std::size_t> first = queue_->first();
    std::ranges::sort(first, printed_before, [&](std::size_t id) { return in_force_[id].key; });
    for (std::size_t id : first) batch.failing.push_back(in_force_[id].key);
    // The time as the first failing certificate gives it: its polynomial,
    // not whichever the queue met first (the text of a trace).
    batch.time = *in_force_.fails(first.front());
    const auto tree_start = std::chrono::steady_clock::now();
    Time at = *next;
    std::optional<tree::Kvd_tree> after;
    if (!failing_contact(*next)) after = local() ? update_locally(at, batch) : build_at(at);
    if (!after && respond(*next, batch)) {
      if (o_.validate == Validation::end) before_last_.reset();  // the tree in force now has new motions
      return true;
    }
    if (!after) {
      sim_.collision = "collision at t = " + k_.to_string(*next) + ": " + build_error_ + colliding(batch);
      sim_.stopped = Stop::collision;
      if (observer_) observer_->batch(batch, true);
      if (o_.validate == Validation::end) before_last_.emplace(now_, current_);  // current stays in force
      now_ = *next;
      return false;
    }
    batch.changed = tree::first_difference(current_, *after).has_value();
    batch.tree_seconds = seconds_since(tree_start);
    sim_.failures += batch.failures();
    sim_.simultaneous_batches += batch.failures() >= 2;
    for (const Failure& f : batch.failing) ++sim_.failures_by_type[static_cast<std::size_t>(f.type)];
    if (o_.validate == Validation::end) before_last_.emplace(now_, std::move(current_));
    current_ = std::move(*after);
    now_ = std::move(at);
    if (observer_) observer_->batch(batch, false);
    const auto cert_start = std::chrono::steady_clock::now();
    std::vector<typename K::Poly> fired;  // the failing polynomials, for a floating-point repair
    if constexpr (floating)
      for (std::size_t id : first) fired.insert(fired.end(), in_force_[id].polys.begin(), in_force_[id].polys.end());
    keep_certificates(batch);
    if constexpr (floating) {
      if (!repair(batch, fired)) {
        sim_.stopped = Stop::stuck;
        sim_.batches.push_back(std::move(batch));
        return false;
      }
    }
    batch.certificate_seconds = seconds_since(cert_start);
    const auto record_start = std::chrono::steady_clock::now();
    batch.structure = tree::structure_hash(current_);
    batch.record_seconds = seconds_since(record_start);
    sim_.batches.push_back(std::move(batch));
    if (o_.progress) o_.progress(sim_.batches.size(), sim_.failures);
    return true;
  }

  static constexpr bool floating = !std::is_same_v<K, Exact_kernel>;

  bool full() const { return o_.certificates == Certificate_set::full; }
  // The full set is what a build evaluates: it always takes the rebuild.
  bool local() const { return o_.update == Update::local && !full(); }

  std::optional<tree::Kvd_tree> try_build(const Time& t) {
    evaluated_.clear();
    try {
      return tree::build(*c_, t, full() ? &evaluated_ : nullptr);
    } catch (const tree::Build_error& e) {
      failed(e);
      return std::nullopt;
    }
  }

  // The tree in force changed by the local update of the batch failing at
  // `at`; none when triangles meet there (the tree in force then stays).
  // A floating-point kernel whose update throws repairs with the recovery's
  // builds (counted as a failed build).
  std::optional<tree::Kvd_tree> update_locally(Time& at, Batch<Time>& batch) {
    std::set<symbolic::Symbolic_plane> moving;
    for (std::size_t id : queue_->first()) moving.merge(moving_sites(scene_, in_force_[id]));
    tree::Kvd_tree t = current_;
    try {
      const Update_cost cost = local_update(t, tree::Fragment_splitter<K>(*c_, at), moving);
      batch.moving_sites = cost.sites;
      batch.nodes_touched = cost.nodes_touched;
      return t;
    } catch (const tree::Build_error& e) {
      failed(e);
      if constexpr (!floating) return std::nullopt;
    } catch (const std::logic_error&) {
      // Rounding can leave pieces that no longer fit together (a join that
      // finds no shared side); exact arithmetic cannot, so there it is a bug.
      if constexpr (!floating) throw;
    }
    return build_at(at);
  }

  // The tree valid just after `at`; none when triangles meet there. A
  // floating-point kernel whose build throws counts it and tries the later
  // instants of the recovery, moving `at` to the one used.
  std::optional<tree::Kvd_tree> build_at(Time& at) {
    std::optional<tree::Kvd_tree> t = try_build(at);
    if constexpr (floating) {
      if (t) return t;
      ++sim_.recovery.failed_builds;
      const std::string error = build_error_;  // the steps' own failures are not the news
      const std::vector<std::size_t> met = met_;
      auto later = step_forward(at, [](const tree::Kvd_tree&) { return true; });
      if (!later) {
        build_error_ = error;
        met_ = met;
        return std::nullopt;
      }
      ++sim_.recovery.rebuilds;
      at = std::move(later->first);
      t = std::move(later->second);
    }
    return t;
  }

  // The first of the instants base + 2^i epsilon, i = 1, ..., recovery_steps,
  // whose build succeeds and is accepted, with its tree.
  template <class Accept>
  std::optional<std::pair<Time, tree::Kvd_tree>> step_forward(const Time& base, Accept accept)
    requires floating
  {
    typename K::FT step = k_.epsilon();
    for (int i = 1; i <= recovery_steps; ++i) {
      step = step * typename K::FT(2);
      Time later = base + step;
      std::optional<tree::Kvd_tree> t = try_build(later);
      if (t && accept(*t)) return std::pair{std::move(later), std::move(*t)};
    }
    return std::nullopt;
  }

  // The certificates of the tree in force made afresh, their failure times,
  // the queue: at the start, after a motion change, after a repair.
  void make_certificates() {
    queue_->reset(current_);
    in_force_.clear();
    upkeep_.clear();
    put_in_force({});
  }

  // After a batch: the reduced set keeps the certificates of the nodes the
  // batch left alone (Reduced_upkeep); the queue changes where they changed.
  void keep_certificates(Batch<Time>& batch) {
    const auto work = keep_certificates(std::set<Certificate_key>(batch.failing.begin(), batch.failing.end()));
    batch.nodes_recomputed = work.nodes;
    batch.certificates_recomputed = work.certificates;
  }
  typename Reduced_upkeep<K>::Work keep_certificates(const std::set<Certificate_key>& failed) {
    if (o_.upkeep == Upkeep::all) upkeep_.remake_all();
    queue_->reshape(current_);
    return put_in_force(failed);
  }

  // After a flight-plan change of `object`: the nodes holding a certificate
  // that names its features make theirs again, as if it had failed. The
  // full set is what the rebuild evaluated: made again whole.
  // How many were made.
  std::size_t remake_certificates_of(std::size_t object) {
    if (full()) {
      make_certificates();
      return in_force_.size();
    }
    std::set<Certificate_key> named;
    in_force_.for_each([&](const auto& cert) {
      if (names_object(scene_, cert.key, object)) named.insert(cert.key);
    });
    return keep_certificates(named).certificates;
  }

  typename Reduced_upkeep<K>::Work put_in_force(const std::set<Certificate_key>& failed) {
    const auto fails = [&](const auto& cert) {
      std::optional<Time> first;
      for (const auto& q : cert.polys) {
        const auto& r = next_root(q);
        if (r && (!first || k_.compare(*r, *first) < 0)) first = r;
      }
      return first;
    };
    typename Reduced_upkeep<K>::Work work;
    std::vector<typename In_force<K>::Offer> offers;
    if (full()) {
      const auto all = full_certificates(*c_, current_, evaluated_, now_);
      work = {current_.statistics().nodes, all.size()};
      for (const auto& cert : all) offers.push_back({&cert, true});
      in_force_.replace(offers, *queue_, fails);
    } else {
      const auto changes = upkeep_.update(*c_, current_, now_, failed, work);
      for (const auto& held : changes.changed) offers.push_back({held.certificate, held.made});
      in_force_.apply(changes.gone, offers, *queue_, fails);
    }
    if (observer_) {
      std::vector<Certificate<typename K::Poly>> certs;
      in_force_.for_each([&](const auto& cert) { certs.push_back(cert); });
      observer_->in_force(now_, certs);
    }
    return work;
  }

  // The first sign-changing root of q after now, cached per polynomial.
  const std::optional<Time>& next_root(const typename K::Poly& q) {
    auto it = roots_.find(q.coefficients());
    if (it == roots_.end() || (it->second && k_.compare(*it->second, now_) <= 0))
      it = roots_.insert_or_assign(q.coefficients(), k_.next_root(q, now_)).first;
    return it->second;
  }

  // Floating-point kernels: a batch that repeats the previous one without
  // changing the tree is rounding firing one event again; the run moves on
  // to the first later instant whose tree differs. (A certificate cannot
  // fail in the past: each is oriented positive just after the instant it is
  // made, and its failure time is a root later than that instant by more
  // than epsilon.) When no nearby tree differs, the certificate is firing
  // inside its own rounding zone (around a root of high multiplicity,
  // rounded values change sign anywhere within about epsilon^(1/m)), and
  // the run steps past that zone. Returns false when it cannot: the run
  // stops there rather than repeat the batch without advancing.
  bool repair(const Batch<Time>& b, const std::vector<typename K::Poly>& fired)
    requires floating
  {
    if (b.changed || sim_.batches.empty() || sim_.batches.back().failing != b.failing) return true;
    ++sim_.recovery.refires;
    auto later = step_forward(now_, [&](const tree::Kvd_tree& t) { return tree::first_difference(current_, t).has_value(); });
    if (!later) later = step_past(now_, fired);
    if (!later) {
      ++sim_.recovery.unrepaired;
      return false;
    }
    adopt(std::move(later->second), std::move(later->first));
    return true;
  }

  // The first instant base + 2^i epsilon (i = 1, 2, ..., while the step is
  // below 1) from which none of `fired` changes sign again within the step,
  // with its tree: past the zone where rounding makes them fire again.
  std::optional<std::pair<Time, tree::Kvd_tree>> step_past(const Time& base, const std::vector<typename K::Poly>& fired)
    requires floating
  {
    for (FT step = k_.epsilon() * FT(2); step < FT(1); step = step * FT(2)) {
      const Time later = base + step;
      const bool clear = std::ranges::none_of(fired, [&](const typename K::Poly& p) {
        const auto r = k_.next_root(p, later);
        return r && k_.compare(*r, later + step) <= 0;
      });
      if (!clear) continue;
      if (std::optional<tree::Kvd_tree> t = try_build(later)) {
        ++sim_.recovery.zones_skipped;
        return std::pair{later, std::move(*t)};
      }
    }
    return std::nullopt;
  }

  // Floating-point kernels: a repaired tree (a fresh build found by
  // validation, or a later step) replaces the tree in force, at its instant.
  void adopt(tree::Kvd_tree t, Time at) {
    ++sim_.recovery.rebuilds;
    current_ = std::move(t);
    now_ = std::move(at);
    make_certificates();
  }

  // Checks the tree in force on (from, to) against a fresh build at a time
  // strictly between, by a classifier of its own (no cache shared with the
  // simulation): a difference is a missed event. Returns the instant and the
  // fresh tree when they differ.
  std::optional<std::pair<Time, tree::Kvd_tree>> validate(const Time& from, const Time& to,
                                                          const tree::Kvd_tree& in_force) {
    Time mid = between(k_, from, to);
    ++sim_.validations;
    std::optional<std::string> diff;
    std::optional<tree::Kvd_tree> fresh;
    try {
      fresh = tree::build(*oracle_, mid);
      diff = tree::first_difference(in_force, *fresh);
      if (diff) diff = "the tree in force differs from a fresh build: " + *diff;
    } catch (const tree::Build_error& e) {
      diff = std::string("the fresh build failed: ") + e.what();
    }
    if (!diff) return std::nullopt;
    if (sim_.validation_failures++ == 0)
      sim_.failure = "between " + k_.to_string(from) + " and " + k_.to_string(to) + ", at " + k_.to_string(mid) +
                     ", " + *diff;
    if (!fresh) return std::nullopt;
    return std::pair{std::move(mid), std::move(*fresh)};
  }

  // Whether the failures at `t` include contacts: VT, ET or TT certificates
  // whose vertex lies in the triangle of another object at t (an object's
  // own features lie in its faces' planes by construction); if so, the
  // objects meeting go to met_ and the features to build_error_.
  bool failing_contact(const Time& t) {
    met_.clear();
    std::string features;
    for (std::size_t id : queue_->first()) {
      const auto& cert = in_force_[id];
      if (!may_collide(cert.key.type)) continue;
      const Touch th = touch(scene_, cert.vertices, cert.planes);
      const auto objects = contact_objects(scene_, th);
      if (objects.size() < 2 || !in_triangle(*c_, k_, th, t)) continue;
      met_.insert(met_.end(), objects.begin(), objects.end());
      features += (features.empty() ? "" : ", ") + std::string(to_string(cert.key.type)) + " " + kinetic::features(cert.key);
    }
    std::sort(met_.begin(), met_.end());
    met_.erase(std::unique(met_.begin(), met_.end()), met_.end());
    if (!features.empty()) build_error_ = "a vertex or an edge reaches a triangle (" + features + ")";
    return !met_.empty();
  }

  // A build or an update that found triangles crossing.
  void failed(const tree::Build_error& e) {
    build_error_ = e.what();
    met_ = e.contact ? contact_objects(scene_, *e.contact) : std::vector<std::size_t>{};
  }

  // Classifiers of the motions in force (their caches hold motion polynomials).
  void make_classifiers() {
    c_ = std::make_unique<const predicates::Classifier<K>>(k_, scene_);
    oracle_ = std::make_unique<const predicates::Classifier<K>>(k_, scene_);
  }

  // X-collide for triangles found meeting at `collision`: reverses the
  // objects' motions at a time r strictly between the last batch and
  // `collision`, where the tree in force is valid, and puts the certificates
  // of the new motions in force from r. A second contact at the same
  // instant before any batch reverses its other objects at the same r.
  // False when the run stops instead: Collisions::stop, an unknown contact,
  // or a contact of objects already reversed for this instant.
  bool respond(const Time& collision, const Batch<Time>& batch) {
    if (o_.collisions != Collisions::reverse) return false;
    std::vector<std::size_t> objects = met_;
    std::erase_if(objects, [&](std::size_t o) { return !scene_.is_moving(o); });  // reversing changes nothing
    const bool again = !sim_.motion_changes.empty() && sim_.motion_changes.back().batches_before == sim_.batches.size() &&
                       k_.compare(sim_.motion_changes.back().collision, collision) == 0;
    if (again)
      std::erase_if(objects, [&](std::size_t o) {
        return std::ranges::binary_search(sim_.motion_changes.back().objects, o);
      });
    if (objects.empty()) return false;
    std::optional<mpq_class> r;
    if (again) r = sim_.motion_changes.back().time;
    else r = reversal_time(collision);
    if (!r) return false;
    if (again) sim_.motion_changes.back().contact += "; " + build_error_;
    else sim_.motion_changes.push_back({*r, collision, {}, {}, sim_.batches.size(), build_error_});
    Motion_change<Time>& record = sim_.motion_changes.back();
    Reversal<Time> step{*r, batch, objects, {}, build_error_};
    for (std::size_t o : objects) {
      scene_.objects[o].motion = scene::reversed(scene_.objects[o].motion, *r);
      step.motions.push_back(scene_.objects[o].motion);
      const auto at = std::ranges::upper_bound(record.objects, o) - record.objects.begin();
      record.objects.insert(record.objects.begin() + at, o);
      record.motions.insert(record.motions.begin() + at, scene_.objects[o].motion);
    }
    make_classifiers();
    now_ = k_.time(from_rational<FT>(*r));
    // The certificates are non-zero at r, and positions are continuous
    // there, so the tree in force is the tree just after r unless a
    // classification that vanished identically under the old motions (one the
    // perturbation decided) no longer does: the build says which.
    if (const std::optional<bool> changed = rebuild_in_force(now_)) record.tree_changed |= *changed;
    if (observer_) observer_->reversal(step);
    make_certificates();
    return true;
  }

  // After a change of motions: the tree just after t under the motions now
  // in force replaces the tree in force. Whether it differs, or none (the
  // tree in force stays) when triangles meet there.
  std::optional<bool> rebuild_in_force(const Time& t) {
    std::optional<tree::Kvd_tree> after = try_build(t);
    if (!after) return std::nullopt;
    const bool changed = tree::first_difference(current_, *after).has_value();
    current_ = std::move(*after);
    return changed;
  }

  // The reversal time: kinetic::reversal_time, moved past any root of a
  // certificate in force (so that the tree in force is valid at r with the
  // old motions and, positions being continuous, with the new ones); none
  // when a floating-point run cannot separate the collision from now.
  std::optional<mpq_class> reversal_time(const Time& collision) {
    Exact_time a = exact(now_);
    const Exact_time c = exact(collision);
    if constexpr (floating)
      if (a.upper() >= c.lower()) return std::nullopt;
    for (;;) {
      const mpq_class r = kinetic::reversal_time(a, c);
      const Time at = k_.time(from_rational<FT>(r));
      bool root = false;
      in_force_.for_each([&](const auto& cert) {
        root = root || std::ranges::any_of(cert.polys, [&](const auto& q) { return k_.sign_at(q, at) == 0; });
      });
      if (!root) return r;
      a = Exact_time(r);
    }
  }

  static Exact_time exact(const Exact_time& t) { return t; }
  template <class T>
  static Exact_time exact(const T& t) { return Exact_time(to_rational(t)); }

  static std::string colliding(const Batch<Time>& b) {
    std::string out;
    for (const Failure& f : b.failing)
      if (may_collide(f.type)) out += std::string(out.empty() ? "; failing: " : ", ") + to_string(f.type) + " " + kinetic::features(f);
    return out;
  }

  const K& k_;
  scene::Scene scene_;  // with the motions in force
  std::unique_ptr<const predicates::Classifier<K>> c_;
  std::unique_ptr<const predicates::Classifier<K>> oracle_;  // for validation only
  const Options& o_;
  Observer<K>* observer_;
  std::unique_ptr<Event_queue<K>> queue_;
  Time now_;
  std::optional<Time> limit_;
  tree::Kvd_tree current_;
  tree::Evaluated evaluated_;  // by the last build, for the full set
  In_force<K> in_force_;
  Reduced_upkeep<K> upkeep_;
  std::map<std::vector<FT>, std::optional<Time>> roots_;
  std::string build_error_;  // why the last build threw
  std::vector<std::size_t> met_;  // the objects it found meeting
  Simulation<Time> sim_;
  std::optional<std::pair<Time, tree::Kvd_tree>> before_last_;  // for Validation::end
  bool stopped_ = false, finished_ = false;
};

}  // namespace kvd::kinetic::detail
