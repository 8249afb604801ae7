#include "vis/render/gpu_mesh.hpp"

#include <cstdint>
#include <vector>

#include "gl/uploads.hpp"
#include "vis/meshes/mesh.hpp"

namespace clothlab::vis {

GpuMesh upload_mesh(const Mesh& mesh) {
  std::vector<float> interleaved;
  interleaved.reserve(6 * mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
    interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
  }
  GpuMesh o;
  o.vao = make_vertex_array();
  o.vbo = static_buffer(interleaved);
  o.ebo = static_buffer(mesh.indices);
  vertex_buffer(o.vao.get(), 0, o.vbo.get(), 0, 6 * sizeof(float));
  for (GLuint a = 0; a < 2; ++a) float_attribute(o.vao.get(), a, 0, 3, a * 3 * sizeof(float));
  element_buffer(o.vao.get(), o.ebo.get());
  o.indices = static_cast<GLsizei>(mesh.indices.size());
  return o;
}

}  // namespace clothlab::vis
