// The shadow map: every caster's depth from the light (docs/rendering.md section 6), drawn before
// the main pass whenever a shadow filter or the depth view (key 7) needs it, and nowhere else. One
// depth texture, read through two sampler objects: a comparing one for PCF and a plain one for
// PCSS's blocker search and the depth view.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "gl/objects.hpp"

namespace clothlab::vis {

class ShadowPass {
 public:
  ShadowPass();

  // Binds the map as the draw target (size x size texels, recreated when the size changes),
  // clears it and sets the caster state: depth only, no culling (the cloth is an open sheet),
  // slope-scaled polygon offset. Needs the Frame block (light_view_proj) bound.
  void begin(int size);
  // Casters with positions at attribute 0 of `vao`.
  void draw_triangles(GLuint vao, GLsizei index_count, const glm::mat4& model,
                      std::size_t first_index = 0);
  void draw_floor(float height, float half_size);
  // Restores the state begin() changed (not the framebuffer: the caller binds its own).
  void end();

  // Coloured shadows of a translucent cloth (mode 5; docs/rendering.md section 5, the OptiFine/Iris
  // scheme): after the all-casters map, a second depth map of the opaque casters only and a
  // colour map holding the product of the transmittances of the translucent layers.
  void begin_opaque();  // the opaque-only depth map as the target (draw the opaque casters)
  // The colour map as the target, cleared to white: draw the translucent casters with
  // draw_transmittance (multiplicative blending, no depth test: layers multiply).
  void begin_transmittance();
  void draw_transmittance(GLuint vao, GLsizei index_count, std::size_t first_index, GLuint albedo,
                          float repeat, glm::vec3 flat_albedo, bool use_flat, float coverage,
                          float transmission);
  bool translucent() const { return translucent_; }

  // Binds the maps for sampling as shaders/lighting.glsl expects: units 6 (comparing) and 7
  // (plain) the all-casters map; with translucent casters 8 the opaque-only map (comparing) and
  // 9 the transmittance colour.
  void bind_textures() const;
  int size() const { return size_; }

 private:
  Program program_, transmittance_program_;
  Framebuffer fbo_, opaque_fbo_, colour_fbo_;
  Texture depth_, opaque_depth_, colour_;
  bool translucent_ = false;                 // the opaque and colour maps were drawn this frame
  Sampler compare_sampler_, plain_sampler_;  // PCF's comparing one; a plain one for PCSS
  VertexArray empty_vao_;
  int size_ = 0;
};

}  // namespace clothlab::vis
