#include "sim/energy.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/parallel.hpp"

namespace clothlab {

namespace {

template <class T>
double stretch_energy(const Vec3Array<T>& x, std::size_t a, std::size_t b, double k, double rest) {
  const double dx = double(x.x[b]) - x.x[a], dy = double(x.y[b]) - x.y[a],
               dz = double(x.z[b]) - x.z[a];
  const double stretch = std::sqrt(dx * dx + dy * dy + dz * dz) - rest;
  return 0.5 * k * stretch * stretch;
}

// Elastic energy of row j of a grid: the springs to its first-half neighbours (each spring once).
template <class T>
double grid_row_elastic(const GridStencil<T>& g, const Vec3Array<T>& x, int j) {
  double sum = 0.0;
  const std::size_t row = static_cast<std::size_t>(g.offset) + static_cast<std::size_t>(j) * g.nu;
  for (const auto& e : g.entries) {
    if (!e.first_half || j + e.dj >= g.nv) continue;
    for (int i = std::max(0, -e.di); i < std::min(g.nu, g.nu - e.di); ++i) {
      const std::size_t a = row + static_cast<std::size_t>(i);
      sum += stretch_energy(x, a, static_cast<std::size_t>(static_cast<long>(a) + e.shift),
                            e.stiffness, e.rest_length);
    }
  }
  return sum;
}

// Elastic energy of vertices [b, e) from the neighbour table: each spring is listed at both of
// its ends, so half of 1/2 k stretch^2 from each.
template <class T>
double neighbour_list_elastic(const Model<T>& m, const Vec3Array<T>& x, std::size_t b,
                              std::size_t e) {
  double sum = 0.0;
  for (std::size_t i = b; i < e; ++i) {
    for (int slot = 0; slot < m.slots; ++slot) {
      const std::size_t k = static_cast<std::size_t>(slot) * m.n + i;
      sum += 0.5 * stretch_energy(x, i, static_cast<std::size_t>(m.neighbour[k]), m.stiffness[k],
                                  m.rest_length[k]);
    }
  }
  return sum;
}

}  // namespace

template <class T>
Energy compute_energy(const Model<T>& m, const State<T>& s, std::vector<double>& partials,
                      int threads) {
  const std::size_t blocks = block_count(m.n);
  std::size_t rows = 0;
  for (const auto& g : m.grids) rows += static_cast<std::size_t>(g.nv);
  partials.resize(std::max(3 * blocks, rows));
  const auto& x = s.pos;
  const auto& v = s.vel;
  const bool list = m.kernel == SpringKernel::neighbour_list;
  for_each_block_indexed(m.n, threads, [&](std::size_t blk, std::size_t b, std::size_t e) {
    double kinetic = 0.0, gravity = 0.0;
    for (std::size_t i = b; i < e; ++i) {
      const double mi = m.mass[i];
      kinetic +=
          0.5 * mi * (double(v.x[i]) * v.x[i] + double(v.y[i]) * v.y[i] + double(v.z[i]) * v.z[i]);
      gravity -= mi * (m.gravity[0] * double(x.x[i]) + m.gravity[1] * double(x.y[i]) +
                       m.gravity[2] * double(x.z[i]));
    }
    partials[3 * blk] = kinetic;
    partials[3 * blk + 1] = list ? neighbour_list_elastic(m, x, b, e) : 0.0;
    partials[3 * blk + 2] = gravity;
  });
  Energy out;
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    out.kinetic += partials[3 * blk];
    out.elastic += partials[3 * blk + 1];
    out.gravity += partials[3 * blk + 2];
  }
  if (list) return out;
  for (const auto& g : m.grids) {
    for_each_index(g.nv, threads, [&](int j) {
      partials[static_cast<std::size_t>(j)] = grid_row_elastic(g, x, j);
    });
    for (int j = 0; j < g.nv; ++j) out.elastic += partials[static_cast<std::size_t>(j)];
  }
  return out;
}

template Energy compute_energy<float>(const Model<float>&, const State<float>&,
                                      std::vector<double>&, int);
template Energy compute_energy<double>(const Model<double>&, const State<double>&,
                                       std::vector<double>&, int);

}  // namespace clothlab
