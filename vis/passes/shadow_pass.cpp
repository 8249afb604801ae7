#include "vis/passes/shadow_pass.hpp"

#include "gl/program.hpp"
#include "gl/uploads.hpp"

namespace clothlab::vis {
namespace {

// Explicit uniform locations in shaders/shadow_depth.vert.
constexpr GLint kModel = 0, kFloor = 1, kFloorAt = 2;
// Slope-scaled depth offset for the casters (glPolygonOffset(factor, units)): the receiver's
// normal offset handles the rest of the acne.
constexpr float kOffsetFactor = 1.5f, kOffsetUnits = 2.0f;

}  // namespace

ShadowPass::ShadowPass()
    : program_(build_program({"shadow_depth.vert", "shadow_depth.frag"})),
      transmittance_program_(build_program({"shadow_colour.vert", "shadow_colour.frag"})),
      fbo_(make_framebuffer()),
      opaque_fbo_(make_framebuffer()),
      colour_fbo_(make_framebuffer()),
      compare_sampler_(make_sampler()),
      plain_sampler_(make_sampler()),
      empty_vao_(make_vertex_array()) {
  // Outside the map: depth 1, so the compare says lit.
  const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  for (GLuint s : {compare_sampler_.get(), plain_sampler_.get()}) {
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
  }
  glSamplerParameteri(compare_sampler_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(compare_sampler_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(compare_sampler_.get(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(compare_sampler_.get(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glSamplerParameteri(plain_sampler_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(plain_sampler_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glObjectLabel(GL_FRAMEBUFFER, fbo_.get(), -1, "shadow map");
}

void ShadowPass::begin(int size) {
  if (size != size_) {
    depth_ = make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(depth_.get(), 1, GL_DEPTH_COMPONENT32F, size, size);
    glNamedFramebufferTexture(fbo_.get(), GL_DEPTH_ATTACHMENT, depth_.get(), 0);
    glNamedFramebufferDrawBuffer(fbo_.get(), GL_NONE);
    glNamedFramebufferReadBuffer(fbo_.get(), GL_NONE);
    glObjectLabel(GL_TEXTURE, depth_.get(), -1, "shadow depth");
    size_ = size;
    opaque_depth_.reset();
    colour_.reset();
  }
  translucent_ = false;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
  glViewport(0, 0, size_, size_);
  const float far = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_MULTISAMPLE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(kOffsetFactor, kOffsetUnits);
  glUseProgram(program_.get());
}

void ShadowPass::draw_triangles(GLuint vao, GLsizei index_count, const glm::mat4& model,
                                std::size_t first_index) {
  glProgramUniformMatrix4fv(program_.get(), kModel, 1, GL_FALSE, &model[0][0]);
  glProgramUniform1i(program_.get(), kFloor, 0);
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, element_offset(first_index));
}

void ShadowPass::draw_floor(float height, float half_size) {
  glProgramUniform1i(program_.get(), kFloor, 1);
  glProgramUniform2f(program_.get(), kFloorAt, height, half_size);
  glBindVertexArray(empty_vao_.get());
  glDrawArrays(GL_TRIANGLES, 0, 6);
}

void ShadowPass::end() {
  glBindVertexArray(0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glEnable(GL_MULTISAMPLE);
}

void ShadowPass::begin_opaque() {
  if (!opaque_depth_) {
    opaque_depth_ = make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(opaque_depth_.get(), 1, GL_DEPTH_COMPONENT32F, size_, size_);
    glNamedFramebufferTexture(opaque_fbo_.get(), GL_DEPTH_ATTACHMENT, opaque_depth_.get(), 0);
    glNamedFramebufferDrawBuffer(opaque_fbo_.get(), GL_NONE);
    glNamedFramebufferReadBuffer(opaque_fbo_.get(), GL_NONE);
    glObjectLabel(GL_TEXTURE, opaque_depth_.get(), -1, "shadow depth, opaque casters");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, opaque_fbo_.get());
  const float far = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far);
  glUseProgram(program_.get());
  translucent_ = true;
}

void ShadowPass::begin_transmittance() {
  if (!colour_) {
    colour_ = make_texture(GL_TEXTURE_2D);
    // Linear transmittance (not sRGB), 16-bit float so products of layers keep their precision.
    glTextureStorage2D(colour_.get(), 1, GL_RGBA16F, size_, size_);
    glTextureParameteri(colour_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(colour_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(colour_.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(colour_.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glNamedFramebufferTexture(colour_fbo_.get(), GL_COLOR_ATTACHMENT0, colour_.get(), 0);
    glObjectLabel(GL_TEXTURE, colour_.get(), -1, "shadow transmittance");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, colour_fbo_.get());
  const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glClearBufferfv(GL_COLOR, 0, white);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ZERO, GL_SRC_COLOR);  // dst *= transmittance
  glUseProgram(transmittance_program_.get());
}

void ShadowPass::draw_transmittance(GLuint vao, GLsizei index_count, std::size_t first_index,
                                    GLuint albedo, float repeat, glm::vec3 flat_albedo,
                                    bool use_flat, float coverage, float transmission) {
  const GLuint p = transmittance_program_.get();
  glProgramUniform1f(p, 0, repeat);
  glProgramUniform3f(p, 1, flat_albedo.r, flat_albedo.g, flat_albedo.b);
  glProgramUniform1i(p, 2, use_flat ? 1 : 0);
  glProgramUniform2f(p, 3, coverage, transmission);
  glBindTextureUnit(0, albedo);
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, element_offset(first_index));
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

void ShadowPass::bind_textures() const {
  glBindTextureUnit(6, depth_.get());
  glBindTextureUnit(7, depth_.get());
  glBindSampler(6, compare_sampler_.get());
  glBindSampler(7, plain_sampler_.get());
  // Without translucent casters the coloured-shadow units are emptied: llvmpipe specialises
  // shaders on every bound texture, and stale ones slowed every later frame (measured 2x).
  glBindTextureUnit(8, translucent_ ? opaque_depth_.get() : 0);
  glBindSampler(8, translucent_ ? compare_sampler_.get() : 0);
  glBindTextureUnit(9, translucent_ ? colour_.get() : 0);
}

}  // namespace clothlab::vis
