// The one place a solver is made for a scene on the backend it names: the CPU solver
// (sim/solver.hpp), or for solver.backend = "gpu" the CPU solver with its integrator on the GPU
// step (gpu/backend_solver.hpp). The applications and the tests make their solvers here; this
// header includes no GL header, so a program that draws nothing (a trace) needs none.
#pragma once

#include <memory>
#include <string>

#include "sim/solver.hpp"

namespace clothlab {

// The solver for `scene`, for solver.backend = "gpu" in the GL context current on the calling
// thread. When the GPU cannot run the scene (integrator, precision, no compute shaders) it is
// the CPU solver, and `note` says why in one line; else `note` is empty.
std::unique_ptr<Solver> make_backend_solver(const Scene& scene, std::string& note);

// A headless GL context of a solver's own (EGL), for programs that draw nothing.
struct OwnedGlContext;
struct OwnedGlContextDeleter {
  void operator()(OwnedGlContext* context) const;
};
using GlContextHandle = std::unique_ptr<OwnedGlContext, OwnedGlContextDeleter>;

// make_backend_solver() for a program without a GL context: a scene asking for the GPU first
// gets a headless context, held in `context`, which must outlive the solver; where none can be
// made, the CPU solver and the reason in `note`.
std::unique_ptr<Solver> make_headless_backend_solver(const Scene& scene, GlContextHandle& context,
                                                     std::string& note);

}  // namespace clothlab
