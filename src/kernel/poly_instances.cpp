// Poly<FT>, compiled once for every kernel's field.
#include "kvd/detail/kernel/instantiate.hpp"

#define KVD_INSTANTIATE_POLY(FT) template class kvd::Poly<FT>;
KVD_FOR_EACH_FIELD(KVD_INSTANTIATE_POLY)
