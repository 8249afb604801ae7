#include "vis/gpu/gpu_solver.hpp"

#include <stdexcept>

#include "vis/gl/gl_error.hpp"

namespace clothlab::vis {

std::string gpu_unsupported_reason(const Scene& scene) {
  const IntegratorKind k = scene.solver.integrator;
  if (k != IntegratorKind::symplectic_euler && k != IntegratorKind::verlet)
    return std::string("the GPU step runs symplectic_euler and verlet, not ") + to_string(k);
  if (scene.solver.precision == Precision::f64) return "the GPU step computes in float, not double";
  return {};
}

namespace {

const Scene& checked(const Scene& scene) {
  const std::string why = gpu_unsupported_reason(scene);
  if (!why.empty()) throw std::invalid_argument(why);
  return scene;
}

}  // namespace

GpuSolver::GpuSolver(const Scene& scene)
    : SolverT<float>(checked(scene), SpringKernel::neighbour_list),
      gpu_(model_, state_.pos, state_.vel),
      kind_(spec_.integrator) {}

void GpuSolver::pull() const {
  if (!gpu_ahead_) return;
  auto& mirror = const_cast<State<float>&>(state_);
  gpu_.read_state(mirror.pos, mirror.vel);
  gpu_ahead_ = false;
}

void GpuSolver::push() {
  gpu_.set_state(state_.pos, state_.vel);
  gpu_ahead_ = false;
}

// The substep on the GPU; the mirror falls behind until sync_state().
SolveStats GpuSolver::integrate(const System<float>& /*sys*/, double t, double h) {
  gpu_.step(1, static_cast<float>(h), kind_, t);
  gpu_ahead_ = true;
  return {};
}

void GpuSolver::sync_state() const {
  pull();
}

void GpuSolver::mirror_written() {
  push();
}

void GpuSolver::state_corrected() {
  push();  // forgets Verlet's stored force, as the CPU's integrator does
}

// Release (D, release_at) and reset change which vertices are pinned: inverse masses of 0.
void GpuSolver::pins_changed() {
  gpu_.set_inverse_masses(model_.inv_mass.data());
}

// Without CPU work between the substeps the mirror is read once per step() call: in the window,
// once per frame.
bool GpuSolver::check_after(long k, long count) const {
  return !gpu_ahead_ || k + 1 == count;
}

Vec3d GpuSolver::position(int vertex) const {
  pull();
  return SolverT<float>::position(vertex);
}

Vec3d GpuSolver::velocity(int vertex) const {
  pull();
  return SolverT<float>::velocity(vertex);
}

// The total force comes from the GPU's own force pass; a single source (springs, gravity, drag,
// wind) from the CPU's code on the mirror.
void GpuSolver::update_force_field(ForceSource source) {
  if (source != ForceSource::total) {
    pull();
    SolverT<float>::update_force_field(source);
    return;
  }
  gpu_.compute_force_field(time());
  gpu_.read_force_field(force_field_);
  force_source_ = source;
}

Energy GpuSolver::energy() {
  pull();
  return SolverT<float>::energy();
}

void GpuSolver::apply_impulse(const Vec3d& center, double radius, const Vec3d& impulse) {
  pull();
  SolverT<float>::apply_impulse(center, radius, impulse);
  push();
}

void GpuSolver::copy_positions(float* xyz) const {
  pull();
  SolverT<float>::copy_positions(xyz);
}

void GpuSolver::copy_velocities(float* xyz) const {
  pull();
  SolverT<float>::copy_velocities(xyz);
}

void GpuSolver::copy_normals(float* xyz) {
  gpu_.compute_normals();
  gpu_.read_normals(xyz);
}

void GpuSolver::load_state(const Solver& other) {
  gpu_ahead_ = false;  // the mirror is about to be overwritten: never pull over it
  SolverT<float>::load_state(other);
  push();
}

void GpuSolver::reset() {
  gpu_ahead_ = false;
  SolverT<float>::reset();
  push();
}

const char* backend_name(const Solver& solver) {
  return dynamic_cast<const GpuSolver*>(&solver) ? "GPU" : "CPU";
}

std::string cpu_fallback_note(const std::string& why) {
  return "solver.backend = \"gpu\": " + why + "; the cloth steps on the CPU";
}

std::unique_ptr<Solver> make_backend_solver(const Scene& scene, std::string& note) {
  note.clear();
  if (scene.solver.backend != Backend::gpu) return make_solver(scene);
  std::string why = gpu_unsupported_reason(scene);
  if (why.empty()) {
    try {
      return std::make_unique<GpuSolver>(scene);
    } catch (const GlUnavailable& e) {
      why = e.what();
    }
  }
  note = cpu_fallback_note(why);
  return make_solver(scene);
}

}  // namespace clothlab::vis
