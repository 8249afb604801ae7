#include "vis/passes/object_pass.hpp"

#include "vis/render/shading_variant.hpp"

namespace clothlab::vis {
namespace {

// Explicit uniform locations in shaders/object.vert and object.frag.
constexpr GLint kObjectModel = 0, kObjectColor = 1;

}  // namespace

ObjectPass::ObjectPass() : programs_({"object.vert", "object.frag"}, ShadingVariant{}.defines()) {}

void ObjectPass::begin(const std::string& shading) {
  program_ = programs_.get(shading);
  glUseProgram(program_);
  glEnable(GL_CULL_FACE);
}

void ObjectPass::draw(const GpuMesh& mesh, const glm::mat4& model, glm::vec3 color) const {
  glProgramUniformMatrix4fv(program_, kObjectModel, 1, GL_FALSE, &model[0][0]);
  glProgramUniform3f(program_, kObjectColor, color.r, color.g, color.b);
  glBindVertexArray(mesh.vao.get());
  glDrawElements(GL_TRIANGLES, mesh.indices, GL_UNSIGNED_INT, nullptr);
}

void ObjectPass::end() const {
  glDisable(GL_CULL_FACE);
  glBindVertexArray(0);
}

}  // namespace clothlab::vis
