#include "gpu/gpu_cloth.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "gl/gl_error.hpp"
#include "gl/program.hpp"
#include "sim/forces/wind.hpp"

namespace clothlab::gpu {

using namespace clothlab::vis;

namespace {

constexpr unsigned kLocalSize = 64;  // local_size_x of every cloth compute shader

// Stages of shaders/cloth_step.comp.
constexpr int kSymplecticEuler = 0, kForceOnly = 1, kVerletDrift = 2, kVerletKick = 3;

// Compute shaders are core from GL 4.3; the context asks for 4.5, but a shared or foreign
// context might not be one.
void require_compute(std::size_t largest_table) {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 43 || !glDispatchCompute)
    throw GlUnavailable("the GPU cloth step needs OpenGL 4.3 compute shaders; this context is " +
                        std::to_string(major) + "." + std::to_string(minor));
  GLint invocations = 0, texels = 0;
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &invocations);
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
  if (invocations < static_cast<GLint>(kLocalSize))
    throw GlUnavailable(
        "the GPU cloth step needs work groups of 64 invocations; this driver allows " +
        std::to_string(invocations));
  if (largest_table > static_cast<std::size_t>(texels))
    throw GlUnavailable("the cloth's neighbour table has " + std::to_string(largest_table) +
                        " entries; this driver's buffer textures hold at most " +
                        std::to_string(texels));
}

Buffer make_storage(const void* data, std::size_t bytes) {
  Buffer b = make_buffer();
  // Zero-sized storage is an error in GL; keep one word so every binding is valid.
  glNamedBufferStorage(b.get(), static_cast<GLsizeiptr>(bytes > 0 ? bytes : 4),
                       bytes > 0 ? data : nullptr, GL_DYNAMIC_STORAGE_BIT);
  return b;
}

GLint location(const Program& p, const char* name) {
  return glGetUniformLocation(p.get(), name);
}

}  // namespace

GpuCloth::TexturedBuffer GpuCloth::make_textured(const void* data, std::size_t bytes,
                                                 GLenum format) {
  TexturedBuffer t{make_storage(data, bytes), make_texture(GL_TEXTURE_BUFFER)};
  glTextureBuffer(t.texture.get(), format, t.buffer.get());
  return t;
}

GpuCloth::GpuCloth(const Model<float>& model, const Vec3Array<float>& positions,
                   const Vec3Array<float>& velocities)
    : n_(model.n),
      slots_(model.slots),
      incident_slots_(model.incident_slots),
      triangle_count_(model.triangles.size()),
      damped_(model.has_damping),
      gravity_(model.gravity),
      drag_(model.drag),
      wind_(model.wind) {
  windy_ = wind_.enabled && !WindField(wind_).calm() && triangle_count_ > 0;
  if (model.kernel != SpringKernel::neighbour_list)
    throw std::invalid_argument("GpuCloth needs a model built with SpringKernel::neighbour_list");
  if (positions.size() != n_ || velocities.size() != n_)
    throw std::invalid_argument("GpuCloth: the state's size differs from the model's vertex count");
  const std::size_t table = n_ * static_cast<std::size_t>(slots_);
  require_compute(
      std::max({table, n_ * static_cast<std::size_t>(incident_slots_), triangle_count_ + 1}));

  neighbour_ = make_textured(model.neighbour.data(), table * sizeof(std::int32_t), GL_R32I);
  stiffness_ = make_textured(model.stiffness.data(), table * sizeof(float), GL_R32F);
  rest_length_ = make_textured(model.rest_length.data(), table * sizeof(float), GL_R32F);
  damping_ = make_textured(model.damping.data(), table * sizeof(float), GL_R32F);
  mass_ = make_storage(model.mass.data(), n_ * sizeof(float));
  inv_mass_ = make_storage(model.inv_mass.data(), n_ * sizeof(float));
  const std::vector<float> zero(4 * n_, 0.0f);
  field_ = make_storage(zero.data(), zero.size() * sizeof(float));
  for (int k = 0; k < 2; ++k) {
    x_[k] = make_textured(zero.data(), zero.size() * sizeof(float), GL_RGBA32F);
    v_[k] = make_textured(zero.data(), zero.size() * sizeof(float), GL_RGBA32F);
  }
  v_pred_ = make_textured(zero.data(), zero.size() * sizeof(float), GL_RGBA32F);
  force_ = make_storage(zero.data(), zero.size() * sizeof(float));
  set_state(positions, velocities);

  std::vector<std::int32_t> corners;
  corners.reserve(3 * triangle_count_);
  for (const auto& t : model.triangles) corners.insert(corners.end(), t.begin(), t.end());
  triangles_ = make_storage(corners.data(), corners.size() * sizeof(std::int32_t));
  const std::vector<float> faces(4 * (triangle_count_ + 1), 0.0f);  // the dummy stays zero
  faces_ = make_textured(faces.data(), faces.size() * sizeof(float), GL_RGBA32F);
  incident_ = make_textured(model.incident_triangle.data(),
                            model.incident_triangle.size() * sizeof(std::int32_t), GL_R32I);
  normals_ = make_storage(zero.data(), zero.size() * sizeof(float));

  step_program_ = build_program({"cloth_step.comp"});
  faces_program_ = build_program({"cloth_faces.comp"});
  normals_program_ = build_program({"cloth_normals.comp"});
  stage_location_ = location(step_program_, "stage");
  time_location_ = location(step_program_, "t");
  h_location_ = location(step_program_, "h");
  half_h_location_ = location(step_program_, "half_h");
  set_force_uniforms(step_program_);
  glProgramUniform1ui(faces_program_.get(), location(faces_program_, "triangles"),
                      static_cast<GLuint>(triangle_count_));
  glProgramUniform1ui(normals_program_.get(), location(normals_program_, "n"),
                      static_cast<GLuint>(n_));
  glProgramUniform1i(normals_program_.get(), location(normals_program_, "slots"), incident_slots_);
}

