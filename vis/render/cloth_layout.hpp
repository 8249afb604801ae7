// The cloth's vertex layout for drawing, as plain data (no GL): render vertices are the
// solver's vertices (same indices), then for every tube (wrap_u) one copy of column 0 per row at
// u = 1, which the seam's triangles use instead of column 0 so the texture wraps round the ring
// rather than running back from 1 to 0 across one quad. Built once per solver (set_cloth).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "sim/model/model.hpp"

namespace clothlab {
class SolverState;
}  // namespace clothlab

namespace clothlab::vis {

struct ClothLayout {
  std::size_t vertices = 0;      // the solver's
  std::vector<int> seam_copies;  // render vertex vertices + k copies solver vertex [k]
  std::vector<ClothRange> cloths;
  // Static attributes per render vertex, one block each: UV (2 floats: i / (nu - 1), j / (nv -
  // 1) on a grid; i / nu round a tube, its seam copies at u = 1; planar on a mesh), rest
  // position (3), and the place in mode 6's UV atlas (2: cloth k of K in rows k / K .. (k+1) / K).
  std::vector<float> fixed;
  glm::vec2 atlas_per_metre{1.0f};       // UV-atlas units per metre of cloth (u, v)
  std::vector<std::uint32_t> triangles;  // the solver's, the seam's quads on their copies
  std::vector<std::uint32_t> lines;      // every spring once
  // Mesh cloths' tangents come from their triangles and UVs (empty without a mesh cloth).
  std::vector<float> mesh_uvs;
  std::vector<std::array<int, 3>> mesh_triangles;

  std::size_t render_vertices() const { return vertices + seam_copies.size(); }
};

ClothLayout make_cloth_layout(const SolverState& solver);

}  // namespace clothlab::vis
