// The GPU's step backends (sim/step_backend.hpp): the integrator substeps on the device, by
// compute shaders (GpuCloth) or by a vertex shader with transform feedback (TfCloth), while the
// solver's CPU code works on a mirror of the state, pulled only when it reads it. Needs the GL
// context current on the calling thread for its whole life.
#pragma once

#include "gpu/gpu_cloth.hpp"
#include "gpu/tf_cloth.hpp"
#include "sim/step_backend.hpp"

namespace clothlab::gpu {

template <class Cloth>
class DeviceStep final : public StepBackend<float> {
 public:
  // Uploads the model (neighbour_list kernel) and the state; `kind` is one the cloth steps
  // (GpuCloth: symplectic_euler, verlet; TfCloth: symplectic_euler, explicit_euler, seed_hack).
  // Throws as the cloth does.
  DeviceStep(const Model<float>& model, const State<float>& state, IntegratorKind kind)
      : cloth_(model, state.pos, state.vel), kind_(kind) {}

  // The substep on the device; the mirror falls behind until pull().
  SolveStats integrate(double t, double h) override {
    cloth_.step(1, static_cast<float>(h), kind_, t);
    ahead_ = true;
    return {};
  }
  bool ahead() const override { return ahead_; }
  void pull(State<float>& mirror) override {
    cloth_.read_state(mirror.pos, mirror.vel);
    ahead_ = false;
  }
  void push(const State<float>& mirror) override {
    cloth_.set_state(mirror.pos, mirror.vel);  // forgets Verlet's stored force
    ahead_ = false;
  }
  // Release (D, release_at) and reset change which vertices are pinned: inverse masses of 0.
  void pins_changed(const Model<float>& model) override {
    cloth_.set_inverse_masses(model.inv_mass.data());
  }
  bool total_force(double t, Vec3Array<float>& force) override {
    cloth_.compute_force_field(t);
    cloth_.read_force_field(force);
    return true;
  }
  bool normals(float* xyz) override {
    cloth_.compute_normals();
    cloth_.read_normals(xyz);
    return true;
  }
  DeviceCloth* device_cloth() const override { return const_cast<Cloth*>(&cloth_); }

  Cloth& cloth() { return cloth_; }

 private:
  Cloth cloth_;
  IntegratorKind kind_;
  bool ahead_ = false;
};

using GpuStep = DeviceStep<GpuCloth>;
using TfStep = DeviceStep<TfCloth>;

}  // namespace clothlab::gpu
