// The 4x4 determinant over any commutative ring R (numbers or time
// polynomials): the thesis's `coplanar` primitive (equation 6.3) when the rows
// are four homogeneous points.
#pragma once

#include <array>

namespace kvd {

template <class R>
using Matrix4 = std::array<std::array<R, 4>, 4>;

// Laplace expansion by the 2x2 minors of the first two rows against those of
// the last two: 12 products of minors instead of 24 products of four entries.
template <class R>
R det4(const Matrix4<R>& m) {
  // Returns R, not auto: GMP expression templates would dangle.
  auto minor = [&](int r, int i, int j) -> R { return m[r][i] * m[r + 1][j] - m[r][j] * m[r + 1][i]; };
  R s = minor(0, 0, 1) * minor(2, 2, 3);
  s -= minor(0, 0, 2) * minor(2, 1, 3);
  s += minor(0, 0, 3) * minor(2, 1, 2);
  s += minor(0, 1, 2) * minor(2, 0, 3);
  s -= minor(0, 1, 3) * minor(2, 0, 2);
  s += minor(0, 2, 3) * minor(2, 0, 1);
  return s;
}

}  // namespace kvd
