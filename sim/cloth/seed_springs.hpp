// The assignment's "seed" spring rule (docs/design.md): every vertex pair closer than
// 2*sqrt(2)*edge is joined by a spring of stiffness k = stiffness * edge / rest_length. On a square
// grid this is the 20-neighbour stencil (offsets with di^2 + dj^2 < 8): structural, shear and
// bending springs.
#pragma once

#include <vector>

#include "sim/cloth/grid_cloth.hpp"

namespace clothlab {

struct Spring {
  int a = 0, b = 0;          // vertex indices, a < b
  double rest_length = 0.0;  // m
  double stiffness = 0.0;    // N/m
};

// One neighbour offset of the seed rule on a regular grid: vertex (i, j) is joined to
// (i + di, j + dj) wherever both lie in the grid. The same offset has the same rest length and
// stiffness everywhere on the grid.
struct GridOffset {
  int di = 0, dj = 0;
  double rest_length = 0.0;  // m
  double stiffness = 0.0;    // N/m
};

// The offsets joined by the seed rule with dj > 0, or dj == 0 and di > 0 (each pair once),
// sorted by (dj, di), i.e. by the neighbour's vertex index.
std::vector<GridOffset> seed_stencil_half(const GridCloth& grid, double stiffness);

// True when two vertices at squared distance dist2 are joined. The pair at exactly
// 2*sqrt(2)*edge (offset (2, 2) on a square grid) is not "closer than" and stays unjoined; the
// relative margin keeps that decision immune to round-off in the positions.
bool seed_rule_joins(double dist2, double edge);

// O(N): walks the grid neighbourhood of each vertex. Springs sorted by (a, b).
std::vector<Spring> seed_springs_grid(const GridCloth& grid, double stiffness);

// O(N^2): the assignment's all-pairs loop over positions; the reference for tests only.
std::vector<Spring> seed_springs_all_pairs(const std::vector<Vec3d>& positions, double edge,
                                           double stiffness);

}  // namespace clothlab
