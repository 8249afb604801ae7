// The assignment's "seed" spring rule (design.md): every vertex pair closer than 2*sqrt(2)*edge
// is joined by a spring of stiffness k = stiffness * edge / rest_length. On a square grid this is
// the 20-neighbour stencil (offsets with di^2 + dj^2 < 8): structural, shear and bending springs.
#pragma once

#include <vector>

#include "sim/cloth/grid_cloth.hpp"

namespace clothlab {

struct Spring {
  int a = 0, b = 0;          // vertex indices, a < b
  double rest_length = 0.0;  // m
  double stiffness = 0.0;    // N/m
};

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
