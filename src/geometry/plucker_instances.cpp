// The Plücker templates, compiled once for every ring of every kernel and
// for the rings of the symbolic perturbation.
#include "kvd/detail/geometry/plucker_impl.hpp"
#include "kvd/detail/kernel/instantiate.hpp"

#define KVD_INSTANTIATE_PLUCKER(R)                                                           \
  template kvd::Line<R> kvd::join(const Point4<R>&, const Point4<R>&);                       \
  template kvd::Plane4<R> kvd::join(const Line<R>&, const Point4<R>&);                       \
  template kvd::Plane4<R> kvd::join(const Point4<R>&, const Point4<R>&, const Point4<R>&);   \
  template kvd::Point4<R> kvd::meet(const Line<R>&, const Plane4<R>&);                       \
  template kvd::Point4<R> kvd::meet(const Plane4<R>&, const Plane4<R>&, const Plane4<R>&);   \
  template R kvd::dot(const Plane4<R>&, const Point4<R>&);                                   \
  template R kvd::coplanar(const Point4<R>&, const Point4<R>&, const Point4<R>&, const Point4<R>&);

namespace kvd {
KVD_FOR_EACH_RING(KVD_INSTANTIATE_PLUCKER)
KVD_FOR_EACH_PERTURBED_RING(KVD_INSTANTIATE_PLUCKER)
}
