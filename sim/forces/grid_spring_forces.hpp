// The row-sweep spring kernel for grid cloths: the same physics as spring_forces.hpp (Hooke plus
// along-spring damping), with the neighbours of one grid row under one stencil offset read as a
// contiguous run of memory. No index array and no gathers: the loop streams and vectorises fully
// (docs/design.md, performance notes: the fastest of the layouts measured for the seed stencil).
#pragma once

#include <algorithm>
#include <cmath>

#include "sim/model/model.hpp"

namespace clothlab {

// Adds the spring forces on the vertices of row j of grid g to f.
template <class T, bool Damped>
void add_grid_row_spring_forces(const GridStencil<T>& g, const Vec3Array<T>& x,
                                const Vec3Array<T>& v, Vec3Array<T>& f, int j) {
  const std::size_t row = static_cast<std::size_t>(g.offset) + static_cast<std::size_t>(j) * g.nu;
  T* __restrict fx = f.x.data() + row;
  T* __restrict fy = f.y.data() + row;
  T* __restrict fz = f.z.data() + row;
  for (const auto& e : g.entries) {
    if (j + e.dj < 0 || j + e.dj >= g.nv) continue;
    const int lo = std::max(0, -e.di), hi = std::min(g.nu, g.nu - e.di);
    const T* ax = x.x.data() + row;
    const T* ay = x.y.data() + row;
    const T* az = x.z.data() + row;
    const T* bx = ax + e.shift;
    const T* by = ay + e.shift;
    const T* bz = az + e.shift;
    const T* avx = v.x.data() + row;
    const T* avy = v.y.data() + row;
    const T* avz = v.z.data() + row;
    const T* bvx = avx + e.shift;
    const T* bvy = avy + e.shift;
    const T* bvz = avz + e.shift;
    const T k = e.stiffness, rest = e.rest_length, c = e.damping;
#pragma omp simd
    for (int i = lo; i < hi; ++i) {
      const T dx = bx[i] - ax[i], dy = by[i] - ay[i], dz = bz[i] - az[i];
      const T len = std::sqrt(dx * dx + dy * dy + dz * dz);
      const T inv_len = len > T(0) ? T(1) / len : T(0);
      T scale = k * (len - rest) * inv_len;
      if constexpr (Damped) {
        const T rvx = bvx[i] - avx[i], rvy = bvy[i] - avy[i], rvz = bvz[i] - avz[i];
        scale += c * (rvx * dx + rvy * dy + rvz * dz) * inv_len * inv_len;
      }
      fx[i] += scale * dx;
      fy[i] += scale * dy;
      fz[i] += scale * dz;
    }
  }
}

}  // namespace clothlab
