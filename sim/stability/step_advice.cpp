#include "sim/stability/step_advice.hpp"

#include <cstdio>

#include "sim/model/model.hpp"
#include "sim/stability/spectrum.hpp"
#include "sim/stability/step_limit.hpp"

namespace clothlab {

std::optional<StepAdvice> step_advice(const Scene& scene) {
  const SolverSpec& s = scene.solver;
  if (!is_explicit(s.integrator) || s.dt_auto) return std::nullopt;
  const Spectrum spectrum = estimate_spectrum(build_model<double>(scene));
  StepAdvice a;
  a.step = s.dt / double(s.substeps > 0 ? s.substeps : 1);
  a.limit = stable_step_limit(s.integrator, spectrum.omega_max, spectrum.gamma_max);
  a.auto_dt = choose_step(s.integrator, spectrum).dt;
  return a;
}

std::string step_advice_line(const StepAdvice& advice, IntegratorKind kind) {
  char line[256];
  if (!(advice.limit > 0.0)) {  // explicit Euler without damping: no step is stable
    std::snprintf(line, sizeof line,
                  "%s has no stable step on this scene (it needs damping); solver.dt = \"auto\" "
                  "takes %.3g s",
                  to_string(kind), advice.auto_dt);
    return line;
  }
  std::snprintf(line, sizeof line,
                "a step of %.3g s is above %s's stability limit on this scene (%.3g s); "
                "solver.dt = \"auto\" takes %.3g s",
                advice.step, to_string(kind), advice.limit, advice.auto_dt);
  return line;
}

}  // namespace clothlab
