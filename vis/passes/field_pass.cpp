#include "vis/passes/field_pass.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "gl/program.hpp"
#include "gl/uploads.hpp"
#include "sim/fields/frame_fields.hpp"
#include "sim/solver.hpp"
#include "vis/render/frame_request.hpp"
#include "vis/render/renderer.hpp"

namespace clothlab::vis {
namespace {

constexpr GLint kViewProj = 0;  // explicit uniform location in shaders/field.vert
// Attachments, in the order of shaders/field.frag's outputs.
constexpr GLenum kForce = GL_COLOR_ATTACHMENT0, kVelocity = GL_COLOR_ATTACHMENT1,
                 kWorld = GL_COLOR_ATTACHMENT2, kTriangle = GL_COLOR_ATTACHMENT3;

}  // namespace

FieldPass::FieldPass(int width, int height)
    : width_(width),
      height_(height),
      fbo_(make_framebuffer()),
      force_(make_renderbuffer()),
      velocity_(make_renderbuffer()),
      world_(make_renderbuffer()),
      triangle_(make_renderbuffer()),
      depth_(make_renderbuffer()),
      program_(build_program({"field.vert", "field.frag"})),
      vao_(make_vertex_array()) {
  // Single-sampled: a multisample resolve would average values across triangle edges (and
  // cannot average ids); the one sample at the pixel's centre is a point of the surface.
  const struct {
    GLenum attachment;
    const Renderbuffer& rb;
    GLenum format;
  } targets[] = {{kForce, force_, GL_RGBA32F},
                 {kVelocity, velocity_, GL_RGBA32F},
                 {kWorld, world_, GL_RGBA32F},
                 {kTriangle, triangle_, GL_R32I},
                 {GL_DEPTH_ATTACHMENT, depth_, GL_DEPTH_COMPONENT32F}};
  for (const auto& t : targets) {
    glNamedRenderbufferStorage(t.rb.get(), t.format, width, height);
    glNamedFramebufferRenderbuffer(fbo_.get(), t.attachment, GL_RENDERBUFFER, t.rb.get());
  }
  const GLenum draw_buffers[] = {kForce, kVelocity, kWorld, kTriangle};
  glNamedFramebufferDrawBuffers(fbo_.get(), 4, draw_buffers);
  const GLenum status = glCheckNamedFramebufferStatus(fbo_.get(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("field framebuffer incomplete (status " + std::to_string(status) +
                             ")");
  glObjectLabel(GL_FRAMEBUFFER, fbo_.get(), -1, "field pass");
  for (GLuint a = 0; a < 3; ++a) float_attribute(vao_.get(), a, a, 3);
}

void FieldPass::draw(const Renderer& renderer, const std::vector<float>& force,
                     const std::vector<float>& velocity, const glm::mat4& view_proj) {
  const std::size_t n = renderer.vertex_count(), rn = renderer.render_vertex_count();
  if (force.size() != 3 * n || velocity.size() != 3 * n)
    throw std::invalid_argument("FieldPass::draw: 3 floats per vertex expected");
  const auto half = static_cast<GLsizeiptr>(3 * rn * sizeof(float));
  if (!field_vbo_ || field_vertices_ != rn) {  // immutable storage: a new buffer per size
    field_vbo_ = make_buffer();
    glNamedBufferStorage(field_vbo_.get(), std::max<GLsizeiptr>(1, 2 * half), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    field_vertices_ = rn;
  }
  const auto solver_half = static_cast<GLsizeiptr>(3 * n * sizeof(float));
  glNamedBufferSubData(field_vbo_.get(), 0, solver_half, force.data());
  glNamedBufferSubData(field_vbo_.get(), half, solver_half, velocity.data());
  // A tube's seam copies (render vertices after the solver's) carry their solver vertex's values.
  const std::vector<int>& copies = renderer.seam_copies();
  if (!copies.empty()) {
    copy_scratch_.resize(6 * copies.size());  // allocates only when the cloth grows
    for (std::size_t k = 0; k < copies.size(); ++k)
      for (int d = 0; d < 3; ++d) {
        const std::size_t from = 3 * static_cast<std::size_t>(copies[k]) + d;
        copy_scratch_[3 * k + d] = force[from];
        copy_scratch_[3 * (copies.size() + k) + d] = velocity[from];
      }
    const auto copy_bytes = static_cast<GLsizeiptr>(3 * copies.size() * sizeof(float));
    glNamedBufferSubData(field_vbo_.get(), solver_half, copy_bytes, copy_scratch_.data());
    glNamedBufferSubData(field_vbo_.get(), half + solver_half, copy_bytes,
                         copy_scratch_.data() + 3 * copies.size());
  }
  // The renderer's buffers are bound anew each time: set_cloth() may have replaced them.
  glVertexArrayVertexBuffer(vao_.get(), 0, renderer.position_buffer(), 0,
                            renderer.position_stride());
  glVertexArrayVertexBuffer(vao_.get(), 1, field_vbo_.get(), 0, 3 * sizeof(float));
  glVertexArrayVertexBuffer(vao_.get(), 2, field_vbo_.get(), half, 3 * sizeof(float));
  glVertexArrayElementBuffer(vao_.get(), renderer.triangle_buffer());

  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
  glViewport(0, 0, width_, height_);
  glEnable(GL_DEPTH_TEST);  // the front-most surface wins
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // cloth is two-sided
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const GLint none[4] = {0, 0, 0, 0};
  for (GLint k = 0; k < 3; ++k) glClearBufferfv(GL_COLOR, k, zero);
  glClearBufferiv(GL_COLOR, 3, none);
  const float far = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far);

  glUseProgram(program_.get());
  glProgramUniformMatrix4fv(program_.get(), kViewProj, 1, GL_FALSE, &view_proj[0][0]);
  glBindVertexArray(vao_.get());
  glDrawElements(GL_TRIANGLES, renderer.triangle_index_count(), GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

std::optional<ProbeSample> FieldPass::read(int px, int py) const {
  if (px < 0 || py < 0 || px >= width_ || py >= height_) return std::nullopt;
  const int y = height_ - 1 - py;  // GL's row 0 is the bottom
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  GLint id = 0;
  glNamedFramebufferReadBuffer(fbo_.get(), kTriangle);
  glReadPixels(px, y, 1, 1, GL_RED_INTEGER, GL_INT, &id);
  if (id <= 0) return std::nullopt;
  ProbeSample s;
  s.triangle = id - 1;
  const std::pair<GLenum, glm::vec3*> reads[] = {
      {kForce, &s.force}, {kVelocity, &s.velocity}, {kWorld, &s.position}};
  for (const auto& [attachment, out] : reads) {
    float rgba[4] = {};
    glNamedFramebufferReadBuffer(fbo_.get(), attachment);
    glReadPixels(px, y, 1, 1, GL_RGBA, GL_FLOAT, rgba);
    *out = glm::vec3(rgba[0], rgba[1], rgba[2]);
  }
  return s;
}

std::optional<ProbeSample> probe_fields(const SolverState& solver, const FrameFields& fields,
                                        const Renderer& renderer, FieldPass& pass,
                                        const glm::mat4& view_proj, int px, int py) {
  if (px < 0 || py < 0 || px >= pass.width() || py >= pass.height()) return std::nullopt;
  const std::vector<float>& force = fields.force(ForceSource::total);
  const std::vector<float>& velocity = fields.velocities;
  require_field(force, 3 * fields.vertices, "the probe's total force");
  require_field(velocity, 3 * fields.vertices, "the probe's velocities");
  pass.draw(renderer, force, velocity, view_proj);
  // One pixel read back per call with glReadPixels, which waits for the draw (a pixel buffer
  // object read one frame late would avoid the stall; one pixel a frame is cheap enough).
  std::optional<ProbeSample> s = pass.read(px, py);
  if (!s) return s;
  // The triangle's vertex nearest to the surface point under the pixel, measured in double. The
  // id indexes the solver's triangles, whose vertices are solver vertices: a tube's seam copy
  // (Renderer::seam_copies) is never named, its solver vertex is.
  double best = INFINITY;
  for (int v : solver.triangles().at(static_cast<std::size_t>(s->triangle))) {
    const Vec3d p = solver.position(v);
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) d2 += (p[k] - s->position[k]) * (p[k] - s->position[k]);
    if (d2 < best) best = d2, s->vertex = v;
  }
  return s;
}

}  // namespace clothlab::vis
