#include "vis/passes/springs_pass.hpp"

#include "vis/gl/program.hpp"
#include "vis/render/cloth_geometry.hpp"

namespace clothlab::vis {

SpringsPass::SpringsPass()
    : program_(build_program({"springs.vert", "springs.geom", "springs.frag"})) {}

void SpringsPass::draw(const ClothGeometry& cloth) const {
  glUseProgram(program_.get());
  glBindVertexArray(cloth.line_vao());
  glDrawElements(GL_LINES, cloth.line_indices(), GL_UNSIGNED_INT, nullptr);
}

}  // namespace clothlab::vis
