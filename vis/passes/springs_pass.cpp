#include "vis/passes/springs_pass.hpp"

#include "gl/program.hpp"
#include "vis/render/cloth_geometry.hpp"

namespace clothlab::vis {

SpringsPass::SpringsPass()
    : program_(build_program({"springs.vert", "springs.geom", "springs.frag"})),
      vertices_program_(build_program({"vertices.vert", "vertices.frag"})) {}

void SpringsPass::draw(const ClothGeometry& cloth) const {
  glUseProgram(program_.get());
  glBindVertexArray(cloth.line_vao());
  glDrawElements(GL_LINES, cloth.line_indices(), GL_UNSIGNED_INT, nullptr);
}

void SpringsPass::draw_vertices(const ClothGeometry& cloth) const {
  glUseProgram(vertices_program_.get());
  glEnable(GL_PROGRAM_POINT_SIZE);
  glBindVertexArray(cloth.cloth_vao());
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(cloth.render_vertex_count()));
  glDisable(GL_PROGRAM_POINT_SIZE);
}

}  // namespace clothlab::vis
