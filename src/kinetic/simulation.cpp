#include "kvd/kinetic/simulation.hpp"

#include "kvd/detail/kernel/instantiate.hpp"
#include "simulator.hpp"

namespace kvd::kinetic {

mpq_class rational_between(const Exact_time& a, const Exact_time& b) {
  for (;;) {
    const mpq_class lo = a.is_rational() ? a.rational() : a.upper();
    const mpq_class hi = b.is_rational() ? b.rational() : b.lower();
    if (lo < hi) return (lo + hi) / 2;
    a.refine();
    b.refine();
  }
}

template <class K>
Simulation<typename K::Time> simulate(const K& k, const scene::Scene& s, const Options& options,
                                      Observer<K>* observer) {
  return detail::Simulator<K>(k, s, options, observer).run();
}

#define KVD_INSTANTIATE_SIMULATE(K) \
  template Simulation<K::Time> simulate<K>(const K&, const scene::Scene&, const Options&, Observer<K>*);
KVD_FOR_EACH_KERNEL(KVD_INSTANTIATE_SIMULATE)

}  // namespace kvd::kinetic
