#include "sim/energy.hpp"

#include <cmath>

#include "sim/core/parallel.hpp"

namespace clothlab {

template <class T>
Energy compute_energy(const Model<T>& m, const State<T>& s, std::vector<double>& partials,
                      int threads) {
  const std::size_t blocks = block_count(m.n);
  partials.resize(3 * blocks);
  const auto& x = s.pos;
  const auto& v = s.vel;
  for_each_block_indexed(m.n, threads, [&](std::size_t blk, std::size_t b, std::size_t e) {
    double kinetic = 0.0, elastic = 0.0, gravity = 0.0;
    for (std::size_t i = b; i < e; ++i) {
      const double mi = m.mass[i];
      kinetic +=
          0.5 * mi * (double(v.x[i]) * v.x[i] + double(v.y[i]) * v.y[i] + double(v.z[i]) * v.z[i]);
      gravity -= mi * (m.gravity[0] * double(x.x[i]) + m.gravity[1] * double(x.y[i]) +
                       m.gravity[2] * double(x.z[i]));
      // Each spring is listed at both of its ends: a quarter of k stretch^2 from each.
      for (int slot = 0; slot < m.slots; ++slot) {
        const std::size_t e_idx = static_cast<std::size_t>(slot) * m.n + i;
        const auto j = static_cast<std::size_t>(m.neighbour[e_idx]);
        const double dx = double(x.x[j]) - x.x[i], dy = double(x.y[j]) - x.y[i],
                     dz = double(x.z[j]) - x.z[i];
        const double stretch = std::sqrt(dx * dx + dy * dy + dz * dz) - m.rest_length[e_idx];
        elastic += 0.25 * m.stiffness[e_idx] * stretch * stretch;
      }
    }
    partials[3 * blk] = kinetic;
    partials[3 * blk + 1] = elastic;
    partials[3 * blk + 2] = gravity;
  });
  Energy out;
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    out.kinetic += partials[3 * blk];
    out.elastic += partials[3 * blk + 1];
    out.gravity += partials[3 * blk + 2];
  }
  return out;
}

template Energy compute_energy<float>(const Model<float>&, const State<float>&,
                                      std::vector<double>&, int);
template Energy compute_energy<double>(const Model<double>&, const State<double>&,
                                       std::vector<double>&, int);

}  // namespace clothlab
