// The sky behind everything (docs/rendering.md section 7): Preetham's daylight model (vis/sky/)
// baked once into a cube map for the sun's direction and the turbidity, drawn as a full-screen
// triangle at the far plane where nothing else was drawn. Baked again only when the turbidity
// changes or the sun turns by more than kSkySunToleranceDeg (a bake costs about 4 ms on the CPU,
// while turning the sun by a quarter of a degree moves the sky's 8-bit sRGB values by more than
// one step in at most 0.1 % of its texels, tests/sky_test.cpp). The renderer places a spot
// light's sun from the casters' centre as the scene was set, so a moving cloth turns no sun.
#pragma once

#include <glm/glm.hpp>

#include "gl/objects.hpp"
#include "vis/sky/preetham_sky.hpp"

namespace clothlab::vis {

class SkyPass {
 public:
  explicit SkyPass(int face_size = 128);

  // Bakes the cube map for the sun towards `sun` (need not be normalised) and the turbidity,
  // unless it holds them already (the sun within kSkySunToleranceDeg); returns it (the floor's
  // haze samples it at the horizon).
  GLuint prepare(glm::vec3 sun, float turbidity);
  // Draws the sky prepared last into the bound framebuffer's empty pixels: call after the
  // opaque geometry, with its depth buffer.
  void draw(const glm::mat4& view_proj, glm::vec3 eye);

  int bakes() const { return bakes_; }  // how often the cube map was baked (tests)

 private:
  void bake(glm::vec3 sun, float turbidity);

  int face_size_;
  Program program_;
  Texture cube_;
  VertexArray empty_vao_;
  glm::vec3 baked_sun_{0.0f};
  float baked_turbidity_ = -1.0f;
  int bakes_ = 0;
};

}  // namespace clothlab::vis
