// The cloth step of the assignment's first GPU path: each substep is a draw of the cloth's
// vertices as points with rasterisation discarded, whose vertex shader (shaders/cloth_step_tf.vert)
// gathers its springs with the compute path's force rule (shaders/cloth_force.glsl) and writes
// the new position and velocity through transform feedback into the other buffers of the
// ping-pong pair; with wind, a draw before it captures each vertex's normal and area
// (shaders/cloth_surface_tf.vert). The buffers are a GpuCloth's (gpu_cloth.hpp), so the state's
// upload and read-back, the pins and the displayed force field are the compute path's.
//
// Drawing reads the captured position buffer as it is (no copy): the renderer computes each
// triangle's normal in a geometry shader (flat_normals()), which is why only grid cloths, whose
// render vertices are the solver's, take this path (sim/scene/validate.cpp). Needs a current GL
// 4.5 context whose vertex shaders may read storage buffers (the mass, the inverse mass, the
// wind's surface).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gpu/gpu_cloth.hpp"

namespace clothlab::gpu {

class TfCloth final : public DeviceCloth {
 public:
  // Uploads the model (neighbour_list kernel) and the state. Throws as GpuCloth does, and
  // GlUnavailable where vertex shaders cannot read storage buffers.
  TfCloth(const Model<float>& model, const Vec3Array<float>& positions,
          const Vec3Array<float>& velocities);

  // Advances `count` substeps of h seconds from time t with symplectic_euler, explicit_euler or
  // seed_hack (others: std::invalid_argument). Queues GPU work; returns at once.
  void step(int count, float h, IntegratorKind kind, double t = 0.0);

  void set_inverse_masses(const float* inv_mass) { base_.set_inverse_masses(inv_mass); }
  void set_state(const Vec3Array<float>& positions, const Vec3Array<float>& velocities) {
    base_.set_state(positions, velocities);
  }
  void read_state(Vec3Array<float>& positions, Vec3Array<float>& velocities) const {
    base_.read_state(positions, velocities);
  }
  // The total force for display, by the compute path's force pass.
  void compute_force_field(double t) { base_.compute_force_field(t); }
  void read_force_field(Vec3Array<float>& f) const { base_.read_force_field(f); }

  GLuint position_buffer() const override { return base_.position_buffer(); }
  GLuint normal_buffer() const override { return 0; }  // the renderer's geometry shader's
  void update_normals() override {}
  void compute_normals() {}
  // Each vertex's first incident triangle's unit normal normalize((x1 - x0) x (x2 - x0)), as the
  // renderer's geometry shader computes it (shaders/cloth_flat.geom); 0 on a vertex without one.
  void read_normals(float* xyz) const override;
  bool flat_normals() const override { return true; }
  const char* name() const override { return "GPU transform feedback"; }

  std::size_t vertex_count() const { return base_.vertex_count(); }
  void finish() const { base_.finish(); }

 private:
  // The step's program for shaders/cloth_step_tf.vert's TF_RULE `rule`, made on first use.
  struct StepProgram {
    Program program;
    GLint h = -1, t = -1;  // uniform locations
  };
  const StepProgram& step_program(int rule);
  void capture(GLuint index, const Buffer& buffer);
  void surface_draw(int src);
  void step_draw(const StepProgram& p, int src, double t);

  GpuCloth base_;
  std::array<StepProgram, 3> step_programs_;
  Program surface_program_;
  VertexArray points_;  // no attributes: the shaders read gl_VertexID
  // A framebuffer without attachments (1 x 1 by default size): a draw needs a complete one even
  // with rasterisation discarded, and a surfaceless context (EGL, headless) has none of its own.
  Framebuffer target_;
  TransformFeedback feedback_;
  GpuCloth::TexturedBuffer corners_;          // 3 ints per triangle, for the surface draw
  std::vector<std::int32_t> first_triangle_;  // per vertex, -1 without one
  std::vector<std::int32_t> corner_list_;     // 3 per triangle
  mutable std::vector<float> positions_;      // read_normals' read-back
};

}  // namespace clothlab::gpu
