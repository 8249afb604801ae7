// The floor: a tiled stone plane at the view's floor height, lit and shadowed like the rest
// (shaders/floor.vert, floor.frag). Needs a current GL 4.5 context.
#pragma once

#include <string>

#include "gl/objects.hpp"
#include "gl/program_variants.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

// The haze distance in camera distances: the floor at the cloth is 0.7 % hazed, at 12 camera
// distances 63 %, and it is drawn out to kHazeReach haze distances (99.99 %), inside the far
// plane (100 camera distances, OrbitCamera::projection).
inline constexpr float kFloorHazeDistances = 12.0f;
inline constexpr float kHazeReach = 3.0f;

class FloorPass {
 public:
  FloorPass();
  // Draws into the bound framebuffer (the Frame block bound, depth test on), lit by the shading
  // variant's shader (ShadingVariant::defines). With the sky's cube map (0: none) the floor
  // reaches out to the horizon and fades into the sky's colour there.
  void draw(const ViewSettings& view, GLuint empty_vao, const std::string& shading,
            GLuint sky_cube);

 private:
  ProgramVariants programs_;
  Texture tiles_;
};

}  // namespace clothlab::vis
