#include "sim/cloth/grid_cloth.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/vec3_math.hpp"

namespace clothlab {

GridCloth build_grid_cloth(const ClothSpec& spec) {
  GridCloth g;
  g.nu = spec.resolution[0];
  g.nv = spec.resolution[1];
  g.du = g.nu > 1 ? spec.size[0] / (g.nu - 1) : 0.0;
  g.dv = g.nv > 1 ? spec.size[1] / (g.nv - 1) : 0.0;
  if (g.nu > 1 && g.nv > 1) {
    g.edge = std::min(g.du, g.dv);
  } else {
    g.edge = g.nu > 1 ? g.du : g.dv;
  }
  g.vertex_mass = spec.mass / g.vertex_count();

  const Vec3d u = normalised(spec.u_axis);
  const Vec3d v = normalised(spec.v_axis);
  g.positions.resize(static_cast<std::size_t>(g.vertex_count()));
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      Vec3d& p = g.positions[static_cast<std::size_t>(g.index(i, j))];
      for (int a = 0; a < 3; ++a) p[a] = spec.origin[a] + i * g.du * u[a] + j * g.dv * v[a];
    }
  }
  for (const auto& pin : spec.pins) g.pinned.push_back(g.index(pin[0], pin[1]));
  std::sort(g.pinned.begin(), g.pinned.end());
  g.pinned.erase(std::unique(g.pinned.begin(), g.pinned.end()), g.pinned.end());

  for (int j = 0; j + 1 < g.nv; ++j) {
    for (int i = 0; i + 1 < g.nu; ++i) {
      const int a = g.index(i, j), b = g.index(i + 1, j);
      const int c = g.index(i + 1, j + 1), d = g.index(i, j + 1);
      g.triangles.push_back({a, b, c});
      g.triangles.push_back({a, c, d});
    }
  }
  return g;
}

}  // namespace clothlab
