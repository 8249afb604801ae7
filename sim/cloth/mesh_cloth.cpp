#include "sim/cloth/mesh_cloth.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "sim/mesh/triangle_mesh.hpp"

namespace clothlab {
namespace {

Eigen::Vector3d rest_position(const GridCloth& g, int v) {
  const Vec3d& p = g.positions[static_cast<std::size_t>(v)];
  return {p[0], p[1], p[2]};
}

// Degrees about x, then y, then z (R = Rz Ry Rx), as everywhere in the scene format.
Eigen::Matrix3d rotation(const Vec3d& degrees) {
  const double k = M_PI / 180.0;
  return (Eigen::AngleAxisd(degrees[2] * k, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(degrees[1] * k, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(degrees[0] * k, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace

GridCloth build_mesh_cloth(const ClothSpec& spec) {
  const TriangleMesh& mesh = *spec.mesh;
  GridCloth g;
  g.mesh = true;
  g.nu = static_cast<int>(mesh.positions.size());
  g.nv = 1;
  const Eigen::Matrix3d r = rotation(spec.rotation);
  const Eigen::Vector3d origin(spec.origin[0], spec.origin[1], spec.origin[2]);
  for (const Eigen::Vector3d& p : mesh.positions) {
    // The parser applied the scale when it read the file; a Scene built in code may not have.
    const Eigen::Vector3d x = r * p + origin;
    g.positions.push_back({x.x(), x.y(), x.z()});
  }
  g.triangles = mesh.triangles;
  for (const auto& pin : spec.pins) g.pinned.push_back(pin[0]);
  std::sort(g.pinned.begin(), g.pinned.end());
  g.pinned.erase(std::unique(g.pinned.begin(), g.pinned.end()), g.pinned.end());

  // Lumped masses: a third of each incident triangle's area, scaled to the total mass.
  g.masses.assign(g.positions.size(), 0.0);
  double area = 0.0;
  for (const auto& t : g.triangles) {
    const double a = 0.5 * (rest_position(g, t[1]) - rest_position(g, t[0]))
                               .cross(rest_position(g, t[2]) - rest_position(g, t[0]))
                               .norm();
    for (int v : t) g.masses[static_cast<std::size_t>(v)] += a / 3.0;
    area += a;
  }
  for (double& m : g.masses) m *= spec.mass / area;
  g.vertex_mass = spec.mass / static_cast<double>(g.positions.size());

  std::vector<double> lengths;
  for (const auto& e : mesh_edges(g.triangles))
    lengths.push_back((rest_position(g, e[0]) - rest_position(g, e[1])).norm());
  std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2),
                   lengths.end());
  g.edge = lengths[lengths.size() / 2];
  return g;
}

std::vector<Spring> mesh_springs(const GridCloth& cloth, const SpringStiffness& k) {
  // Each edge, with the vertices opposite it in the triangles that share it.
  std::map<std::pair<int, int>, std::vector<int>> opposite;
  for (const auto& t : cloth.triangles)
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      opposite[{std::min(a, b), std::max(a, b)}].push_back(t[(c + 2) % 3]);
    }
  std::map<std::pair<int, int>, double> pairs;  // each pair's class stiffness; an edge wins
  for (const auto& [edge, across] : opposite) pairs[edge] = k.stretch;
  for (const auto& [edge, across] : opposite) {
    // Interior edge of a manifold surface: bend across it. A boundary edge has one triangle;
    // a non-manifold one (three or more) has no single fold to resist.
    if (across.size() == 2 && across[0] != across[1])
      pairs.emplace(std::pair{std::min(across[0], across[1]), std::max(across[0], across[1])},
                    k.bend);
  }
  std::vector<Spring> springs;
  springs.reserve(pairs.size());
  for (const auto& [p, c] : pairs) {
    Spring s;
    s.a = p.first;
    s.b = p.second;
    s.rest_length = (rest_position(cloth, s.a) - rest_position(cloth, s.b)).norm();
    if (s.rest_length == 0.0) continue;  // two folded-over triangles: no direction to resist in
    s.stiffness = c * cloth.edge / s.rest_length;
    springs.push_back(s);
  }
  return springs;
}

}  // namespace clothlab
