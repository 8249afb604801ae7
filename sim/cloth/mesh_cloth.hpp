// Cloth from a triangle mesh (an OBJ file, shape = "mesh"): any topology, so any garment
// pattern or draped shape a modeller produces. Springs follow the mesh rather than the grid
// seed rule: one along every edge (stretch and shear) and one across every interior edge,
// between the two vertices opposite it (bending, Provot 1995's "flexion" springs for a
// triangle mesh), each with stiffness = stiffness * edge / rest_length, the rule every other
// shape uses, with `edge` the mesh's median edge length.
#pragma once

#include <vector>

#include "sim/cloth/grid_cloth.hpp"
#include "sim/cloth/seed_springs.hpp"
#include "sim/mesh/mesh_edges.hpp"

namespace clothlab {

// The cloth as placed (OBJ coordinates * scale, turned, moved by origin): nu = vertex count,
// nv = 1, mesh = true, the OBJ's triangles, pins from the spec (vertex k stored as (k, 0)).
// Mass is lumped by area (a third of each incident triangle's area), so a mesh with small
// triangles in one place is not heavier there; it sums to spec.mass. The spec must have been
// validated (shape "mesh", every vertex in a face, no zero-length edge).
GridCloth build_mesh_cloth(const ClothSpec& spec);

// Edge springs and bending springs (see above), sorted by (a, b), each pair once (a bending
// pair that is also an edge, as on a tetrahedron, stays one edge spring).
std::vector<Spring> mesh_springs(const GridCloth& cloth, const SpringStiffness& k);

}  // namespace clothlab
