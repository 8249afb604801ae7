// Procedural scenery meshes (pure CPU). Every generator returns positions, unit normals and uvs
// for all vertices, CCW-from-outside triangles, and unit tangents (analytic for the sphere and
// the box, compute_tangents() for the others; u runs to the right and v up seen from outside,
// so the handedness is +1 throughout). Closed
// shapes are watertight once vertices duplicated at UV seams are welded by position.
// Throw std::invalid_argument on non-positive sizes or too few segments.
#pragma once

#include <glm/glm.hpp>

#include "vis/meshes/mesh.hpp"

namespace clothlab::vis {

// Sphere about the origin, poles on +-y. `slices` >= 3 around y (u = longitude / 2pi, the seam
// at u = 0/1 duplicated), `stacks` >= 2 from +y (v = 1) to -y (v = 0). Smooth normals; the pole
// rows are one vertex per slice (u at the slice centre), so no triangle is degenerate.
Mesh make_uv_sphere(float radius, int slices, int stacks);

// Box about the origin with the given half extents (all > 0): 24 vertices (4 per face, flat
// face normals), 12 triangles, uvs [0,1]^2 per face.
Mesh make_box(glm::vec3 half_extents);

// Cylinder along +x from x = 0 to x = length (the pole a cloth hangs from). `slices` >= 3,
// smooth side normals, the seam duplicated (side u = x / length, v = angle / 2pi). With `caps`,
// flat discs at both ends (normals -x and +x, planar uvs); without, an open tube.
Mesh make_cylinder(float radius, float length, int slices, bool caps);

// Box with rounded edges and corners (the shape of a rounded box collider: the box of half
// extents h - r grown by r): `rounding` r is clamped to the smallest half extent, r <= 0 gives
// make_box. `segments` >= 1 steps per quarter circle of rounding; smooth normals, uvs [0,1]^2
// per face, tangents from compute_tangents().
Mesh make_rounded_box(glm::vec3 half_extents, float rounding, int segments);

// Capsule along y about the origin: the segment from (0, -half_length, 0) to (0, half_length, 0)
// grown by `radius` (half_length >= 0; 0 gives a sphere). `slices` >= 3 around y, `cap_stacks`
// >= 1 rings per hemisphere. Smooth normals, u = longitude / 2pi as on the UV sphere (seam
// duplicated), v = height from the bottom (0) to the top (1), analytic tangents (east).
Mesh make_capsule(float radius, float half_length, int slices, int cap_stacks);

// A (p, q) torus knot (p, q coprime, >= 1) swept with a tube: the centre line
//   c(t) = radius * ((2 + cos(q t)) / 2 * (cos(p t), sin(p t), 0) + (0, 0, sin(q t) / 2)),
// t in [0, 2pi), lies on a torus of major radius `radius` and minor radius radius / 2 (three.js'
// TorusKnotGeometry parametrisation). `segments` >= 3 rings along the curve, `sides` >= 3
// vertices per ring, u = along the curve, v = around the tube, both seams duplicated. The ring
// frame is parallel-transported (rotation minimising, double reflection) and its accumulated
// twist after one loop is spread evenly along the curve, so the tube closes without a seam.
Mesh make_torus_knot(int p, int q, float radius, float tube_radius, int segments, int sides);

// Per-vertex tangents from the uvs (Lengyel's method: E. Lengyel, "Computing Tangent Space Basis
// Vectors for an Arbitrary Mesh", Terathon Software 3D Graphics Library, 2001; also in
// "Mathematics for 3D Game Programming and Computer Graphics", sec. 7.8): accumulate dP/du and
// dP/dv of every triangle on its vertices, Gram-Schmidt dP/du against the normal, handedness
// w = sign(dot(cross(N, T), dP/dv)). Triangles with degenerate uvs are skipped; a vertex left
// without a usable dP/du gets an arbitrary unit tangent perpendicular to its normal. Fills
// mesh.tangents (one per vertex); leaves it empty if the mesh has no uvs.
void compute_tangents(Mesh& mesh);

}  // namespace clothlab::vis
