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
//    fixed multiple of the explicit limit.
inline constexpr double kAutoSafety = 0.8;
inline constexpr double kXpbdSubstepLimits = 2.0;  // xpbd substep in explicit limits
// s: implicit_euler and local_global (vbd and bdf2 take the display step, 1/60 s)
inline constexpr double kImplicitStep = 1.0 / 120.0;
StepChoice choose_step(IntegratorKind kind, const Spectrum& spectrum);

}  // namespace clothlab
