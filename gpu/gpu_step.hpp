// The GPU's step backend (sim/step_backend.hpp): the integrator substeps as compute shaders
// (GpuCloth) while the solver's CPU code works on a mirror of the state, pulled only when it
// reads it. Needs the GL context current on the calling thread for its whole life.
#pragma once

#include "gpu/gpu_cloth.hpp"
#include "sim/step_backend.hpp"

namespace clothlab::gpu {

class GpuStep final : public StepBackend<float> {
 public:
  // Uploads the model (neighbour_list kernel) and the state; `kind` is symplectic_euler or
  // verlet. Throws as GpuCloth does.
  GpuStep(const Model<float>& model, const State<float>& state, IntegratorKind kind);

  SolveStats integrate(double t, double h) override;
  bool ahead() const override { return ahead_; }
  void pull(State<float>& mirror) override;
  void push(const State<float>& mirror) override;
  void pins_changed(const Model<float>& model) override;
  bool total_force(double t, Vec3Array<float>& force) override;
  bool normals(float* xyz) override;
  DeviceCloth* device_cloth() const override { return const_cast<GpuCloth*>(&cloth_); }

  GpuCloth& cloth() { return cloth_; }

 private:
  GpuCloth cloth_;
  IntegratorKind kind_;
  bool ahead_ = false;
};

}  // namespace clothlab::gpu
