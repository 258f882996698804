// The event loop of the kinetic KVD (kinetic/simulation.hpp), as a class
// that kvd::Kinetic_kvd steps (include/kvd/kvd.hpp; kinetic::simulate runs
// it to the end). It holds the tree in force, the queue and the certificate
// upkeep; the builds and the local update (Builder), validation
// (Validator), the floating-point recovery (Fp_recovery), the collision
// policy (X_collide) and the root cache are classes of their own under
// detail/kinetic/. Internal: not installed.
#pragma once

#include <algorithm>
#include <memory>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "kvd/detail/kinetic/builder.hpp"
#include "kvd/detail/kinetic/fp_recovery.hpp"
#include "kvd/detail/kinetic/in_force.hpp"
#include "kvd/detail/kinetic/reduced_upkeep.hpp"
#include "kvd/detail/kinetic/root_cache.hpp"
#include "kvd/detail/kinetic/stopwatch.hpp"
#include "kvd/detail/kinetic/validator.hpp"
#include "kvd/detail/kinetic/x_collide.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/detail/tree/subtree_hashes.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/tree/compare.hpp"

namespace kvd::kinetic::detail {

template <class K>
class Simulator {
  using Time = typename K::Time;
  using FT = typename K::FT;

public:
  Simulator(const K& k, const scene::Scene& s, const Options& o, Observer<K>* observer)
      : k_(k), scene_(s), o_(o), observer_(observer), builder_(k, scene_, full()), validator_(k, scene_, o.validate),
        recovery_(k, builder_, sim_.recovery), x_collide_(k, o.collisions), queue_(make_queue(k, o.queue)),
        now_(k.time(from_rational<FT>(s.start))) {
    sim_.limit = o.until;
    if (s.end && (!sim_.limit || *s.end < *sim_.limit)) sim_.limit = *s.end;
    if (sim_.limit) limit_ = k.time(from_rational<FT>(*sim_.limit));
  }

