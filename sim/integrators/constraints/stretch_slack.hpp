// The strain the stretch limits (tethers.hpp, coarse_stretch.hpp) allow a cloth at substep h
// (issue 54; docs/solver.md, "Stretch limits that let go"). A limit with no slack forbids the
// stretch the material really has (1-3 % along the tethers of the swinging accuracy sheet, whose
// static strain is 0.2 %), so its error stops falling at a floor however many substeps run: on
// that sheet in double, 4-5 mm at 0.2 s and 16-35 mm at 1 s from 20 to 320 substeps. The limits
// are there because one Gauss-Seidel sweep a substep carries a pin's hold only a vertex or two
// across the grid; the more sweeps a frame per vertex of the side, the less the sweeps need them.
// So the slack grows with the sweeps per frame beyond the automatic ten, per vertex of the side,
// in units of the cloth's static strain:
//   s(h) = kSlackGain * static_strain * max(0, kSlackFreeSubstep / h - 1) / side,
// none at xpbd's automatic substep (the defaults have none) and without bound as h -> 0,
// where the sweeps alone converge. kSlackGain is fitted on the accuracy sheet at 32^2, 64^2 and
// 256^2 (the best slack at 20-160 substeps grew with the substeps and fell with the side: 0.01-0.02
// at 32^2 and 80 substeps, 0.001-0.0025 at 256^2).
#pragma once

namespace clothlab {

// s: xpbd's automatic substep on the grids that get stretch limits (ten per 1/60 s frame).
inline constexpr double kSlackFreeSubstep = 1.0 / 600.0;
inline constexpr double kSlackGain = 32.0;

// The allowed strain; `side` is the cloth's longer side in vertices.
inline double stretch_slack(double static_strain, int side, double h) {
  if (!(h > 0.0) || side <= 0) return 0.0;
  // The automatic substep in float or written with a few digits is none beyond it.
  const double beyond = kSlackFreeSubstep / h - 1.0;
  if (!(beyond > 1e-6)) return 0.0;
  return kSlackGain * static_strain * beyond / double(side);
}

// What the slack of one cloth reads of it, kept by each stretch limit that holds the cloth.
struct ClothSlack {
  double strain = 0.0;  // static_strain() of the cloth (tethers.hpp)
  int side = 0;         // its longer side in vertices
  // 1 + the slack at substep h: a limit holds at rest * scale.
  double scale(double h) const { return 1.0 + stretch_slack(strain, side, h); }
};

}  // namespace clothlab
