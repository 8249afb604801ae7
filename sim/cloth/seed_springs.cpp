#include "sim/cloth/seed_springs.hpp"

#include <cmath>

namespace clothlab {

bool seed_rule_joins(double dist2, double edge) {
  const double reach2 = 8.0 * edge * edge;  // (2 sqrt(2) edge)^2
  return dist2 > 0.0 && dist2 < reach2 * (1.0 - 1e-9);
}

std::vector<Spring> seed_springs_grid(const GridCloth& g, double stiffness) {
  std::vector<Spring> springs;
  if (g.edge <= 0.0) return springs;
  const double reach = 2.0 * std::sqrt(2.0) * g.edge;
  const int ri = g.du > 0.0 ? static_cast<int>(std::ceil(reach / g.du)) : 0;
  const int rj = g.dv > 0.0 ? static_cast<int>(std::ceil(reach / g.dv)) : 0;
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      const int a = g.index(i, j);
      // Only neighbours with a larger index, so each pair appears once and (a, b) are sorted.
      for (int dj = 0; dj <= rj && j + dj < g.nv; ++dj) {
        for (int di = -ri; di <= ri; ++di) {
          if (dj == 0 && di <= 0) continue;
          if (i + di < 0 || i + di >= g.nu) continue;
          const double x = di * g.du, y = dj * g.dv;
          const double dist2 = x * x + y * y;
          if (!seed_rule_joins(dist2, g.edge)) continue;
          const double rest = std::sqrt(dist2);
          springs.push_back({a, g.index(i + di, j + dj), rest, stiffness * g.edge / rest});
        }
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
