#include "vis/passes/sky_pass.hpp"

#include <cmath>

#include "gl/program.hpp"
#include "vis/sky/preetham_sky.hpp"

namespace clothlab::vis {
namespace {

constexpr GLint kInverseViewProj = 0, kEye = 1;  // explicit uniform locations in shaders/sky.*
constexpr float kGroundBlendDeg = 20.0f;

}  // namespace

SkyPass::SkyPass(int face_size)
    : face_size_(face_size),
      program_(build_program({"sky.vert", "sky.frag"})),
      empty_vao_(make_vertex_array()) {}

void SkyPass::bake(glm::vec3 sun, float turbidity) {
  SkyParams params;
  params.sun_direction = sun;
  params.turbidity = turbidity;
  // Below the horizon the sky keeps its horizon colour for a while: the hazed floor meets it
  // there (the floor ends before the far plane, a fraction of a degree under the horizon).
  params.ground_blend_deg = kGroundBlendDeg;
  const CubeFaces faces = bake_sky(params, face_size_);
  cube_ = make_texture(GL_TEXTURE_CUBE_MAP);
  glTextureStorage2D(cube_.get(), 1, GL_RGB16F, face_size_, face_size_);
  for (int f = 0; f < 6; ++f)
    glTextureSubImage3D(cube_.get(), 0, 0, 0, f, face_size_, face_size_, 1, GL_RGB, GL_FLOAT,
                        faces.rgb[static_cast<std::size_t>(f)].data());
  glTextureParameteri(cube_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(cube_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(cube_.get(), wrap, GL_CLAMP_TO_EDGE);
  glObjectLabel(GL_TEXTURE, cube_.get(), -1, "sky cube map");
  baked_sun_ = sun;
  baked_turbidity_ = turbidity;
  ++bakes_;
}

GLuint SkyPass::prepare(glm::vec3 sun, float turbidity) {
  const float turned = glm::dot(glm::normalize(sun), glm::normalize(baked_sun_));
  if (!cube_ || !(turned >= std::cos(glm::radians(kSkySunToleranceDeg))) ||
      turbidity != baked_turbidity_)
    bake(sun, turbidity);
  // No seams between the faces (docs/rendering.md section 7), for the sky and the floor's haze.
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  return cube_.get();
}

void SkyPass::draw(const glm::mat4& view_proj, glm::vec3 eye) {
  const glm::mat4 inverse = glm::inverse(view_proj);
  glUseProgram(program_.get());
  glProgramUniformMatrix4fv(program_.get(), kInverseViewProj, 1, GL_FALSE, &inverse[0][0]);
  glProgramUniform3f(program_.get(), kEye, eye.x, eye.y, eye.z);
  glBindTextureUnit(0, cube_.get());
  glDepthFunc(GL_LEQUAL);  // only where the depth is still the cleared far plane
  glDepthMask(GL_FALSE);
  glBindVertexArray(empty_vao_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

}  // namespace clothlab::vis
