// Stability limits of the explicit integrators on the damped oscillator x'' = -w^2 x - g x'
// (the linearised cloth is a set of such modes), and the step `dt = "auto"` chooses.
#pragma once

#include "sim/scene/scene.hpp"
#include "sim/stability/spectrum.hpp"

namespace clothlab {

// Spectral radius of one step of `kind` (an explicit method) on the damped oscillator.
double amplification(IntegratorKind kind, double h, double omega, double gamma);

// The largest h with amplification <= 1 (bisection; 0 where none exists, as for explicit Euler
// without damping). Only for explicit methods.
double stable_step_limit(IntegratorKind kind, double omega, double gamma);

struct StepChoice {
  double dt = 0.0;     // s, one solver step
  int substeps = 1;    // integrator steps per solver step
  Spectrum spectrum;   // what the choice was made from
  double limit = 0.0;  // s, the explicit (symplectic Euler) stability limit of the scene
};

// What `solver.dt = "auto"` picks (docs/solver.md, "Choosing the step"):
//  - explicit methods: kAutoSafety times the method's own limit (for explicit Euler without
//    damping, which no step makes stable, a tenth of symplectic Euler's), rounded down to two
//    significant digits;
//  - large-step methods: a fixed display-rate step; xpbd's substeps are solver.substeps' own
//    choice (auto_substeps below), so StepChoice::substeps is 1.
inline constexpr double kAutoSafety = 0.8;
// s: implicit_euler and local_global (vbd and bdf2 take the display step, 1/60 s)
inline constexpr double kImplicitStep = 1.0 / 120.0;
StepChoice choose_step(IntegratorKind kind, const Spectrum& spectrum);

// `solver.substeps = "auto"` (the default): 1 for every method but xpbd, which takes at least
// kXpbdMinSubsteps substeps per 1/60 s and one more per kXpbdSideVertices vertices of
// `longest_side`, scaled to the step, at most kXpbdMaxSubsteps. longest_side counts only cloths
// whose sweeps must carry corrections across them alone: the solver leaves out grids with
// coarse stretch levels (sim/integrators/constraints/coarse_stretch.hpp), which carry them.
// Measured on the accuracy sheet (k0 = 1e3, tethers on, RMS at 0.2 s from RK4; docs/solver.md,
// "Small steps at scale"): without levels the error stops falling at about 3-4 mm once the substeps
// reach a tenth to an eighth of the side; with them 10 substeps land 3.5 / 4.0 / 4.7 mm at 64^2 /
// 128^2 / 256^2. Stiffness changes it little once tethers carry the stretch (32^2 at 0.5 s, 10 ->
// 20 substeps: k0 = 1e3 10.4 -> 6.3 mm, 1e5 27.3 -> 25.9 mm).
inline constexpr int kXpbdMinSubsteps = 10;
inline constexpr int kXpbdSideVertices = 10;
inline constexpr int kXpbdMaxSubsteps = 200;
int auto_substeps(IntegratorKind kind, double dt, int longest_side);

}  // namespace clothlab
