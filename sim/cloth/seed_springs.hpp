// The assignment's "seed" spring rule (docs/design.md): every vertex pair closer than
// 2*sqrt(2)*edge is joined by a spring of stiffness k = c * edge / rest_length, where c is the
// specific stiffness of the spring's class. On a square grid this is the 20-neighbour stencil
// (offsets with di^2 + dj^2 < 8): stretch (axis neighbours), shear (diagonals) and bend springs
// (two steps along an axis and the knight's moves), as Provot (1995) names them.
#pragma once

#include <vector>

#include "sim/cloth/grid_cloth.hpp"

namespace clothlab {

// The specific stiffness (N/m for a spring one edge long) of each class of spring.
struct SpringStiffness {
  double stretch = 0.0, shear = 0.0, bend = 0.0;
  static SpringStiffness uniform(double k) { return {k, k, k}; }
  static SpringStiffness of(const SpringSpec& s) {
    return {s.stretch.value_or(s.stiffness), s.shear.value_or(s.stiffness),
            s.bend.value_or(s.stiffness)};
  }
};

// The class of grid offset (di, dj): one step along an axis stretches, one step along both
// shears, anything longer bends.
double class_stiffness(const SpringStiffness& k, int di, int dj);

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
std::vector<GridOffset> seed_stencil_half(const GridCloth& grid, const SpringStiffness& k);

// True when two vertices at squared distance dist2 are joined. The pair at exactly
// 2*sqrt(2)*edge (offset (2, 2) on a square grid) is not "closer than" and stays unjoined; the
// relative margin keeps that decision immune to round-off in the positions.
bool seed_rule_joins(double dist2, double edge);

// O(N): walks the grid neighbourhood of each vertex. Springs sorted by (a, b).
std::vector<Spring> seed_springs_grid(const GridCloth& grid, const SpringStiffness& k);

// O(N^2): the assignment's all-pairs loop over positions; the reference for tests only. The
// class comes from the rest length: about one edge stretches, about sqrt(2) edges shears.
std::vector<Spring> seed_springs_all_pairs(const std::vector<Vec3d>& positions, double edge,
                                           const SpringStiffness& k);

}  // namespace clothlab
