// The floor: a tiled stone plane at the view's floor height, lit and shadowed like the rest
// (shaders/floor.vert, floor.frag). Needs a current GL 4.5 context.
#pragma once

#include <string>

#include "vis/gl/objects.hpp"
#include "vis/gl/program_variants.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

class FloorPass {
 public:
  FloorPass();
  // Draws into the bound framebuffer (the Frame block bound, depth test on), lit by the shading
  // variant's shader (ShadingVariant::defines).
  void draw(const ViewSettings& view, GLuint empty_vao, const std::string& shading);

 private:
  ProgramVariants programs_;
  Texture tiles_;
};

}  // namespace clothlab::vis
