// Triangle meshes for scenery (the pole, props, test shapes): plain CPU arrays, no GL. The
// renderer uploads them; the generators live in vis/meshes/shapes.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace clothlab::vis {

// An indexed triangle mesh. positions, normals and uvs have one entry per vertex; tangents are
// optional (empty, or one per vertex: xyz unit tangent along +u, w = handedness +-1 so that the
// bitangent is w * cross(normal, tangent.xyz)). Triangles are counter-clockwise seen from
// outside (the side the normals point to).
struct Mesh {
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec4> tangents;
  std::vector<std::uint32_t> indices;  // 3 per triangle

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

// Axis-aligned bounding box; for an empty mesh min = +inf and max = -inf (empty() is true).
struct Bounds {
  glm::vec3 min{0.0f}, max{0.0f};
  bool empty() const { return min.x > max.x; }
  glm::vec3 centre() const { return 0.5f * (min + max); }
  glm::vec3 size() const { return max - min; }
};

Bounds mesh_bounds(const Mesh& mesh);

// Transforms positions by `m`, normals by the normal matrix transpose(inverse(mat3(m)))
// (renormalised) and tangent xyz by mat3(m) (re-orthogonalised against the new normal). A
// transform with negative determinant mirrors the mesh, so the triangle winding is reversed
// and the tangent handedness flipped to keep the mesh outward-facing and consistent.
void transform_mesh(Mesh& mesh, const glm::mat4& m);

// Signed volume enclosed by the triangles, sum of dot(p0, cross(p1, p2)) / 6; positive for a
// closed outward-facing (CCW from outside) mesh.
double signed_volume(const Mesh& mesh);

// Appends `other` to `mesh` (indices offset). Tangents are kept only if both have them (or
// `mesh` is empty).
void append_mesh(Mesh& mesh, const Mesh& other);

}  // namespace clothlab::vis