  // Its parts hold references to scene_, builder_ and sim_: not copied or moved.
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  // The tree at the start, its certificates and the queue. Throws
  // tree::Build_error when the scene is not valid at its start (in a
  // floating-point kernel, nor just after it: build_at).
  void start() {
    const Stopwatch watch;
    Tree_after first = build_at(now_);
    if (!first.tree) throw tree::Build_error(first.meeting.error);
    take(std::move(first));
    make_certificates();
    queue_->first_time();  // the whole tournament, part of the construction
    sim_.construction_seconds = watch.seconds();
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
    if (stopped_) validator_.finish(now_, sim_);
    // A run whose next event lies past the limit, or that has none left, has
    // certified the tree in force up to the limit.
    const bool to_limit = stopped_ && (sim_.stopped == Stop::limit || sim_.stopped == Stop::exhausted);
    sim_.time_reached = to_limit && limit_ ? *limit_ : now_;
    sim_.structure_hash = hashes_.root();
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
    motions_changed();
    const auto changed = rebuild_in_force(t);
    if (const Meeting* m = std::get_if<Meeting>(&changed)) {
      scene_.objects[object].motion = old;
      motions_changed();
      throw tree::Build_error("set_motion: at t = " + at.get_str() + ", " + m->error);
    }
    now_ = t;
    sim_.motion_changes.push_back({at, t, {object}, {motion}, sim_.batches.size(), "flight-plan change", std::get<bool>(changed)});
    validator_.forget();  // the tree in force now has new motions
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
  // Of the tree in force, kept up to date along the paths each update changed.
  const std::string& structure_hash() const { return hashes_.root(); }
  const predicates::Classifier<K>& classifier() const { return builder_.classifier(); }
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
    if (validator_.every()) {
      auto stale = validator_.check(now_, *next, current_, sim_);
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
    const std::vector<std::size_t> failing = queue_->first();
    std::vector<std::size_t> first = failing;
    std::ranges::sort(first, printed_before, [&](std::size_t id) { return in_force_[id].key; });
    for (std::size_t id : first) batch.failing.push_back(in_force_[id].key);
    // The time as the first failing certificate gives it: its polynomial,
    // not whichever the queue met first (the text of a trace).
    batch.time = *in_force_.fails(first.front());
    const Stopwatch tree_watch;
    Time at = *next;
    Tree_after after;
    if (auto contact = x_collide_.contact(builder_.classifier(), scene_, in_force_, failing, *next))
      after.meeting = std::move(*contact);
    else after = local() ? update_locally(at, batch) : build_at(at);
    if (!after.tree) {
      if (const auto step = x_collide_.respond(scene_, sim_, in_force_, now_, *next, batch, after.meeting)) {
        reversed(*step);
        return true;
      }
      sim_.collision = "collision at t = " + k_.to_string(*next) + ": " + after.meeting.error + X_collide<K>::colliding(batch);
      sim_.stopped = Stop::collision;
      if (observer_) observer_->batch(batch, true);
      if (validator_.keeps_last()) validator_.leaving(now_, current_);  // current stays in force
      now_ = *next;
      return false;
    }
    batch.tree_seconds = tree_watch.seconds();
    sim_.failures += batch.failures();
    sim_.simultaneous_batches += batch.failures() >= 2;
    for (const Failure& f : batch.failing) ++sim_.failures_by_type[static_cast<std::size_t>(f.type)];
    // The tree that was in force: a build left it in current_; a local
    // update edited it in place, and kept a copy only for validation.
    validator_.leaving(now_, after.edited ? std::move(before_) : std::move(current_));
    const Stopwatch record_watch;
    batch.changed = take(std::move(after));
    batch.record_seconds = record_watch.seconds();
    now_ = std::move(at);
    if (observer_) observer_->batch(batch, false);
    const Stopwatch cert_watch;
    std::vector<typename K::Poly> fired;  // the failing polynomials, for a floating-point repair
    if constexpr (floating)
      for (std::size_t id : first) fired.insert(fired.end(), in_force_[id].polys.begin(), in_force_[id].polys.end());
    keep_certificates(batch);
    if constexpr (floating) {
      if (Fp_recovery<K>::refires(batch, sim_.batches.empty() ? nullptr : &sim_.batches.back())) {
        auto later = recovery_.move_past(now_, current_, fired);
        if (!later) {
          sim_.stopped = Stop::stuck;
          sim_.batches.push_back(std::move(batch));
          return false;
        }
        adopt(std::move(later->second), std::move(later->first));
      }
    }
    // The next queue minimum: the tournament repairs its changed paths now,
    // inside the batch's time (the next step reads the cached result).
    queue_->first_time();
    batch.certificate_seconds = cert_watch.seconds();
    batch.structure = hashes_.root();
    sim_.batches.push_back(std::move(batch));
    if (o_.progress) o_.progress(sim_.batches.size(), sim_.failures);
    return true;
  }

  static constexpr bool floating = !std::is_same_v<K, Exact_kernel>;

  bool full() const { return o_.certificates == Certificate_set::full; }
  // The full set is what a build evaluates: it always takes the rebuild.
  bool local() const { return o_.update != Update::rebuild && !full(); }

  // The tree in force changed in place by the local update of the batch
  // failing at `at`, and moved into the result. A floating-point kernel whose update fails repairs with the
  // recovery's builds.
  Tree_after update_locally(Time& at, Batch<Time>& batch) {
    std::set<symbolic::Symbolic_plane> moving;
    std::vector<const Certificate<typename K::Poly>*> failing;
    for (std::size_t id : queue_->first()) {
      moving.merge(moving_sites(scene_, links_, current_, in_force_[id]));
      failing.push_back(&in_force_[id]);
    }
    const int scope = o_.update == Update::local ? update_scope(scene_, links_, current_, failing) : -1;
    if (validator_.keeps_last()) before_ = current_;  // the update edits the tree in force
    auto updated = builder_.update(current_, links_, at, moving, scope,
                                   o_.update == Update::local ? Edit::recut : Edit::reinsert);
    if (Update_cost* cost = std::get_if<Update_cost>(&updated)) {
      batch.moving_sites = cost->sites;
      batch.scope = cost->widened ? Update_scope::widened : scope >= 0 ? Update_scope::subtree : Update_scope::whole;
      batch.nodes_touched = cost->nodes_touched;
      batch.nodes_changed = cost->nodes_changed;
      return {std::move(current_), {}, std::move(cost->changed)};
    }
    before_ = {};  // undone: the tree in force is current_ again
    if constexpr (floating) return build_at(at);
    else return {std::nullopt, std::get<Meeting>(std::move(updated)), std::nullopt};
  }

  // The tree valid just after `at`, or the meeting there. A floating-point
  // kernel whose build fails tries the later instants of the recovery,
  // moving `at` to the one used; when none succeeds, the first failure is
  // the news.
  Tree_after build_at(Time& at) {
    Tree_after t = builder_.build(at);
    if constexpr (floating) {
      if (t.tree) return t;
      if (auto later = recovery_.build_later(at)) {
        at = std::move(later->first);
        t.tree = std::move(later->second);
      }
    }
    return t;
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
    queue_->reshape(current_, links_, unsettled());
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
    roots_.bound(in_force_.size());
    const auto fails = [&](const auto& cert) { return roots_.fails(k_, cert, now_); };
    typename Reduced_upkeep<K>::Work work;
    std::vector<typename In_force<K>::Offer> offers;
    if (full()) {
      const auto all = full_certificates(builder_.classifier(), current_, builder_.evaluated(), now_);
      work = {current_.statistics().nodes, all.size()};
      for (const auto& cert : all) offers.push_back({&cert, true});
      in_force_.replace(offers, *queue_, fails);
    } else {
      const auto changes = upkeep_.update(builder_.classifier(), current_, links_, unsettled(), now_, failed, work);
      for (const auto& held : changes.changed) offers.push_back({held.certificate, held.made});
      in_force_.apply(changes.gone, offers, *queue_, fails);
    }
    settled_ = true;
    edited_.clear();
    if (observer_) {
      std::vector<Certificate<typename K::Poly>> certs;
      in_force_.for_each([&](const auto& cert) { certs.push_back(cert); });
      observer_->in_force(now_, certs);
    }
    return work;
  }

  // Floating-point kernels: a repaired tree (a fresh build found by
  // validation, or a later step) replaces the tree in force, at its instant.
  void adopt(tree::Kvd_tree t, Time at) {
    ++sim_.recovery.rebuilds;
    take({std::move(t), {}, std::nullopt});
    now_ = std::move(at);
    make_certificates();
  }

  // The motions in scene_ changed: the classifiers follow.
  void motions_changed() {
    builder_.motions_changed();
    validator_.motions_changed();
  }

  // After X-collide's `step`: the new motions are in force from its time.
  // The certificates are non-zero there, and positions are continuous, so
  // the tree in force is the tree just after it unless a classification
  // that vanished identically under the old motions (one the perturbation
  // decided) no longer does: the build says which.
  void reversed(const Reversal<Time>& step) {
    motions_changed();
    validator_.forget();  // the tree in force now has new motions
    now_ = k_.time(from_rational<FT>(step.time));
    if (const auto changed = rebuild_in_force(now_); const bool* c = std::get_if<bool>(&changed))
      sim_.motion_changes.back().tree_changed |= *c;
    if (observer_) observer_->reversal(step);
    make_certificates();
  }

  // After a change of motions: the tree just after t under the motions now
  // in force replaces the tree in force. Whether it differs; or the meeting
  // there, and the tree in force stays.
  std::variant<bool, Meeting> rebuild_in_force(const Time& t) {
    Tree_after after = builder_.build(t);
    if (!after.tree) return std::move(after.meeting);
    return take(std::move(after));
  }

  // The nodes changed since the certificates were last put in force (none:
  // the tree in force is a new build, to be looked at whole).
  const std::vector<int>* unsettled() const { return settled_ ? &edited_ : nullptr; }

  // `after` becomes the tree in force, its structure hash updated along
  // the paths a local update changed, or made afresh for a build. Whether
  // the tree changed: equal structure hashes are an equal canonical
  // serialisation, node for node.
  bool take(Tree_after after) {
    const std::string before = hashes_.root();
    current_ = std::move(*after.tree);
    if (after.edited) {
      links_.update(current_, *after.edited);
      hashes_.update(current_, links_, *after.edited);
      edited_.insert(edited_.end(), after.edited->begin(), after.edited->end());
    } else {
      links_.reset(current_);
      hashes_.reset(current_);
      settled_ = false;
    }
    return hashes_.root() != before;
  }

  const K& k_;
  scene::Scene scene_;  // with the motions in force
  const Options& o_;
  Observer<K>* observer_;
  Simulation<Time> sim_;
  Builder<K> builder_;
  Validator<K> validator_;
  Fp_recovery<K> recovery_;
  X_collide<K> x_collide_;
  std::unique_ptr<Event_queue<K>> queue_;
  Time now_;
  std::optional<Time> limit_;
  tree::Kvd_tree current_;
  tree::Tree_links links_;       // of current_
  tree::Subtree_hashes hashes_;  // of current_
  tree::Kvd_tree before_;        // current_ before a local update, when validation keeps it
  // What changed in current_ since the certificates were last put in force
  // (unsettled()): a build (settled_ false), or the nodes local updates edited.
  bool settled_ = false;
  std::vector<int> edited_;
  In_force<K> in_force_;
  Reduced_upkeep<K> upkeep_;
  Root_cache<K> roots_;
  bool stopped_ = false, finished_ = false;
};

}  // namespace kvd::kinetic::detail
