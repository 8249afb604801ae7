#include "sim/cloth/tube_cloth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/core/vec3_math.hpp"

namespace clothlab {
namespace {

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double point_distance(const Vec3d& a, const Vec3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

GridCloth build_tube_cloth(const ClothSpec& spec) {
  GridCloth g;
  g.wrap_u = true;
  g.nu = spec.resolution[0];
  g.nv = spec.resolution[1];
  const Vec3d axis = normalised(spec.v_axis);
  // The seam's direction, made perpendicular to the axis; the ring turns from it towards
  // axis x seam.
  Vec3d seam = normalised(spec.u_axis);
  const double along = seam[0] * axis[0] + seam[1] * axis[1] + seam[2] * axis[2];
  for (int a = 0; a < 3; ++a) seam[a] -= along * axis[a];
  seam = normalised(seam);
  const Vec3d turn = cross(axis, seam);
  g.positions.resize(static_cast<std::size_t>(g.vertex_count()));
  for (int j = 0; j < g.nv; ++j) {
    const double s = double(j) / double(g.nv - 1);
    const double r = (1.0 - s) * spec.radius[0] + s * spec.radius[1];
    for (int i = 0; i < g.nu; ++i) {
      const double angle = 2.0 * std::numbers::pi * double(i) / double(g.nu);
      Vec3d& p = g.positions[static_cast<std::size_t>(g.index(i, j))];
      for (int a = 0; a < 3; ++a)
        p[a] = spec.origin[a] + s * spec.length * axis[a] +
               r * (std::cos(angle) * seam[a] + std::sin(angle) * turn[a]);
    }
  }
  // Spacing round the narrower ring (a chord) and along the slant.
  const double narrow = std::min(spec.radius[0], spec.radius[1]);
  g.du = 2.0 * narrow * std::sin(std::numbers::pi / g.nu);
  g.dv = std::hypot(spec.length, spec.radius[1] - spec.radius[0]) / (g.nv - 1);
  g.edge = std::min(g.du, g.dv);
  g.vertex_mass = spec.mass / g.vertex_count();

  for (const auto& pin : spec.pins) g.pinned.push_back(g.index(pin[0], pin[1]));
  std::sort(g.pinned.begin(), g.pinned.end());
  g.pinned.erase(std::unique(g.pinned.begin(), g.pinned.end()), g.pinned.end());

  for (int j = 0; j + 1 < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {  // the last quad of each row closes the ring
      const int next = (i + 1) % g.nu;
      const int a = g.index(i, j), b = g.index(next, j);
      const int c = g.index(next, j + 1), d = g.index(i, j + 1);
      g.triangles.push_back({a, b, c});
      g.triangles.push_back({a, c, d});
    }
  }
  return g;
}

std::vector<Spring> seed_springs_tube(const GridCloth& g, const SpringStiffness& k) {
  std::vector<Spring> springs;
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      // Half the stencil (dj > 0, or dj == 0 and di > 0): each pair once.
      for (int dj = 0; dj <= 2 && j + dj < g.nv; ++dj) {
        for (int di = -2; di <= 2; ++di) {
          if (di * di + dj * dj >= 8 || (dj == 0 && di <= 0)) continue;
          const int a = g.index(i, j), b = g.index(((i + di) % g.nu + g.nu) % g.nu, j + dj);
          const double rest =
              point_distance(g.positions[std::size_t(a)], g.positions[std::size_t(b)]);
          springs.push_back(
              {std::min(a, b), std::max(a, b), rest, class_stiffness(k, di, dj) * g.edge / rest});
        }
      }
    }
  }
  std::sort(springs.begin(), springs.end(),
            [](const Spring& x, const Spring& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  return springs;
}

}  // namespace clothlab
