// Mechanical energy of the cloth, accumulated in double whatever the solver's scalar type.
//   kinetic  = sum 1/2 m |v|^2
//   elastic  = sum over springs 1/2 k (|x_b - x_a| - L)^2
//   gravity  = -sum m g . x   (zero at the origin)
// Sums run per block and then in block order, so the value is the same for any thread count.
#pragma once

#include <vector>

#include "sim/integrators/integrator.hpp"

namespace clothlab {

struct Energy {
  double kinetic = 0.0, elastic = 0.0, gravity = 0.0;
  double total() const { return kinetic + elastic + gravity; }
};

// `partials` is scratch space (resized on first use, then reused without allocating).
template <class T>
Energy compute_energy(const Model<T>& m, const State<T>& s, std::vector<double>& partials,
                      int threads);

}  // namespace clothlab
