#include "sim/push_region.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace clothlab {

PushRegion default_push_region(const SolverState& solver) {
  const std::size_t n = solver.vertex_count();
  std::vector<float> xyz(3 * n);
  solver.copy_positions(xyz.data());
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  PushRegion region;
  for (std::size_t v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      const double x = xyz[3 * v + std::size_t(k)];
      lo[k] = std::min(lo[k], x);
      hi[k] = std::max(hi[k], x);
      region.center[k] += x / double(n);
    }
  }
  const double diagonal =
      std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
  region.radius = std::max(0.05, 0.25 * diagonal);
  return region;
}

}  // namespace clothlab
