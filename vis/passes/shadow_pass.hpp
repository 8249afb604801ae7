// The shadow map: every caster's depth from the light (rendering.md section 6), drawn before the
// main pass whenever a shadow filter or the depth view (key 7) needs it, and nowhere else. One
// depth texture, read through two sampler objects: a comparing one for PCF and a plain one for
// PCSS's blocker search and the depth view.
#pragma once

#include <glm/glm.hpp>

#include "vis/gl/objects.hpp"

namespace clothlab::vis {

class ShadowPass {
 public:
  ShadowPass();

  // Binds the map as the draw target (size x size texels, recreated when the size changes),
  // clears it and sets the caster state: depth only, no culling (the cloth is an open sheet),
  // slope-scaled polygon offset. Needs the Frame block (light_view_proj) bound.
  void begin(int size);
  // Casters with positions at attribute 0 of `vao`.
  void draw_triangles(GLuint vao, GLsizei index_count, const glm::mat4& model);
  void draw_floor(float height, float half_size);
  // Restores the state begin() changed (not the framebuffer: the caller binds its own).
  void end();

  // Binds the map for sampling: units 6 (comparing) and 7 (plain), as shaders/frame.glsl expects.
  void bind_textures() const;
  int size() const { return size_; }

 private:
  Program program_;
  Framebuffer fbo_;
  Texture depth_;
  struct Samplers {  // GL sampler objects (no RAII type in vis/gl for them yet)
    GLuint compare = 0, plain = 0;
    Samplers() = default;
    Samplers(const Samplers&) = delete;
    Samplers& operator=(const Samplers&) = delete;
    ~Samplers();
  } samplers_;
  VertexArray empty_vao_;
  int size_ = 0;
};

}  // namespace clothlab::vis
