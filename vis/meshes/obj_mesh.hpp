// A triangle mesh read from an OBJ file (sim/mesh/triangle_mesh.hpp) as a drawable mesh: for
// mesh colliders and OBJ scenery.
#pragma once

#include "sim/mesh/triangle_mesh.hpp"
#include "vis/meshes/mesh.hpp"

namespace clothlab::vis {

// In the OBJ's own coordinates. Flat (smooth = false): each triangle gets its own three vertices
// with the face normal, so the edges of a chair stay crisp. Smooth: vertices are shared and each
// normal is the sum of the incident faces' cross products (area-weighted), normalised. No uvs
// are read (they are zero); degenerate triangles are dropped.
Mesh make_obj_mesh(const TriangleMesh& obj, bool smooth);

}  // namespace clothlab::vis
