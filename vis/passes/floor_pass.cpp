#include "vis/passes/floor_pass.hpp"

#include "vis/gl/program.hpp"
#include "vis/gl/uploads.hpp"
#include "vis/render/shading_variant.hpp"
#include "vis/textures/floor_texture.hpp"

namespace clothlab::vis {
namespace {

// Explicit uniform locations of shaders/floor.vert (no lookups per frame).
constexpr GLint kFloorHalfSize = 0, kFloorTileSize = 1;

}  // namespace

FloorPass::FloorPass()
    : programs_({"floor.vert", "floor.frag"}, ShadingVariant{}.defines()),
      tiles_(upload_texture(make_floor_texture())) {
  glObjectLabel(GL_TEXTURE, tiles_.get(), -1, "floor tiles");
}

void FloorPass::draw(const ViewSettings& view, GLuint empty_vao, const std::string& shading) {
  const GLuint program = programs_.get(shading);
  glUseProgram(program);
  glProgramUniform1f(program, kFloorHalfSize, view.floor_half_size);
  glProgramUniform1f(program, kFloorTileSize, view.floor_tile_size);
  glBindTextureUnit(0, tiles_.get());
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 6);
}

}  // namespace clothlab::vis
