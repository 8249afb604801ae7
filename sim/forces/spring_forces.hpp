// Spring forces gathered per vertex over the neighbour table (Model<T>).
// Hooke: F_i += k (|d| - L) d/|d|, with d = x_j - x_i.
// Along-spring damping (docs/design.md): F_i += c ((v_j - v_i) . d^) d^, i.e. -c ((v_i - v_j) . n)
// n. Both ends compute the same expression with d negated, so F_ij = -F_ji exactly (momentum).
#pragma once

#include <cmath>
#include <cstddef>

#include "sim/model/model.hpp"

namespace clothlab {

// Adds the spring forces on vertices [begin, end) to f. Slot-major loops: for each slot the
// inner loop runs over consecutive vertices, which vectorises (neighbours are gathered).
template <class T, bool Damped>
void add_spring_forces(const Model<T>& m, const Vec3Array<T>& x, const Vec3Array<T>& v,
                       Vec3Array<T>& f, std::size_t begin, std::size_t end) {
  const std::size_t n = m.n;
  const T* __restrict px = x.x.data();
  const T* __restrict py = x.y.data();
  const T* __restrict pz = x.z.data();
  const T* __restrict vx = v.x.data();
  const T* __restrict vy = v.y.data();
  const T* __restrict vz = v.z.data();
  T* __restrict fx = f.x.data();
  T* __restrict fy = f.y.data();
  T* __restrict fz = f.z.data();
  for (int s = 0; s < m.slots; ++s) {
    const std::size_t base = static_cast<std::size_t>(s) * n;
    const std::int32_t* __restrict nb = m.neighbour.data() + base;
    const T* __restrict ks = m.stiffness.data() + base;
    const T* __restrict rest = m.rest_length.data() + base;
    const T* __restrict cs = m.damping.data() + base;
#pragma omp simd
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t j = static_cast<std::size_t>(nb[i]);
      const T dx = px[j] - px[i], dy = py[j] - py[i], dz = pz[j] - pz[i];
      const T len = std::sqrt(dx * dx + dy * dy + dz * dz);
      // Padding entries (j == i) have len = 0 and k = 0: the select keeps them at zero force.
      const T inv_len = len > T(0) ? T(1) / len : T(0);
      T scale = ks[i] * (len - rest[i]) * inv_len;
      if constexpr (Damped) {
        const T rvx = vx[j] - vx[i], rvy = vy[j] - vy[i], rvz = vz[j] - vz[i];
        scale += cs[i] * (rvx * dx + rvy * dy + rvz * dz) * inv_len * inv_len;
      }
      fx[i] += scale * dx;
      fy[i] += scale * dy;
      fz[i] += scale * dz;
    }
  }
}

}  // namespace clothlab
