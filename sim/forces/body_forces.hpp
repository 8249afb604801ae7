// Gravity and linear drag per vertex, the forces that need no neighbour: the first writer of f
// in every force pass (the springs and the wind add to it).
#pragma once

#include <cstddef>

#include "sim/model/model.hpp"

namespace clothlab {

// f = gravity and/or linear drag on [b, e) (overwrites). The default, both fused, is the step
// loop's; one alone serves compute_force_source.
template <class T, bool Gravity = true, bool Drag = true>
void add_body_forces(const Model<T>& m, const Vec3Array<T>& v, Vec3Array<T>& f, std::size_t b,
                     std::size_t e) {
  static_assert(Gravity || Drag);
  const T gx = m.gravity[0], gy = m.gravity[1], gz = m.gravity[2], drag = m.drag;
#pragma omp simd
  for (std::size_t i = b; i < e; ++i) {
    const T mi = m.mass[i];
    if constexpr (Gravity && Drag) {
      f.x[i] = mi * gx - drag * v.x[i];
      f.y[i] = mi * gy - drag * v.y[i];
      f.z[i] = mi * gz - drag * v.z[i];
    } else if constexpr (Gravity) {
      f.x[i] = mi * gx;
      f.y[i] = mi * gy;
      f.z[i] = mi * gz;
    } else {
      f.x[i] = -(drag * v.x[i]);
      f.y[i] = -(drag * v.y[i]);
      f.z[i] = -(drag * v.z[i]);
    }
  }
}

template <class T>
void zero_forces(Vec3Array<T>& f, std::size_t b, std::size_t e) {
#pragma omp simd
  for (std::size_t i = b; i < e; ++i) {
    f.x[i] = T(0);
    f.y[i] = T(0);
    f.z[i] = T(0);
  }
}

}  // namespace clothlab
