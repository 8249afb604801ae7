#include "gpu/gpu_step.hpp"

namespace clothlab::gpu {

GpuStep::GpuStep(const Model<float>& model, const State<float>& state, IntegratorKind kind)
    : cloth_(model, state.pos, state.vel), kind_(kind) {}

// The substep on the GPU; the mirror falls behind until pull().
SolveStats GpuStep::integrate(double t, double h) {
  cloth_.step(1, static_cast<float>(h), kind_, t);
  ahead_ = true;
  return {};
}

void GpuStep::pull(State<float>& mirror) {
  cloth_.read_state(mirror.pos, mirror.vel);
  ahead_ = false;
}

void GpuStep::push(const State<float>& mirror) {
  cloth_.set_state(mirror.pos, mirror.vel);  // forgets Verlet's stored force
  ahead_ = false;
}

// Release (D, release_at) and reset change which vertices are pinned: inverse masses of 0.
void GpuStep::pins_changed(const Model<float>& model) {
  cloth_.set_inverse_masses(model.inv_mass.data());
}

bool GpuStep::total_force(double t, Vec3Array<float>& force) {
  cloth_.compute_force_field(t);
  cloth_.read_force_field(force);
  return true;
}

bool GpuStep::normals(float* xyz) {
  cloth_.compute_normals();
  cloth_.read_normals(xyz);
  return true;
}

}  // namespace clothlab::gpu
