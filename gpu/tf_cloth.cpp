#include "gpu/tf_cloth.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "gl/gl_error.hpp"
#include "gl/program.hpp"

namespace clothlab::gpu {

using namespace clothlab::vis;

namespace {

// shaders/cloth_step_tf.vert's `rule`.
int rule_of(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::symplectic_euler:
      return 0;
    case IntegratorKind::explicit_euler:
      return 1;
    case IntegratorKind::seed_hack:
      return 2;
    default:
      throw std::invalid_argument(
          "the transform-feedback step runs symplectic_euler, explicit_euler and seed_hack");
  }
}

// The step's vertex shader reads the mass, the inverse mass and the wind's surface as storage
// buffers, which GL 4.3 allows in vertex shaders but does not require.
void require_vertex_storage() {
  GLint blocks = 0;
  glGetIntegerv(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, &blocks);
  if (blocks < 3)
    throw GlUnavailable(
        "the transform-feedback step reads 3 storage buffers in its vertex shader; this driver "
        "allows " +
        std::to_string(blocks));
}

}  // namespace

TfCloth::TfCloth(const Model<float>& model, const Vec3Array<float>& positions,
                 const Vec3Array<float>& velocities)
    : base_(model, positions, velocities) {
  require_vertex_storage();
  const std::size_t n = base_.n_, triangles = base_.triangle_count_;
  corner_list_.reserve(3 * triangles);
  for (const auto& t : model.triangles) corner_list_.insert(corner_list_.end(), t.begin(), t.end());
  corners_ = GpuCloth::make_textured(corner_list_.data(),
                                     corner_list_.size() * sizeof(std::int32_t), GL_R32I);
  first_triangle_.assign(n, -1);
  for (std::size_t i = 0; i < n && base_.incident_slots_ > 0; ++i) {
    const std::int32_t t = model.incident_triangle[i];  // slot 0 of vertex i
    if (t >= 0 && static_cast<std::size_t>(t) < triangles) first_triangle_[i] = t;
  }
  positions_.resize(3 * n);

  surface_program_ = build_program({"cloth_surface_tf.vert"}, "", {"surface_out"});
  const GLuint s = surface_program_.get();
  glProgramUniform1ui(s, glGetUniformLocation(s, "n"), static_cast<GLuint>(n));
  glProgramUniform1i(s, glGetUniformLocation(s, "slots"), base_.incident_slots_);
  glProgramUniform1i(s, glGetUniformLocation(s, "triangles"), static_cast<GLint>(triangles));
  points_ = make_vertex_array();
  target_ = make_framebuffer();
  glNamedFramebufferParameteri(target_.get(), GL_FRAMEBUFFER_DEFAULT_WIDTH, 1);
  glNamedFramebufferParameteri(target_.get(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, 1);
  feedback_ = make_transform_feedback();
}

const TfCloth::StepProgram& TfCloth::step_program(int rule) {
  StepProgram& p = step_programs_[static_cast<std::size_t>(rule)];
  if (p.program) return p;
  const std::string defines = "#define TF_RULE " + std::to_string(rule) + "\n#define CLOTH_WIND " +
                              (base_.windy_ ? "1" : "0") + "\n";
  p.program = build_program({"cloth_step_tf.vert"}, defines, {"x_out", "v_out"});
  base_.set_force_uniforms(p.program);
  p.h = glGetUniformLocation(p.program.get(), "h");
  p.t = glGetUniformLocation(p.program.get(), "t");
  return p;
}

// Output `index` of the next draw into `buffer`.
void TfCloth::capture(GLuint index, const Buffer& buffer) {
  glTransformFeedbackBufferBase(feedback_.get(), index, buffer.get());
}

// Each vertex's (unit normal, area) of the positions in x_[src] into the surface buffer.
void TfCloth::surface_draw(int src) {
  glUseProgram(surface_program_.get());
  glBindTextureUnit(0, base_.x_[src].texture.get());
  glBindTextureUnit(1, base_.incident_.texture.get());
  glBindTextureUnit(2, corners_.texture.get());
  capture(0, base_.normals_);
  glBeginTransformFeedback(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(base_.n_));
  glEndTransformFeedback();
}

// One substep from the state in x_[src], v_[src] at time t into x_[1 - src], v_[1 - src].
void TfCloth::step_draw(const StepProgram& p, int src, double t) {
  const int dst = 1 - src;
  glUseProgram(p.program.get());
  glBindTextureUnit(0, base_.neighbour_.texture.get());
  glBindTextureUnit(1, base_.stiffness_.texture.get());
  glBindTextureUnit(2, base_.rest_length_.texture.get());
  glBindTextureUnit(3, base_.damping_.texture.get());
  glBindTextureUnit(4, base_.x_[src].texture.get());
  glBindTextureUnit(5, base_.v_[src].texture.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, base_.mass_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, base_.inv_mass_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, base_.normals_.get());
  glProgramUniform1d(p.program.get(), p.t, t);
  capture(0, base_.x_[dst].buffer);
  capture(1, base_.v_[dst].buffer);
  glBeginTransformFeedback(GL_POINTS);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(base_.n_));
  glEndTransformFeedback();
}

void TfCloth::step(int count, float h, IntegratorKind kind, double t) {
  const StepProgram& p = step_program(rule_of(kind));
  if (count <= 0 || base_.n_ == 0) return;
  glProgramUniform1f(p.program.get(), p.h, h);
  GLint framebuffer = 0;  // the caller's, restored below
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target_.get());
  glEnable(GL_RASTERIZER_DISCARD);
  glBindVertexArray(points_.get());
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback_.get());
  const double hd = static_cast<double>(h);  // the CPU's time of each step
  for (int k = 0; k < count; ++k) {
    if (base_.windy_) surface_draw(base_.current_);
    step_draw(p, base_.current_, t + k * hd);
    base_.current_ = 1 - base_.current_;
  }
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
  glBindVertexArray(0);
  glDisable(GL_RASTERIZER_DISCARD);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
  glUseProgram(0);
  base_.force_valid_ = false;
}

void TfCloth::read_normals(float* xyz) const {
  base_.read_positions(positions_.data());
  const float* p = positions_.data();
  for (std::size_t i = 0; i < first_triangle_.size(); ++i) {
    float n[3] = {0.0f, 0.0f, 0.0f};
    if (const std::int32_t t = first_triangle_[i]; t >= 0) {
      const float* p0 = p + 3 * corner_list_[3 * t];
      const float* p1 = p + 3 * corner_list_[3 * t + 1];
      const float* p2 = p + 3 * corner_list_[3 * t + 2];
      const float a[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
      const float b[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
      const float c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                          a[0] * b[1] - a[1] * b[0]};
      const float len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      if (len > 0.0f)
        for (int k = 0; k < 3; ++k) n[k] = c[k] / len;
    }
    for (int k = 0; k < 3; ++k) xyz[3 * i + k] = n[k];
  }
}

}  // namespace clothlab::gpu
