#include "vis/passes/floor_pass.hpp"

#include <algorithm>

#include "gl/program.hpp"
#include "gl/uploads.hpp"
#include "vis/render/shading_variant.hpp"
#include "vis/textures/floor_texture.hpp"
#include "vis/textures/image_texture.hpp"

namespace clothlab::vis {
namespace {

// Explicit uniform locations of shaders/floor.vert and floor.frag (no lookups per frame).
constexpr GLint kFloorHalfSize = 0, kFloorTileSize = 1, kFloorHaze = 2;

}  // namespace

FloorPass::FloorPass()
    : programs_({"floor.vert", "floor.frag"}, ShadingVariant{}.defines()),
      tiles_(upload_texture(make_floor_texture())) {
  glObjectLabel(GL_TEXTURE, tiles_.get(), -1, "floor tiles");
}

void FloorPass::draw(const ViewSettings& view, GLuint empty_vao, const std::string& shading,
                     GLuint sky_cube) {
  const GLuint program = programs_.get(shading);
  glUseProgram(program);
  // With a sky, out to where the haze has hidden it (kHazeReach haze distances, 1 - e^-9), and
  // at least the lit floor's size; the shadow map still covers floor_half_size only.
  const float haze = kFloorHazeDistances * view.camera.distance;
  const float half_size =
      sky_cube ? std::max(view.floor_half_size, kHazeReach * haze) : view.floor_half_size;
  glProgramUniform1f(program, kFloorHalfSize, half_size);
  glProgramUniform1f(program, kFloorTileSize, view.floor_tile_size);
  glProgramUniform4f(program, kFloorHaze, sky_cube ? 1.0f / haze : 0.0f, 0.0f, 0.0f, 0.0f);
  glBindTextureUnit(0, tiles_.get());
  glBindTextureUnit(1, sky_cube);
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 6);
}

}  // namespace clothlab::vis
