// Where a solver's integrator substeps run (docs/gpu-backend.md). The CPU solver integrates its
// own state in place and has no backend. A backend (the GPU's, gpu/gpu_step.hpp) integrates a
// copy of the state of its own and the solver keeps its state as a mirror of it: the step loop's
// CPU parts (pins, release, grab, colliders, self-collision, moving pins, divergence checks) read
// the mirror after pull() and send what they corrected back with push(). sim/ has no GL: a
// backend that keeps the cloth in device buffers names them as plain integers (DeviceCloth).
#pragma once

#include "sim/integrators/integrator.hpp"
#include "sim/model/model.hpp"

namespace clothlab {

// A cloth whose current positions and normals live in device buffers a renderer can draw from.
class DeviceCloth {
 public:
  virtual ~DeviceCloth() = default;
  // The area-weighted unit normals of the current positions, into normal_buffer().
  virtual void update_normals() = 0;
  // Buffer names: positions and the last update_normals(), 4 floats per vertex.
  virtual unsigned position_buffer() const = 0;
  virtual unsigned normal_buffer() const = 0;
  // The last update_normals(), 3 floats per vertex (waits for the device).
  virtual void read_normals(float* xyz) const = 0;
  // True when the renderer computes each triangle's normal itself (a geometry shader) and
  // normal_buffer() is 0; read_normals() then gives each vertex the normal of its first
  // incident triangle, the same per-triangle normal.
  virtual bool flat_normals() const { return false; }
  // The backend's name in titles and reports ("GPU", "GPU transform feedback").
  virtual const char* name() const = 0;
};

template <class T>
class StepBackend {
 public:
  virtual ~StepBackend() = default;
  // One integrator substep of h seconds from time t; the mirror falls behind.
  virtual SolveStats integrate(double t, double h) = 0;
  // True while the backend's state is newer than the mirror.
  virtual bool ahead() const = 0;
  // The backend's state into the mirror.
  virtual void pull(State<T>& mirror) = 0;
  // The mirror, changed on the CPU, to the backend (which forgets any cached force).
  virtual void push(const State<T>& mirror) = 0;
  // The pinned set changed: the model's inverse masses.
  virtual void pins_changed(const Model<T>& model) = 0;
  // The total force at time t into `force`; false: the CPU computes it on the mirror.
  virtual bool total_force(double t, Vec3Array<T>& force) = 0;
  // Unit normals of the current state, 3 floats per vertex; false: the CPU computes them.
  virtual bool normals(float* xyz) = 0;
  // The device buffers of the cloth, or null.
  virtual DeviceCloth* device_cloth() const = 0;
};

}  // namespace clothlab
