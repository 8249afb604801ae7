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

// What `solver.dt = "auto"` picks (README, "Choosing the step"):
//  - explicit methods: kAutoSafety times the method's own limit (for explicit Euler without
//    damping, which no step makes stable, a tenth of symplectic Euler's), rounded down to two
//    significant digits;
//  - large-step methods: a fixed display-rate step, subdivided (xpbd) so that each substep is a
//    fixed multiple of the explicit limit, in at most kXpbdMaxSubsteps substeps.
inline constexpr double kAutoSafety = 0.8;
inline constexpr double kXpbdSubstepLimits = 2.0;  // xpbd substep in explicit limits
// Measured on the 32 x 32 accuracy sheet at 1/60 s (RMS at 0.5 s from RK4, README "Large
// steps"): with 20 / 40 / 80 substeps xpbd lands 17 / 7.2 / 3.3 mm away at k0 = 1e3 but 27.5 /
// 25.2 / 24.9 mm at k0 = 1e5, where the stiffness rule asks 297 substeps for 12.9 mm at 7.8x the
// cost of 40. Past about 30 substeps a stiff lattice gains little per substep (one sweep per
// substep leaves it as extensible as the substep allows), so the rule stops there; float and
// double agree to 0.3 mm up to 80 substeps, so the cap also keeps float's cancellation away.
inline constexpr int kXpbdMaxSubsteps = 40;
// s: implicit_euler and local_global (vbd and bdf2 take the display step, 1/60 s)
inline constexpr double kImplicitStep = 1.0 / 120.0;
StepChoice choose_step(IntegratorKind kind, const Spectrum& spectrum);

}  // namespace clothlab
