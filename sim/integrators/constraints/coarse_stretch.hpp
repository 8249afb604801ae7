// Coarse stretch levels (after Mueller 2008, "Hierarchical position based dynamics"): after
// xpbd's fine sweep, a grid cloth's positions are restricted to grids of every second vertex
// (2x coarsening while the coarse grid keeps at least kCoarseMinSide vertices a side), one-sided
// distance constraints along each coarse grid's axes and diagonals are projected from the
// coarsest level up (kCoarseSweeps Gauss-Seidel sweeps a level), and each level's displacement
// is prolonged bilinearly to the next finer one and at last to the cloth. A coarse constraint
// only shortens a coarse edge longer than at rest, so, like the tethers (tethers.hpp), it acts
// where the fine sweeps left the sheet stretched, and it carries the correction across the
// sheet 2^levels times faster than a fine sweep does. The same cloths as the tethers get it (a
// flat grid its own weight stretches by under 1 %). docs/solver.md, "Small steps at scale", has
// the measurements: on the 256^2 accuracy sheet with tethers 10 substeps land 4.7 mm from RK4
// with the levels and 25.3 mm without.
//
// Each level's constraints run in 8 passes (4 offsets x 2 parity classes of the row, or of the
// column for the row's own offset) whose constraints share no vertex; a pass is one parallel loop
// over rows of contiguous (or every-second) vertices, so the result is the same bits on any
// thread count. A grid's spacing is uniform, so each offset has one rest length.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/integrators/constraints/stretch_slack.hpp"
#include "sim/model/model.hpp"

namespace clothlab {

inline constexpr int kCoarseMinSide = 32;
inline constexpr int kCoarseSweeps = 2;

// The levels one cloth of nu x nv vertices gets (0 below 2 kCoarseMinSide a side).
int coarse_level_count(int nu, int nv);

template <class T>
class CoarseStretch {
 public:
  CoarseStretch() = default;
  explicit CoarseStretch(const Model<T>& m);
  bool empty() const { return cloths_.empty(); }

  // Restrict, project, prolong into pos. Called by every thread of a parallel region (its loops
  // are orphaned `omp for` with their barriers), or outside one on a single thread.
  void apply(Vec3Array<T>& pos, const T* inv_mass);
  // The substep's length, for the slack each cloth's levels allow (stretch_slack.hpp): before
  // apply(), outside the parallel region.
  void set_substep(double h);

 private:
  struct Level {
    int nu = 0, nv = 0;
    std::vector<std::int32_t> fine;  // the model's vertex under each coarse vertex
    T rest[4] = {};                  // rest length of each coarse offset
    T limit[4] = {};                 // the longest it may be at this substep (rest * (1 + slack))
    Vec3Array<T> x, x0;              // positions now and as restricted
    AlignedVector<T> w;              // inverse masses (0: pinned)
  };
  struct Cloth {
    int offset = 0, nu = 0, nv = 0;
    std::vector<Level> levels;  // finest coarse level first
    ClothSlack slack;           // of the cloth
  };
  void restrict_positions(Cloth& c, const Vec3Array<T>& pos, const T* inv_mass);
  void project(Level& l);
  void project_rows(Level& l, int o, int cls);
  // Adds coarse level c's displacement, bilinearly interpolated, to the nu x nv grid (x, w).
  void prolong(const Level& c, int nu, int nv, T* x, T* y, T* z, const T* w);

  std::vector<Cloth> cloths_;
};

}  // namespace clothlab
