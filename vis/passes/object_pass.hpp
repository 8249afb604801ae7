// Lit closed objects: the scene's props (vis/render/scenery) and its colliders
// (vis/render/collider_scenery), through shaders/object.vert and object.frag with each object's
// model matrix and colour, back faces culled (planes carry a face for each side).
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "gl/program_variants.hpp"
#include "vis/render/gpu_mesh.hpp"

namespace clothlab::vis {

class ObjectPass {
 public:
  ObjectPass();  // builds the plain shading variant (a bad shader fails here)

  // Draws a batch: begin() with the frame's shading variant, draw() each object, end().
  void begin(const std::string& shading);
  void draw(const GpuMesh& mesh, const glm::mat4& model, glm::vec3 color) const;
  void end() const;

 private:
  ProgramVariants programs_;
  GLuint program_ = 0;  // the batch's
};

}  // namespace clothlab::vis
