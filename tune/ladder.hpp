// The settings `clothlab tune` compares (docs/tuning.md, "The ladder"): every integrator family
// with the knob that trades its cost for accuracy, all at the display step of 1/60 s split into
// substeps, so that every run, the reference's included, reaches the same sample times exactly.
#pragma once

#include <vector>

#include "sim/stability/spectrum.hpp"
#include "tune/sampled_run.hpp"

namespace clothlab::tune {

inline constexpr double kFrame = 1.0 / 60.0;  // s: the display step every setting divides

// The reference: RK4 in double at `fraction` of its stability limit (Spectrum), the step
// rounded down to divide a frame; `halved` gives the same at half that step.
Setting reference_setting(const Spectrum& spectrum, double fraction, bool halved);
// Its steps a frame: the frame divided by the step, rounded up.
int reference_substeps(const Spectrum& spectrum, double fraction, bool halved);

// The ladder, cheapest knob first within each family:
//  explicit:    symplectic Euler (float) at 0.9 of its stability limit and at half that step,
//               in double at 0.9, Verlet (float) at 0.9, RK4 (float) at 0.9 of its own limit;
//  implicit:    implicit Euler at 1, 2 and 4 substeps a frame, BDF2 at 1 and 2 (float);
//  constraints: xpbd at "auto", 5, 10, 20, 40 and 80 substeps, and 10 and 20 with 2 iterations;
//  descent:     vbd at 10, 30 and 100 iterations, local-global at 10 and 30.
std::vector<Setting> ladder(const Spectrum& spectrum);

// Substeps of a frame for a step of at most `step` s (at least 1).
int substeps_for(double step);

}  // namespace clothlab::tune
