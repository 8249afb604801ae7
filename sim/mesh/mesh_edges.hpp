// The edges of a triangle mesh, each once: what a mesh cloth's springs, its edge contacts and the
// scene's checks of an OBJ cloth (valence, zero-length edges) are built from.
#pragma once

#include <array>
#include <vector>

namespace clothlab {

// Every edge of the triangles once, as (a, b) with a < b, sorted.
std::vector<std::array<int, 2>> mesh_edges(const std::vector<std::array<int, 3>>& triangles);

}  // namespace clothlab
