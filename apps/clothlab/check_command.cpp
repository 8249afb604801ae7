#include <cstdio>

#include "apps/clothlab/commands.hpp"
#include "apps/clothlab/memory_check.hpp"
#include "sim/model/build_estimate.hpp"
#include "sim/scene/parameters.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/solver.hpp"
#include "sim/stability/step_advice.hpp"

namespace clothlab::app {

namespace {

// s: `check` builds a scene estimated to take longer than this only when forced, so that it
// answers within seconds for any size (sim/model/build_estimate.hpp).
constexpr double kMaxCheckBuild = 60.0;

}  // namespace

int run_check(const CheckArgs& args) {
  const std::optional<Scene> scene = load_scene("check", args.scene, args.overrides);
  if (!scene) return kBadInput;
  if (estimated_build_seconds(*scene) > kMaxCheckBuild && !args.force) {
    const SceneError e = size_error(*scene, "the scene needs " + build_needs(*scene) +
                                                "; check builds one over a minute only with "
                                                "--force");
    std::fprintf(stderr, "clothlab check: %s\n", e.what());
    return kBadInput;
  }
  std::printf("%s: needs %s\n", args.scene.c_str(), build_needs(*scene).c_str());
  std::fflush(stdout);  // said before a long build
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
