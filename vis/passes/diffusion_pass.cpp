#include "vis/passes/diffusion_pass.hpp"

#include <cmath>

#include "gl/program.hpp"
#include "vis/render/shading_variant.hpp"

namespace clothlab::vis {
namespace {

constexpr GLint kRepeat = 0, kAtlasSize = 1;      // shaders/tsd_irradiance.frag
constexpr GLint kSigmaMetres = 0, kFallback = 1;  // shaders/tsd_blur.frag

Texture atlas_texture(int size, const char* label, GLenum format = GL_RGBA16F) {
  Texture t = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.get(), 1, format, size, size);
  glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glObjectLabel(GL_TEXTURE, t.get(), -1, label);
  return t;
}

}  // namespace

DiffusionPass::DiffusionPass(int size)
    : size_(size),
      irradiance_programs_({"tsd_irradiance.vert", "tsd_irradiance.frag"},
                           ShadingVariant{}.defines()),
      blur_program_(build_program({"tsd_blur.vert", "tsd_blur.frag"})),
      fbo_(make_framebuffer()),
      irradiance_(atlas_texture(size, "diffusion: irradiance")),
      stretch_(atlas_texture(size, "diffusion: metres per atlas uv", GL_RG16F)),
      temp_(atlas_texture(size, "diffusion: half-blurred")),
      blurred_{atlas_texture(size, "diffusion: blur 1"), atlas_texture(size, "diffusion: blur 2"),
               atlas_texture(size, "diffusion: blur 3")},
      empty_vao_(make_vertex_array()) {}

void DiffusionPass::blur(const Texture& source, const Texture& target, float sigma) {
  // Horizontal into temp_, vertical into target.
  glUseProgram(blur_program_.get());
  glNamedFramebufferTexture(fbo_.get(), GL_COLOR_ATTACHMENT0, temp_.get(), 0);
  glProgramUniform2f(blur_program_.get(), kSigmaMetres, sigma, 0.0f);
  glBindTextureUnit(0, source.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glNamedFramebufferTexture(fbo_.get(), GL_COLOR_ATTACHMENT0, target.get(), 0);
  glProgramUniform2f(blur_program_.get(), kSigmaMetres, 0.0f, sigma);
  glBindTextureUnit(0, temp_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void DiffusionPass::run(GLuint vao, GLsizei index_count, glm::vec2 atlas_per_metre, float repeat,
                        const std::string& shading) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
  glNamedFramebufferTexture(fbo_.get(), GL_COLOR_ATTACHMENT0, irradiance_.get(), 0);
  glNamedFramebufferTexture(fbo_.get(), GL_COLOR_ATTACHMENT1, stretch_.get(), 0);
  const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo_.get(), 2, both);
  glViewport(0, 0, size_, size_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_FRAMEBUFFER_SRGB);  // linear floats
  glDisable(GL_BLEND);
  const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, clear);
  glClearBufferfv(GL_COLOR, 1, clear);
  const GLuint irradiance = irradiance_programs_.get(shading);
  glUseProgram(irradiance);
  glProgramUniform1f(irradiance, kRepeat, repeat);
  glProgramUniform1f(irradiance, kAtlasSize, static_cast<float>(size_));
  glBindVertexArray(vao);
  glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
  // The blurs read the stretch map: it must not stay attached while they draw.
  glNamedFramebufferTexture(fbo_.get(), GL_COLOR_ATTACHMENT1, 0, 0);
  glNamedFramebufferDrawBuffer(fbo_.get(), GL_COLOR_ATTACHMENT0);

  glBindVertexArray(empty_vao_.get());
  glProgramUniform2f(blur_program_.get(), kFallback, 1.0f / atlas_per_metre.x,
                     1.0f / atlas_per_metre.y);
  glBindTextureUnit(1, stretch_.get());
  float previous = 0.0f;
  const Texture* source = &irradiance_;
  for (std::size_t k = 0; k < kSigma.size(); ++k) {
    // Each blur adds its variance to the previous one's (Gaussians convolve by adding them).
    const float sigma = std::sqrt(kSigma[k] * kSigma[k] - previous * previous);
    blur(*source, blurred_[k], sigma);
    source = &blurred_[k];
    previous = kSigma[k];
  }
  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
}

void DiffusionPass::bind_results() const {
  for (std::size_t k = 0; k < blurred_.size(); ++k)
    glBindTextureUnit(static_cast<GLuint>(10 + k), blurred_[k].get());
}

}  // namespace clothlab::vis