void GpuCloth::set_state(const Vec3Array<float>& positions, const Vec3Array<float>& velocities) {
  current_ = 0;
  const auto bytes = static_cast<GLsizeiptr>(4 * n_ * sizeof(float));
  staging_.resize(4 * n_);  // allocates once
  for (const auto& [from, to] : {std::pair{&positions, &x_[0]}, std::pair{&velocities, &v_[0]}}) {
    for (std::size_t i = 0; i < n_; ++i) {
      staging_[4 * i] = from->x[i];
      staging_[4 * i + 1] = from->y[i];
      staging_[4 * i + 2] = from->z[i];
      staging_[4 * i + 3] = 0.0f;
    }
    glNamedBufferSubData(to->buffer.get(), 0, bytes, staging_.data());
  }
  force_valid_ = false;
}

void GpuCloth::dispatch(unsigned items) const {
  glDispatchCompute((items + kLocalSize - 1) / kLocalSize, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
}

void GpuCloth::set_force_uniforms(const Program& program) {
  const GLuint p = program.get();
  glProgramUniform1ui(p, location(program, "n"), static_cast<GLuint>(n_));
  glProgramUniform1i(p, location(program, "slots"), slots_);
  glProgramUniform1i(p, location(program, "damped"), damped_ ? 1 : 0);
  glProgramUniform3f(p, location(program, "gravity"), gravity_[0], gravity_[1], gravity_[2]);
  glProgramUniform1f(p, location(program, "drag"), drag_);
  set_wind_uniforms(program);
}

// The wind's constants (sim/forces/wind.hpp WindField) as cloth_force.glsl's uniforms.
void GpuCloth::set_wind_uniforms(const Program& program) {
  const WindSpec& spec = wind_;
  const WindField field(spec);
  const GLuint p = program.get();
  glProgramUniform1i(p, location(program, "windy"), windy_ ? 1 : 0);
  glProgramUniform1i(p, location(program, "gusty"), windy_ && !field.steady() ? 1 : 0);
  glProgramUniform3f(p, location(program, "wind"), static_cast<float>(spec.velocity[0]),
                     static_cast<float>(spec.velocity[1]), static_cast<float>(spec.velocity[2]));
  glProgramUniform1f(p, location(program, "wind_coefficient"),
                     static_cast<float>(spec.coefficient));
  glProgramUniform3dv(p, location(program, "wind_lag"), 1, field.lag());
  glProgramUniform1d(p, location(program, "gust"), spec.gust);
  glProgramUniform1d(p, location(program, "gust_period"), spec.gust_period);
  // seed * golden ratio, as detail::lattice_value forms it, for the two octaves' seeds.
  GLuint seeds[4];
  for (int k = 0; k < 2; ++k) {
    const std::uint64_t g = (spec.seed + static_cast<std::uint64_t>(k)) * 0x9e3779b97f4a7c15ULL;
    seeds[2 * k] = static_cast<GLuint>(g & 0xffffffffu);
    seeds[2 * k + 1] = static_cast<GLuint>(g >> 32);
  }
  glProgramUniform2uiv(p, location(program, "gust_seeds"), 2, seeds);
}

// The surface (normals_: unit normal and vertex area) of the positions in `x`: a face pass and a
// vertex gather pass. Leaves its own program bound.
void GpuCloth::surface_pass(const TexturedBuffer& x) {
  glUseProgram(faces_program_.get());
  glBindTextureUnit(0, x.texture.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, triangles_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, faces_.buffer.get());
  if (triangle_count_ > 0) dispatch(static_cast<unsigned>(triangle_count_));
  glUseProgram(normals_program_.get());
  glBindTextureUnit(0, incident_.texture.get());
  glBindTextureUnit(1, faces_.texture.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, normals_.get());
  dispatch(static_cast<unsigned>(n_));
}

// One dispatch of cloth_step.comp's `stage` at time t reading the state in x_[src], v_[src] and
// writing x_[1 - src], v_[1 - src]; Verlet's end kick gathers at (x_[1 - src], v_pred_) instead.
// `force` receives stages 1 and 3's force (Verlet's store, or the displayed force field).
void GpuCloth::force_pass(int stage, int src, double t, const Buffer& force) {
  const int dst = 1 - src;
  const bool end_kick = stage == kVerletKick;
  const TexturedBuffer& gather_x = end_kick ? x_[dst] : x_[src];
  if (windy_ && stage != kVerletDrift) surface_pass(gather_x);
  const GLuint p = step_program_.get();
  glUseProgram(p);
  glBindTextureUnit(0, neighbour_.texture.get());
  glBindTextureUnit(1, stiffness_.texture.get());
  glBindTextureUnit(2, rest_length_.texture.get());
  glBindTextureUnit(3, damping_.texture.get());
  glBindTextureUnit(4, gather_x.texture.get());
  glBindTextureUnit(5, (end_kick ? v_pred_ : v_[src]).texture.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, x_[src].buffer.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, v_[src].buffer.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, x_[dst].buffer.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, v_[dst].buffer.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, force.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, v_pred_.buffer.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, mass_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, inv_mass_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, normals_.get());
  glProgramUniform1i(p, stage_location_, stage);
  glProgramUniform1d(p, time_location_, t);
  dispatch(static_cast<unsigned>(n_));
}

void GpuCloth::step(int count, float h, IntegratorKind kind, double t) {
  if (kind != IntegratorKind::symplectic_euler && kind != IntegratorKind::verlet)
    throw std::invalid_argument("GpuCloth steps symplectic_euler and verlet only");
  if (count <= 0 || n_ == 0) return;
  const GLuint p = step_program_.get();
  glProgramUniform1f(p, h_location_, h);
  glProgramUniform1f(p, half_h_location_, 0.5f * h);  // as the CPU rounds it
  // The CPU integrators take the time of each step and of Verlet's end force this way.
  const double hd = static_cast<double>(h);
  if (kind == IntegratorKind::symplectic_euler) {
    for (int k = 0; k < count; ++k) {
      force_pass(kSymplecticEuler, current_, t + k * hd, force_);
      current_ = 1 - current_;
    }
    force_valid_ = false;  // a later Verlet step evaluates its start force afresh
  } else {
    if (!force_valid_) force_pass(kForceOnly, current_, t, force_);
    for (int k = 0; k < count; ++k) {
      force_pass(kVerletDrift, current_, t + k * hd, force_);
      force_pass(kVerletKick, current_, t + k * hd + hd, force_);
      current_ = 1 - current_;
    }
    force_valid_ = true;
  }
  glUseProgram(0);
}

void GpuCloth::compute_force_field(double t) {
  if (n_ == 0) return;
  force_pass(kForceOnly, current_, t, field_);
  glUseProgram(0);
}

void GpuCloth::read_force_field(Vec3Array<float>& f) const {
  read_vec4(field_, f);
}

void GpuCloth::set_inverse_masses(const float* inv_mass) {
  glNamedBufferSubData(inv_mass_.get(), 0, static_cast<GLsizeiptr>(n_ * sizeof(float)), inv_mass);
  force_valid_ = false;
}

void GpuCloth::compute_normals() {
  if (n_ == 0) return;
  surface_pass(x_[current_]);
  glUseProgram(0);
}

const std::vector<float>& GpuCloth::load_staging(const Buffer& b) const {
  staging_.resize(4 * n_);
  glGetNamedBufferSubData(b.get(), 0, static_cast<GLsizeiptr>(staging_.size() * sizeof(float)),
                          staging_.data());
  return staging_;
}

void GpuCloth::read_vec4(const Buffer& b, float* xyz) const {
  const std::vector<float>& v = load_staging(b);
  for (std::size_t i = 0; i < n_; ++i) {
    xyz[3 * i] = v[4 * i];
    xyz[3 * i + 1] = v[4 * i + 1];
    xyz[3 * i + 2] = v[4 * i + 2];
  }
}

void GpuCloth::read_vec4(const Buffer& b, Vec3Array<float>& a) const {
  const std::vector<float>& v = load_staging(b);
  for (std::size_t i = 0; i < n_; ++i) a.set(i, v[4 * i], v[4 * i + 1], v[4 * i + 2]);
}

void GpuCloth::read_state(Vec3Array<float>& positions, Vec3Array<float>& velocities) const {
  read_vec4(x_[current_].buffer, positions);
  read_vec4(v_[current_].buffer, velocities);
}

void GpuCloth::read_positions(float* xyz) const {
  read_vec4(x_[current_].buffer, xyz);
}
void GpuCloth::read_velocities(float* xyz) const {
  read_vec4(v_[current_].buffer, xyz);
}
void GpuCloth::read_normals(float* xyz) const {
  read_vec4(normals_, xyz);
}

void GpuCloth::finish() const {
  glFinish();
}

}  // namespace clothlab::gpu
