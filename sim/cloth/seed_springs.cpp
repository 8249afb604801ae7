#include "sim/cloth/seed_springs.hpp"

#include <algorithm>
#include <cmath>

namespace clothlab {

bool seed_rule_joins(double dist2, double edge) {
  const double reach2 = 8.0 * edge * edge;  // (2 sqrt(2) edge)^2
  return dist2 > 0.0 && dist2 < reach2 * (1.0 - 1e-9);
}

std::vector<GridOffset> seed_stencil_half(const GridCloth& g, double stiffness) {
  std::vector<GridOffset> offsets;
  if (g.edge <= 0.0) return offsets;
  const double reach = 2.0 * std::sqrt(2.0) * g.edge;
  // Reach in grid steps, capped by the grid itself (a 1-vertex direction has no reach).
  const int ri = g.du > 0.0 ? std::min(g.nu - 1, static_cast<int>(std::ceil(reach / g.du))) : 0;
  const int rj = g.dv > 0.0 ? std::min(g.nv - 1, static_cast<int>(std::ceil(reach / g.dv))) : 0;
  for (int dj = 0; dj <= rj; ++dj) {
    for (int di = -ri; di <= ri; ++di) {
      if (dj == 0 && di <= 0) continue;
      const double x = di * g.du, y = dj * g.dv;
      const double dist2 = x * x + y * y;
      if (!seed_rule_joins(dist2, g.edge)) continue;
      const double rest = std::sqrt(dist2);
      offsets.push_back({di, dj, rest, stiffness * g.edge / rest});
    }
  }
  return offsets;
}

std::vector<Spring> seed_springs_grid(const GridCloth& g, double stiffness) {
  const std::vector<GridOffset> stencil = seed_stencil_half(g, stiffness);
  std::vector<Spring> springs;
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      for (const GridOffset& o : stencil) {
        if (i + o.di < 0 || i + o.di >= g.nu || j + o.dj >= g.nv) continue;
        springs.push_back({g.index(i, j), g.index(i + o.di, j + o.dj), o.rest_length, o.stiffness});
      }
    }
  }
  return springs;
}

std::vector<Spring> seed_springs_all_pairs(const std::vector<Vec3d>& p, double edge,
                                           double stiffness) {
  std::vector<Spring> springs;
  const int n = static_cast<int>(p.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      double dist2 = 0.0;
      for (int k = 0; k < 3; ++k) dist2 += (p[b][k] - p[a][k]) * (p[b][k] - p[a][k]);
      if (!seed_rule_joins(dist2, edge)) continue;
      const double rest = std::sqrt(dist2);
      springs.push_back({a, b, rest, stiffness * edge / rest});
    }
  }
  return springs;
}

}  // namespace clothlab
