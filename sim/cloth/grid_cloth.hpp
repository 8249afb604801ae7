// A rectangular grid of vertices as docs/design.md defines it: vertex (i, j) sits at
// origin + i * du * u + j * dv * v, with du = size_u / (res_u - 1) and u, v the unit axes.
#pragma once

#include <array>
#include <vector>

#include "sim/scene/scene.hpp"

namespace clothlab {

struct GridCloth {
  int nu = 0, nv = 0;            // vertices along u and v
  double du = 0.0, dv = 0.0;     // spacing along u and v (0 where a direction has 1 vertex)
  double edge = 0.0;             // the smaller spacing of the directions with >= 2 vertices
  double vertex_mass = 0.0;      // kg, total mass / vertex count
  std::vector<Vec3d> positions;  // index i + j * nu
  std::vector<int> pinned;       // local vertex indices, sorted
  std::vector<std::array<int, 3>> triangles;  // two per grid quad, counter-clockwise about u x v
  bool wrap_u = false;  // a tube: column nu - 1 is joined to column 0 (the seam)
  // A mesh cloth (sim/cloth/mesh_cloth.hpp): no grid, nu = vertex count, nv = 1; its triangles
  // come from the OBJ and each vertex has its own mass (`masses`, lumped by area).
  bool mesh = false;
  std::vector<double> masses;  // empty: every vertex has vertex_mass

  int index(int i, int j) const { return i + j * nu; }
  int vertex_count() const { return nu * nv; }
};

// Builds the geometry of one grid cloth. The spec must have been validated.
GridCloth build_grid_cloth(const ClothSpec& spec);

}  // namespace clothlab
