// solver.backend = "gpu" or "transform_feedback": the CPU solver (SolverT<float> over the neighbour
// list) with its integrator on the GPU step backend (gpu_step.hpp). Everything but the integrator
// is the CPU's own code: the step loop, the model, pins and their release, the grab, pushes,
// colliders, self-collision, moving pins and the divergence checks, on a mirror of the GPU's state
// refreshed only when something on the CPU reads it (docs/gpu-backend.md). The renderer draws
// from the solver's device_cloth(). Needs the GL context current on the calling thread for the
// solver's whole life.
#pragma once

#include <memory>
#include <string>

#include "sim/solver.hpp"

namespace clothlab::gpu {

// Why the GPU backend cannot run `scene` (one line), or empty when it can.
std::string gpu_unsupported_reason(const Scene& scene);

// The solver for `scene` stepping on the GPU, by compute shaders or (backend =
// "transform_feedback") transform feedback. Throws GlUnavailable without compute shaders,
// std::invalid_argument when gpu_unsupported_reason(scene) is not empty, SceneError as the CPU
// solver does.
std::unique_ptr<Solver> make_gpu_solver(const Scene& scene);

// The line said when solver.backend = `backend` cannot be honoured for reason `why`.
std::string cpu_fallback_note(Backend backend, const std::string& why);

}  // namespace clothlab::gpu
