#include <cstdio>

#include "apps/clothlab/commands.hpp"
#include "sim/scene/parameters.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/solver.hpp"
#include "sim/stability/step_advice.hpp"

namespace clothlab::app {

int run_check(const CheckArgs& args) {
  const std::optional<Scene> scene = load_scene("check", args.scene, args.overrides);
  if (!scene) return kBadInput;
  // Building the solver proves the scene is simulable (springs, pins, tables all fit).
  const auto solver = make_solver(*scene);
  char substeps[48] = "";
  if (solver->substeps() > 1)
    std::snprintf(substeps, sizeof substeps, " in %d substeps", solver->substeps());
  std::printf("%s: ok (%zu cloth(s), %zu vertices, %zu springs, %s, dt = %g s%s%s)\n",
              args.scene.c_str(), scene->cloths.size(), solver->vertex_count(),
              solver->spring_count(), to_string(scene->solver.integrator), solver->dt(),
              scene->solver.dt_auto ? " (auto)" : "", substeps);
  // The scene is valid, but a fixed step above an explicit method's limit will diverge: said
  // here, before a run finds it out.
  if (const auto advice = step_advice(*scene); advice && advice->above())
    std::printf("%s: warning: %s\n", args.scene.c_str(),
                step_advice_line(*advice, scene->solver.integrator).c_str());
  return 0;
}

// The parameter table, as the key table in docs/scene-format.md holds it.
int run_params() {
  std::fputs(parameters_markdown().c_str(), stdout);
  return 0;
}

}  // namespace clothlab::app
