// Whether a scene's fixed step is above its explicit method's stability limit, said before a run
// (`clothlab check`) and after one that diverged (`clothlab trace`).
#pragma once

#include <optional>
#include <string>

#include "sim/scene/scene.hpp"

namespace clothlab {

struct StepAdvice {
  double step = 0.0;     // s, the integrator's step: dt over the substeps
  double limit = 0.0;    // s, the method's stability limit on this scene (0: no step is stable)
  double auto_dt = 0.0;  // s, what dt = "auto" takes
  bool above() const { return step > limit; }
};

// For an explicit method with a fixed dt: its step, its limit on the scene's stiffest mode
// (sim/stability/step_limit.hpp) and dt = "auto"'s choice; nothing for the large-step methods
// and for dt = "auto".
std::optional<StepAdvice> step_advice(const Scene& scene);

// One line: "a step of 0.01 s is above symplectic_euler's stability limit on this scene
// (0.000786 s); solver.dt = \"auto\" takes 0.00062 s", or that the method has no stable step.
std::string step_advice_line(const StepAdvice& advice, IntegratorKind kind);

}  // namespace clothlab
