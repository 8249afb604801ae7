// Structure-of-arrays storage for per-vertex 3-vectors: x, y and z each contiguous and aligned,
// so the hot loops vectorise across vertices.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace clothlab {

template <class T>
using AlignedVector = std::vector<T, Eigen::aligned_allocator<T>>;

template <class T>
struct Vec3Array {
  AlignedVector<T> x, y, z;

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n, T value = T(0)) {
    x.assign(n, value);
    y.assign(n, value);
    z.assign(n, value);
  }
  void set(std::size_t i, T vx, T vy, T vz) {
    x[i] = vx;
    y[i] = vy;
    z[i] = vz;
  }
  AlignedVector<T>& axis(int a) { return a == 0 ? x : (a == 1 ? y : z); }
  const AlignedVector<T>& axis(int a) const { return a == 0 ? x : (a == 1 ? y : z); }
};

}  // namespace clothlab
