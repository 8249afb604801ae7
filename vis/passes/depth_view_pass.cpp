#include "vis/passes/depth_view_pass.hpp"

#include "gl/program.hpp"

namespace clothlab::vis {
namespace {

constexpr GLint kViewport = 0;  // explicit uniform location in shaders/depth_view.frag

}  // namespace

DepthViewPass::DepthViewPass() : program_(build_program({"depth_view.vert", "depth_view.frag"})) {}

void DepthViewPass::draw(int width, int height, GLuint colormap, GLuint empty_vao) const {
  glUseProgram(program_.get());
  glProgramUniform2f(program_.get(), kViewport, float(width), float(height));
  glBindTextureUnit(1, colormap);
  glBindVertexArray(empty_vao);
  glDisable(GL_DEPTH_TEST);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glBindVertexArray(0);
}

}  // namespace clothlab::vis
