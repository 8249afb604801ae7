#include "vis/render/gpu_mesh.hpp"

#include <cstdint>
#include <vector>

#include "vis/meshes/mesh.hpp"

namespace clothlab::vis {

GpuMesh upload_mesh(const Mesh& mesh) {
  GpuMesh o;
  o.vao = make_vertex_array();
  o.vbo = make_buffer();
  o.ebo = make_buffer();
  std::vector<float> interleaved;
  interleaved.reserve(6 * mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
    interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
  }
  glNamedBufferStorage(o.vbo.get(), static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                       interleaved.data(), 0);
  glNamedBufferStorage(o.ebo.get(),
                       static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                       mesh.indices.data(), 0);
  glVertexArrayVertexBuffer(o.vao.get(), 0, o.vbo.get(), 0, 6 * sizeof(float));
  for (GLuint a = 0; a < 2; ++a) {
    glEnableVertexArrayAttrib(o.vao.get(), a);
    glVertexArrayAttribFormat(o.vao.get(), a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
    glVertexArrayAttribBinding(o.vao.get(), a, 0);
  }
  glVertexArrayElementBuffer(o.vao.get(), o.ebo.get());
  o.indices = static_cast<GLsizei>(mesh.indices.size());
  return o;
}

}  // namespace clothlab::vis
