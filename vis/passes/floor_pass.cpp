#include "vis/passes/floor_pass.hpp"

#include "vis/gl/program.hpp"
#include "vis/gl/uploads.hpp"
#include "vis/textures/floor_texture.hpp"

namespace clothlab::vis {
namespace {

// Explicit uniform locations of shaders/floor.vert (no lookups per frame).
constexpr GLint kFloorHalfSize = 0, kFloorTileSize = 1;

}  // namespace

FloorPass::FloorPass()
    : program_(build_program({"floor.vert", "floor.frag"})),
      tiles_(upload_texture(make_floor_texture())) {
  glObjectLabel(GL_TEXTURE, tiles_.get(), -1, "floor tiles");
}

void FloorPass::draw(const ViewSettings& view, GLuint empty_vao) const {
  glUseProgram(program_.get());
  glProgramUniform1f(program_.get(), kFloorHalfSize, view.floor_half_size);
  glProgramUniform1f(program_.get(), kFloorTileSize, view.floor_tile_size);
  glBindTextureUnit(0, tiles_.get());
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 6);
}

}  // namespace clothlab::vis
