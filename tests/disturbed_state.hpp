// A state off rest for kernel and integrator comparisons: every spring stretched or compressed
// and moving, every free vertex with its own velocity (smooth in the index, so no two alike).
#pragma once

#include <cmath>

#include "sim/integrators/integrator.hpp"

namespace clothlab {

template <class T>
State<T> disturbed(const Model<T>& m) {
  State<T> s{m.rest_positions, {}};
  s.vel.resize(m.n);
  for (std::size_t i = 0; i < m.n; ++i) {
    const double u = double(i);
    s.pos.x[i] += T(0.01 * std::sin(0.7 * u));
    s.pos.z[i] += T(0.02 * std::cos(1.1 * u));
    if (m.inv_mass[i] != T(0))
      s.vel.set(i, T(0.3 * std::sin(1.3 * u)), T(-0.5 + 0.2 * std::cos(0.9 * u)),
                T(0.4 * std::sin(2.1 * u)));
  }
  return s;
}

}  // namespace clothlab
