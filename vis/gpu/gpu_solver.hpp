// solver.backend = "gpu": the Solver whose cloth step runs as OpenGL compute shaders (GpuCloth).
// It is the CPU solver (SolverT<float> over the neighbour list) with its integrator replaced
// through SolverT's hooks: the step loop, model, pins, release, grab, colliders, self-collision,
// moving pins and the divergence checks are the CPU's own code, and the state lives on the GPU. The
// CPU keeps a mirror of it, refreshed only when something on the CPU needs it:
//  - the divergence checks, after every step when the mirror is current anyway, else once at the
//    end of each step() / advance() call (a frame's steps in the window);
//  - colliders, self-collision, moving pins and a grab, around each substep (their responses run
//    on the CPU and the corrected state goes back up);
//  - reads (positions, velocities, energy, traces) and writes (push, reset, load_state).
// The renderer draws from position_buffer() / the normal pass directly (Renderer::update_cloth).
// Needs the GL context current on the calling thread for its whole life.
#pragma once

#include <memory>
#include <string>

#include "sim/solver_impl.hpp"
#include "vis/gpu/gpu_cloth.hpp"

namespace clothlab::vis {

// Why the GPU backend cannot run `scene` (one line), or empty when it can.
std::string gpu_unsupported_reason(const Scene& scene);

class GpuSolver final : public SolverT<float> {
 public:
  // Throws GlUnavailable without compute shaders, std::invalid_argument when
  // gpu_unsupported_reason(scene) is not empty, SceneError as the CPU solver does.
  explicit GpuSolver(const Scene& scene);

  Vec3d position(int vertex) const override;
  Vec3d velocity(int vertex) const override;
  void update_force_field(ForceSource source = ForceSource::total) override;
  Energy energy() override;
  void apply_impulse(const Vec3d& center, double radius, const Vec3d& impulse) override;
  void copy_positions(float* xyz) const override;
  void copy_normals(float* xyz) override;
  void copy_velocities(float* xyz) const override;
  void load_state(const Solver& other) override;
  void reset() override;

  // The GPU side, for the renderer (buffers, normals) and tests.
  GpuCloth& gpu() { return gpu_; }
  const GpuCloth& gpu() const { return gpu_; }

 private:
  // The GPU state into the CPU mirror when the GPU is ahead. Logically const: the mirror is a
  // cache of the state the GPU holds.
  void pull() const;
  void push();  // the mirror (changed on the CPU) up to the GPU

  // SolverT's step loop, with the integrator on the GPU.
  SolveStats integrate(const System<float>& sys, double t, double h) override;
  void sync_state() const override;
  void mirror_written() override;
  void state_corrected() override;
  void pins_changed() override;
  bool check_after(long k, long count) const override;

  GpuCloth gpu_;
  IntegratorKind kind_;
  mutable bool gpu_ahead_ = false;
};

// "GPU" when `solver` steps on the GPU backend, else "CPU".
const char* backend_name(const Solver& solver);
// The line said when solver.backend = "gpu" cannot be honoured for reason `why`.
std::string cpu_fallback_note(const std::string& why);

// The solver for `scene`: a GpuSolver when scene.solver.backend is gpu and the scene and the
// current GL context allow it, else the CPU solver, with `note` set to one line saying why the
// GPU was not used (left empty otherwise). Needs a current GL context when backend is gpu.
std::unique_ptr<Solver> make_backend_solver(const Scene& scene, std::string& note);

}  // namespace clothlab::vis
