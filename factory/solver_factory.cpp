#include "factory/solver_factory.hpp"

#include "gl/gl_error.hpp"
#include "gl/headless_context.hpp"
#include "gpu/backend_solver.hpp"

namespace clothlab {

struct OwnedGlContext {
  vis::HeadlessContext context;
};

void OwnedGlContextDeleter::operator()(OwnedGlContext* context) const {
  delete context;
}

std::unique_ptr<Solver> make_backend_solver(const Scene& scene, std::string& note) {
  note.clear();
  if (scene.solver.backend == Backend::cpu) return make_solver(scene);
  std::string why = gpu::gpu_unsupported_reason(scene);
  if (why.empty()) {
    try {
      return gpu::make_gpu_solver(scene);
    } catch (const vis::GlUnavailable& e) {
      why = e.what();
    }
  }
  note = gpu::cpu_fallback_note(scene.solver.backend, why);
  return make_solver(scene);
}

std::unique_ptr<Solver> make_headless_backend_solver(const Scene& scene, GlContextHandle& context,
                                                     std::string& note) {
  // A context only where the GPU could run the scene; else make_backend_solver says why not.
  if (scene.solver.backend != Backend::cpu && gpu::gpu_unsupported_reason(scene).empty() &&
      !context) {
    try {
      context.reset(new OwnedGlContext{});
    } catch (const vis::GlUnavailable& e) {
      note = gpu::cpu_fallback_note(scene.solver.backend, e.what());
      return make_solver(scene);
    }
  }
  return make_backend_solver(scene, note);
}

}  // namespace clothlab
