// Length and direction of a 3-vector given as std::array<double, 3> (the scene's Vec3d), computed
// with the largest component scaled out first so that a vector whose squared length overflows a
// double ([1e200, 0, 0]) still has its length and direction (Blue 1978's scaled norm; the same
// reason Eigen has stableNorm).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace clothlab {

// Where the plain sum of squares neither overflows nor underflows, the plain formula is used, so a
// scene's usual axes keep their bits.
inline double scaled_length(const std::array<double, 3>& a) {
  const double squares = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
  if (std::isnormal(squares) && std::isfinite(squares)) return std::sqrt(squares);
  const double m = std::max({std::abs(a[0]), std::abs(a[1]), std::abs(a[2])});
  if (!(m > 0.0) || !std::isfinite(m)) return m;
  const double x = a[0] / m, y = a[1] / m, z = a[2] / m;
  return m * std::sqrt(x * x + y * y + z * z);
}

// The unit vector along a (a must be non-zero and finite).
inline std::array<double, 3> normalised(const std::array<double, 3>& a) {
  const double len = scaled_length(a);
  return {a[0] / len, a[1] / len, a[2] / len};
}

}  // namespace clothlab
