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
      kind_(spec_.integrator),
      uploaded_pins_(model_.pinned.size()) {}

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

// Release (D, release_at) and reset change which vertices are pinned: inverse masses of 0.
void GpuSolver::upload_pins_if_changed() {
  if (model_.pinned.size() == uploaded_pins_) return;
  gpu_.set_inverse_masses(model_.inv_mass.data());
  uploaded_pins_ = model_.pinned.size();
}

// SolverT::step with the integrator on the GPU; the CPU-side parts pull the state down first and
// push what they corrected back up.
AdvanceResult GpuSolver::step(long count) {
  AdvanceResult result;
  if (diverged_) {
    result.divergence = diverged_;
    return result;
  }
  const double h = dt_ / substeps_;
  Divergence report;
  for (long k = 0; k < count; ++k) {
    const double t0 = time();
    release_due(false);
    upload_pins_if_changed();
    if (self_) {
      pull();
      self_->find_pairs(model_, state_, dt_, threads_);
    }
    for (int sub = 0; sub < substeps_; ++sub) {
      const double t = t0 + sub * h;
      if (contacts_) {
        pull();
        contacts_->begin(state_, t, h, threads_);
      }
      if (moving_pins_) {
        pull();
        moving_pins_->drive(model_, state_, t, h);
        push();
      }
      gpu_.step(1, static_cast<float>(h), kind_, t);
      gpu_ahead_ = true;
      record(SolveStats{});
      if (moving_pins_) {
        pull();
        moving_pins_->place(model_, state_, t0 + (sub + 1) * h);
        push();
      }
      bool corrected = false;
      if (grab_) {
        pull();
        pull_grabbed(h);
        corrected = true;
      }
      if (contacts_) {
        pull();
        if (contacts_->respond(model_, state_, t, h, threads_)) corrected = true;
      }
      if (self_) {
        pull();
        if (self_->respond(model_, state_, h)) corrected = true;
      }
      if (corrected) push();
    }
    ++steps_;
    ++result.steps;
    // The checks read the mirror: every step when it is current anyway, else at the call's end.
    if (gpu_ahead_ && k + 1 < count) continue;
    pull();
    if (monitor_.check(model_, state_, steps_, time(), threads_, report)) {
      diverged_ = report;
      result.divergence = report;
      break;
    }
  }
  return result;
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
  upload_pins_if_changed();
  push();
}

void GpuSolver::release_pins() {
  SolverT<float>::release_pins();
  upload_pins_if_changed();
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
  note = "solver.backend = \"gpu\": " + why + "; the cloth steps on the CPU";
  return make_solver(scene);
}

}  // namespace clothlab::vis
