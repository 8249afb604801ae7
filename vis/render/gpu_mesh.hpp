// A scenery mesh uploaded for drawing: positions and normals interleaved at attributes 0 and 1
// (what shaders/object.vert and the shadow pass read), indexed triangles. Shared by the scene's
// props (Scenery) and the colliders (ColliderScenery).
#pragma once

#include "gl/objects.hpp"

namespace clothlab::vis {

struct Mesh;

struct GpuMesh {
  VertexArray vao;
  Buffer vbo, ebo;
  GLsizei indices = 0;
};

// Uploads `mesh` into immutable buffers (it never changes; a moving object moves by its model
// matrix).
GpuMesh upload_mesh(const Mesh& mesh);

}  // namespace clothlab::vis
