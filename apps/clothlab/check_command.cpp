#include <cstdio>

#include "apps/clothlab/commands.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/solver.hpp"

namespace clothlab::app {

int run_check(const CheckArgs& args) {
  try {
    const Scene scene = parse_scene_file(args.scene, args.overrides);
    // Building the solver proves the scene is simulable (springs, pins, tables all fit).
    const auto solver = make_solver(scene);
    std::printf("%s: ok (%zu cloth(s), %zu vertices, %zu springs, %s, dt = %g s)\n",
                args.scene.c_str(), scene.cloths.size(), solver->vertex_count(),
                solver->spring_count(), to_string(scene.solver.integrator), scene.solver.dt);
    return 0;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "clothlab check: %s\n", e.what());
    return 2;
  }
}

}  // namespace clothlab::app
