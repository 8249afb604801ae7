// The cloth step on the GPU: OpenGL 4.3+ compute shaders (shaders/cloth_step.comp) over the
// neighbour_list model the CPU uses, one invocation per vertex gathering its own springs through
// buffer textures, no atomics. Gravity, drag, springs with along-spring damping, wind, and
// the symplectic Euler and velocity Verlet integrators, each written out in the CPU's order with
// `precise` arithmetic, so on a driver without fused multiply-add (llvmpipe) the state matches a
// CPU build without contraction (-ffp-contract=off) bit for bit. Smoothed normals take a face pass
// and a vertex gather pass (shaders/cloth_faces.comp, cloth_normals.comp); with wind the same two
// passes run before every force evaluation, and the gusts use the CPU's noise in double precision.
//
// State layout: positions and velocities are vec4 per vertex (w unused), in ping-pong pairs. A
// std430 vec3 array has a 16-byte stride anyway, and vec4 lets the same buffer be both the SSBO a
// pass writes and the GL_RGBA32F buffer texture the next pass gathers from (texelFetch; RGB32F
// buffer textures are optional in some drivers' fast paths). Needs a current GL 4.5 context.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "gl/objects.hpp"
#include "sim/model/model.hpp"
#include "sim/scene/scene.hpp"
#include "sim/step_backend.hpp"

namespace clothlab::gpu {

using vis::Buffer;
using vis::Framebuffer;
using vis::Program;
using vis::Texture;
using vis::TransformFeedback;
using vis::VertexArray;

class TfCloth;

class GpuCloth final : public DeviceCloth {
  // The transform-feedback step (tf_cloth.hpp) keeps its cloth in a GpuCloth's buffers and
  // steps it with its own draws.
  friend class TfCloth;

 public:
  // Uploads the model (kernel neighbour_list, else std::invalid_argument) and the state (n
  // positions and velocities, m and m/s). Throws GlUnavailable without compute shaders (GL 4.3)
  // or when the tables exceed the driver's buffer-texture size; ShaderError on a shader failure.
  GpuCloth(const Model<float>& model, const Vec3Array<float>& positions,
           const Vec3Array<float>& velocities);

  // Advances `count` steps of h seconds from time t (s; the gusts depend on it) with
  // symplectic_euler or verlet (others: std::invalid_argument). Verlet keeps its end-of-step
  // force for the next call, as the CPU does; a change of integrator, set_state(),
  // or set_inverse_masses() forgets it. Queues GPU work; returns at once.
  void step(int count, float h, IntegratorKind kind, double t = 0.0);
  // After a change of the pins (n inverse masses, 0 where pinned).
  void set_inverse_masses(const float* inv_mass);

  // The total force F(x, v) at time t on every vertex (pinned ones too, as the CPU's
  // compute_forces) into a buffer of its own, for display; read_force_field copies it out.
  void compute_force_field(double t);
  void read_force_field(Vec3Array<float>& f) const;
  // The current state into n-vertex arrays (waits for the GPU; allocates nothing).
  void read_state(Vec3Array<float>& positions, Vec3Array<float>& velocities) const;

  // The buffers the renderer draws from: positions of the current state and the normals of the
  // last compute_normals(), both vec4 per vertex (normal.w is the vertex area).
  GLuint position_buffer() const override { return x_[current_].buffer.get(); }
  GLuint normal_buffer() const override { return normals_.get(); }

  // Replaces the state (n positions and velocities).
  void set_state(const Vec3Array<float>& positions, const Vec3Array<float>& velocities);

  // The current state, 3 floats per vertex (waits for the GPU; allocates).
  void read_positions(float* xyz) const;
  void read_velocities(float* xyz) const;

  // Unit area-weighted normals of the current positions (the CPU's compute_surface_from_triangles)
  // into the normal buffer; read_normals copies them out, 3 floats per vertex.
  void compute_normals();
  void read_normals(float* xyz) const override;
  void update_normals() override { compute_normals(); }
  const char* name() const override { return "GPU"; }

  std::size_t vertex_count() const { return n_; }
  // Waits until every queued pass has finished (for timing).
  void finish() const;

 private:
  struct TexturedBuffer {
    Buffer buffer;
    Texture texture;  // a buffer texture over `buffer`
  };
  static TexturedBuffer make_textured(const void* data, std::size_t bytes, GLenum format);
  void read_vec4(const Buffer& b, float* xyz) const;
  void read_vec4(const Buffer& b, Vec3Array<float>& a) const;
  const std::vector<float>& load_staging(const Buffer& b) const;
  // The force rule's uniforms (shaders/cloth_force.glsl) on `program`: the model's and the wind's.
  void set_force_uniforms(const Program& program);
  void set_wind_uniforms(const Program& program);
  void surface_pass(const TexturedBuffer& x);
  void force_pass(int stage, int src, double t, const Buffer& force);
  void dispatch(unsigned items) const;

  std::size_t n_ = 0;
  int slots_ = 0;
  int incident_slots_ = 0;
  std::size_t triangle_count_ = 0;
  bool windy_ = false;  // the wind blows on a cloth with triangles
  // The model's constants the force rule's uniforms are set from.
  bool damped_ = false;
  std::array<float, 3> gravity_{};
  float drag_ = 0.0f;
  WindSpec wind_;

  TexturedBuffer neighbour_, stiffness_, rest_length_, damping_;  // slot-major, n * slots
  Buffer mass_, inv_mass_;
  TexturedBuffer x_[2], v_[2];  // ping-pong state, vec4
  TexturedBuffer v_pred_;       // Verlet's predicted end velocity
  Buffer force_;                // Verlet's end-of-step force, reused as the next start force
  Buffer field_;                // compute_force_field()'s force
  bool force_valid_ = false;
  int current_ = 0;  // which of x_, v_ holds the state

  Buffer triangles_;         // 3 ints per triangle
  TexturedBuffer faces_;     // (c, area) per triangle, plus a zero dummy
  TexturedBuffer incident_;  // slot-major, n * incident_slots
  Buffer normals_;           // (unit normal, vertex area) per vertex
  Program step_program_, faces_program_, normals_program_;
  GLint stage_location_ = -1;                                          // cloth_step.comp's `stage`
  GLint time_location_ = -1, h_location_ = -1, half_h_location_ = -1;  // `t`, `h`, `half_h`
  mutable std::vector<float> staging_;  // 4 n floats for uploads and read-backs
};

}  // namespace clothlab::gpu
