#include <type_traits>

#include "kvd/detail/kernel/instantiate.hpp"
#include "kvd/kvd.hpp"
#include "kvd/query/visibility.hpp"
#include "simulator.hpp"

namespace kvd {

template <class K>
Kinetic_kvd<K>::Kinetic_kvd(const K& kernel, const scene::Scene& scene, kinetic::Options options,
                            kinetic::Observer<K>* observer)
    : options_(std::make_unique<kinetic::Options>(std::move(options))),
      sim_(std::make_unique<kinetic::detail::Simulator<K>>(kernel, scene, *options_, observer)) {
  sim_->start();
}

template <class K>
Kinetic_kvd<K>::~Kinetic_kvd() = default;
template <class K>
Kinetic_kvd<K>::Kinetic_kvd(Kinetic_kvd&&) noexcept = default;
template <class K>
Kinetic_kvd<K>& Kinetic_kvd<K>::operator=(Kinetic_kvd&&) noexcept = default;

template <class K>
const typename K::Time& Kinetic_kvd<K>::now() const {
  return sim_->now();
}

template <class K>
std::optional<typename K::Time> Kinetic_kvd<K>::next_event_time() const {
  return sim_->next_time();
}

template <class K>
const typename Kinetic_kvd<K>::Batch* Kinetic_kvd<K>::advance() {
  const std::size_t before = sim_->so_far().batches.size();
  while (sim_->step())
    if (sim_->so_far().batches.size() > before) return &sim_->so_far().batches.back();
  sim_->finish();
  // A floating-point run that is stuck records its last batch and stops.
  return sim_->so_far().batches.size() > before ? &sim_->so_far().batches.back() : nullptr;
}

template <class K>
std::size_t Kinetic_kvd<K>::advance_to(const typename K::FT& t) {
  const auto& k = sim_->kernel();
  const typename K::Time until = k.time(t);
  std::size_t n = 0;
  for (auto next = next_event_time(); next && k.compare(*next, until) <= 0; next = next_event_time())
    n += advance() != nullptr;
  return n;
}

template <class K>
bool Kinetic_kvd<K>::stopped() const {
  return !sim_->next_time();
}

template <class K>
void Kinetic_kvd<K>::set_motion(std::size_t object, const scene::Motion& motion, const mpq_class& at) {
  sim_->set_motion(object, motion, at);
}

template <class K>
const tree::Kvd_tree& Kinetic_kvd<K>::tree() const {
  return sim_->tree();
}

template <class K>
std::string Kinetic_kvd<K>::structure_hash() const {
  return sim_->structure_hash();
}

template <class K>
std::vector<kinetic::Certificate<typename K::Poly>> Kinetic_kvd<K>::certificates() const {
  return sim_->certificates();
}

template <class K>
std::vector<int> Kinetic_kvd<K>::back_to_front(const Point4<typename K::FT>& view) const {
  // An instant inside the interval of the tree in force: before the next
  // event, or the limit, or one time unit on.
  using FT = typename K::FT;
  const typename K::Time& now = sim_->now();
  std::optional<typename K::Time> to = next_event_time();
  if (!to) to = sim_->limit();
  FT t;
  if constexpr (std::is_same_v<K, Exact_kernel>) {
    t = to && sim_->kernel().compare(now, *to) < 0 ? kinetic::rational_between(now, *to)
                                                    : (now.is_rational() ? now.rational() : now.upper()) + 1;
  } else {
    t = to && *to > now ? (now + *to) / FT(2) : now + FT(1);
  }
  return query::back_to_front(sim_->classifier(), sim_->tree(), view, t);
}

template <class K>
const kinetic::Simulation<typename K::Time>& Kinetic_kvd<K>::record() const {
  return sim_->finish();
}

#define KVD_INSTANTIATE_KINETIC(K) template class Kinetic_kvd<K>;
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_KINETIC)

namespace kinetic {

// The stepping object run to the end: kvd simulate, diff, certify and bench
// are its clients through this function.
template <class K>
Simulation<typename K::Time> simulate(const K& k, const scene::Scene& s, const Options& options,
                                      Observer<K>* observer) {
  Kinetic_kvd<K> run(k, s, options, observer);
  while (run.advance()) {
  }
  return run.record();
}

#define KVD_INSTANTIATE_SIMULATE(K) \
  template Simulation<K::Time> simulate<K>(const K&, const scene::Scene&, const Options&, Observer<K>*);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SIMULATE)

}  // namespace kinetic

}  // namespace kvd
