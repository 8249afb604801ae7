#include "gpu/backend_solver.hpp"

#include <stdexcept>

#include "gpu/gpu_step.hpp"
#include "sim/scene/parameter_keys.hpp"
#include "sim/solver_impl.hpp"

namespace clothlab::gpu {

std::string gpu_unsupported_reason(const Scene& scene) {
  // What transform feedback cannot run is refused when the scene is validated.
  if (scene.solver.backend == Backend::transform_feedback) return {};
  const IntegratorKind k = scene.solver.integrator;
  if (k != IntegratorKind::symplectic_euler && k != IntegratorKind::verlet)
    return std::string("the GPU step runs symplectic_euler and verlet, not ") + to_string(k);
  if (scene.solver.precision == Precision::f64) return "the GPU step computes in float, not double";
  return {};
}

std::unique_ptr<Solver> make_gpu_solver(const Scene& scene) {
  if (const std::string why = gpu_unsupported_reason(scene); !why.empty())
    throw std::invalid_argument(why);
  auto solver = std::make_unique<SolverT<float>>(scene, SpringKernel::neighbour_list);
  const IntegratorKind kind = scene.solver.integrator;
  if (scene.solver.backend == Backend::transform_feedback)
    solver->set_step_backend(std::make_unique<TfStep>(solver->model(), solver->state(), kind));
  else
    solver->set_step_backend(std::make_unique<GpuStep>(solver->model(), solver->state(), kind));
  return solver;
}

std::string cpu_fallback_note(Backend backend, const std::string& why) {
  const Parameter& key = *find_parameter(Section::solver, key_of<&SolverSpec::backend>());
  return parameter_path(key) + " = \"" + to_string(backend) + "\": " + why +
         "; the cloth steps on the CPU";
}

}  // namespace clothlab::gpu
