// Texture coordinates for a mesh cloth (sim/cloth/mesh_cloth.hpp), whose OBJ brings none we use:
// its rest shape projected onto the plane of its two longest bounding-box axes, one scale for
// both (so the weave stays square), u along the longest axis from 0 to 1.
#pragma once

#include <glm/glm.hpp>

namespace clothlab::vis {

// Writes 2 floats per vertex first..last-1 of `rest` (3 floats per vertex, global indices) into
// uv (global indices, 2 floats per vertex). Returns the metres that u = 1 and v = 1 span (both
// the longest extent, at least 1e-6).
glm::vec2 planar_uvs(const float* rest, int first, int last, float* uv);

}  // namespace clothlab::vis
