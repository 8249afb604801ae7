#include "sim/model/memory_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/mesh/triangle_mesh.hpp"

namespace clothlab {
namespace {

// Peak resident bytes per vertex of `clothlab check` on a 1000 x 1000 sheet (float / double):
// the model, state, force workspace, spectrum estimate and the integrator's own arrays.
struct PerVertex {
  double f32, f64;
};

PerVertex per_vertex(IntegratorKind integrator) {
  switch (integrator) {
    case IntegratorKind::implicit_euler:
    case IntegratorKind::bdf2:
      return {1430, 2450};  // plus the Newton system's matrix-free PCG vectors and Hessian blocks
    case IntegratorKind::local_global:
      return {5680, 6500};  // plus the sparse Cholesky factor of the global matrix
    default:
      return {1200, 1360};
  }
}

// The most triangles at one vertex (a bound on its edges, and so on its springs' width / 2).
double widest(const TriangleMesh& mesh) {
  std::vector<int> around(mesh.positions.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int k : t) ++around[std::size_t(k)];
  return around.empty() ? 0.0 : double(*std::max_element(around.begin(), around.end()) + 1);
}

}  // namespace

double scene_vertices(const Scene& scene) {
  double vertices = 0.0;
  for (const ClothSpec& c : scene.cloths) vertices += double(c.resolution[0]) * c.resolution[1];
  return vertices;
}

std::uint64_t estimated_solver_bytes(const Scene& scene) {
  const double vertices = scene_vertices(scene);
  const PerVertex b = per_vertex(scene.solver.integrator);
  double bytes = vertices * (scene.solver.precision == Precision::f64 ? b.f64 : b.f32);
  // A sparse Cholesky factor of a grid's Laplacian fills in as n log n (nested dissection,
  // George 1973): measured 4.1 KB per vertex at 500^2 and 5.7 KB at 1000^2.
  if (scene.solver.integrator == IntegratorKind::local_global && vertices > 1e6)
    bytes *= 1.0 + 0.4 * std::log2(vertices / 1e6);
  // A mesh cloth's neighbour table is padded to its widest vertex (sim/model/model.hpp): per
  // slot an index and a stiffness, rest length and damping, for up to two springs per edge.
  const double value = scene.solver.precision == Precision::f64 ? 8.0 : 4.0;
  for (const ClothSpec& c : scene.cloths)
    if (c.mesh) bytes += double(c.mesh->positions.size()) * 2.0 * widest(*c.mesh) * (4 + 3 * value);
  // A mesh collider's distance grid (sim/mesh/sdf_grid.hpp): up to (resolution + 9)^3 cells of a
  // distance and a nearest-triangle index, and the same again while it is built.
  for (const ColliderSpec& c : scene.colliders)
    if (c.kind == ColliderKind::mesh) bytes += 2.0 * std::pow(c.sdf_resolution + 9.0, 3) * 12.0;
  return static_cast<std::uint64_t>(std::min(bytes, 1.8e19));
}

}  // namespace clothlab
