// Per-vertex tangent frame of a grid cloth for normal mapping, recomputed every frame from the
// current positions and normals (docs/rendering.md section 3). Plain arrays, no solver dependency.
#pragma once

#include <array>
#include <vector>

namespace clothlab {

// Grid cloth of nu x nv vertices, vertex (i, j) at index i + j * nu with UV
// (i / (nu - 1), j / (nv - 1)); `positions` and `normals` hold 3 floats per vertex, the normals
// unit length (as Solver::copy_normals gives them; they are renormalised here anyway). Writes 4
// floats per vertex to `tangents`:
//   xyz: T = normalize(dP/du - N (N . dP/du)), with dP/du by central differences along i
//        (one-sided on the first and last column);
//   w:   the handedness sign((dP/du x dP/dv) . N), +1 or -1 (+1 when that product is 0), so the
//        bitangent is B = w * (N x T) and points along dP/dv; det[T, B, N] = w.
// For a GridCloth, whose triangles (a, b, c) wind so that their normal is dP/du x dP/dv, w = +1
// unless the normals are flipped or the UVs mirrored.
// Degenerate cases, where dP/du has no part orthogonal to N (collapsed column, nu == 1, dP/du
// along N): T = normalize(dP/dv x N), the direction a right-handed frame with B along dP/dv
// would have; if that is degenerate too, a fixed function of N alone (Duff et al., "Building an
// orthonormal basis, revisited", JCGT 2017). A zero normal gives T = (1, 0, 0), w = +1.
// wrap_u (a tube, sim/cloth/tube_cloth.hpp): column nu - 1 neighbours column 0 across the seam,
// so dP/du is a central difference on every column, the seam's included (UV i / nu round the
// ring): the frame is as continuous across the seam as anywhere else.
// Allocation-free; each output depends only on the inputs, so rows may run in parallel.
// Does nothing when nu or nv < 1.
void compute_grid_tangents(int nu, int nv, const float* positions, const float* normals,
                           float* tangents, bool wrap_u = false);

// One row j of compute_grid_tangents (for callers that split rows between threads).
void compute_grid_tangent_row(int nu, int nv, int j, const float* positions, const float* normals,
                              float* tangents, bool wrap_u = false);

// A mesh cloth (sim/cloth/mesh_cloth.hpp): the same frame from its triangles and per-vertex
// UVs (Lengyel's method: E. Lengyel, "Computing Tangent Space Basis Vectors for an Arbitrary
// Mesh", 2001): each triangle's dP/du and dP/dv from its edges and UV differences, summed at its
// vertices, then T and w as above (degenerate cases likewise). `triangles` index the global
// arrays; only vertices first..last-1 are written; `scratch` holds 6 floats per vertex of
// that range (resized here when too small).
void compute_mesh_tangents(int first, int last, const std::vector<std::array<int, 3>>& triangles,
                           const float* positions, const float* normals, const float* uvs,
                           float* tangents, std::vector<float>& scratch);

}  // namespace clothlab
