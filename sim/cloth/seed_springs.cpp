#include "sim/cloth/seed_springs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace clothlab {

bool seed_rule_joins(double dist2, double edge) {
  const double reach2 = 8.0 * edge * edge;  // (2 sqrt(2) edge)^2
  return dist2 > 0.0 && dist2 < reach2 * (1.0 - 1e-9);
}

double class_stiffness(const SpringStiffness& k, int di, int dj) {
  const int longest = std::max(std::abs(di), std::abs(dj));
  if (longest > 1) return k.bend;
  return di != 0 && dj != 0 ? k.shear : k.stretch;
}

std::vector<GridOffset> seed_stencil_half(const GridCloth& g, const SpringStiffness& k) {
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
      offsets.push_back({di, dj, rest, class_stiffness(k, di, dj) * g.edge / rest});
    }
  }
  return offsets;
}

std::vector<Spring> seed_springs_grid(const GridCloth& g, const SpringStiffness& k) {
  const std::vector<GridOffset> stencil = seed_stencil_half(g, k);
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
                                           const SpringStiffness& k) {
  std::vector<Spring> springs;
  const int n = static_cast<int>(p.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      double dist2 = 0.0;
      for (int c = 0; c < 3; ++c) dist2 += (p[b][c] - p[a][c]) * (p[b][c] - p[a][c]);
      if (!seed_rule_joins(dist2, edge)) continue;
      const double rest = std::sqrt(dist2);
      const double c = rest < 1.2 * edge ? k.stretch : rest < 1.5 * edge ? k.shear : k.bend;
      springs.push_back({a, b, rest, c * edge / rest});
    }
  }
  return springs;
}

}  // namespace clothlab
