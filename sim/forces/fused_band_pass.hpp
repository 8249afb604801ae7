// The force pass of a one-stage integrator and its per-vertex update in one sweep over a grid
// cloth's bands (issue 23): a band's rows are updated while they are still in cache, right after
// its springs, instead of in a second pass over the whole cloth, and the step is one parallel
// region instead of two (each region a thread wake-up and barriers).
//
// When a row may be updated: its force is complete once its own band's springs and the band
// before's (the halo on its first `reach` rows) are summed, and its old x and v may change only
// once no spring still reads them; springs run from a row to later rows, so only the band before
// reads a band's first `reach` rows. Each thread takes a contiguous run of bands in order, so
// within the run both hold as soon as a band's springs are done; the first `reach` rows of a
// run's first band wait for the barrier (the band before belongs to the thread before). Every
// vertex's force is summed in the same order as compute_forces (body forces, the band's springs,
// then the halo), so the step is the same bits as the unfused one on any thread count.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstddef>

#include "sim/core/parallel.hpp"
#include "sim/forces/body_forces.hpp"
#include "sim/forces/force_field.hpp"
#include "sim/forces/grid_spring_forces.hpp"

namespace clothlab {

// The sweep serves forces that are springs, gravity and drag on grid bands: the row-sweep kernel
// without wind (the wind needs every vertex normal before any force).
template <class T>
bool band_pass_fusable(const Model<T>& m) {
  return m.kernel == SpringKernel::row_sweep && !m.grids.empty() && !wind_acts(m);
}

namespace detail {

// Band b's springs, then what of it may be updated now (see the file comment); `first` marks
// the first band of a thread's run.
template <class T, class Update>
void band_forces_then_update(const Model<T>& m, const GridStencil<T>& g, GridBands<T>& bands,
                             const Vec3Array<T>& x, const Vec3Array<T>& v, Vec3Array<T>& f, int b,
                             bool first, Update& update) {
  const int j0 = bands.first_row(b), j1 = bands.end_row(b, g.nv);
  const auto [begin, end] = grid_rows(g, j0, j1);
  add_body_forces(m, v, f, begin, end);
  add_band_spring_forces(g, bands, x, v, f, b, m.has_damping);
  if (b == 0) {
    update(begin, end);
  } else if (!first) {
    add_band_halo(g, bands, f, b);
    update(begin, end);
  } else {
    update(grid_rows(g, std::min(j0 + bands.reach, j1), j1).first, end);
  }
}

}  // namespace detail

// f = F(x, v) (springs, gravity, drag) and then update(b, e) on every vertex range [b, e) once
// its force is final; update may change x and v there. Requires band_pass_fusable(m).
template <class T, class Update>
void forces_then_update(const Model<T>& m, const Vec3Array<T>& x, const Vec3Array<T>& v,
                        Vec3Array<T>& f, ForceWorkspace<T>& ws, int threads, Update&& update) {
  for (std::size_t c = 0; c < m.grids.size(); ++c) {
    const GridStencil<T>& g = m.grids[c];
    GridBands<T>& bands = ws.grid_bands[c];
    const int count = bands.count;
    run_team(count > 1 ? threads : 1, [&] {
      const int nt = omp_get_num_threads(), t = omp_get_thread_num();
      const int b0 = count * t / nt, b1 = count * (t + 1) / nt;
      for (int b = b0; b < b1; ++b)
        detail::band_forces_then_update(m, g, bands, x, v, f, b, b == b0, update);
#pragma omp barrier
      if (b0 > 0 && b0 < b1) {
        add_band_halo(g, bands, f, b0);
        const int j0 = bands.first_row(b0);
        const int j1 = std::min(j0 + bands.reach, bands.end_row(b0, g.nv));
        const auto [begin, end] = grid_rows(g, j0, j1);
        update(begin, end);
      }
    });
  }
}

}  // namespace clothlab
