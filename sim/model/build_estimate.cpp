#include "sim/model/build_estimate.hpp"

#include <cmath>

#include "sim/model/memory_estimate.hpp"

namespace clothlab {
namespace {

// Microseconds per vertex to build a 1000 x 1000 sheet's solver: `clothlab check --force`
// (parsing, springs, model, the spectrum estimate and the integrator's own tables), release,
// 2-core host, one run each (docs/inputs.md, "Memory and build time"): 9.8-11.8 s for the explicit
// methods, xpbd and vbd, 19.7 s for implicit Euler. Triangle contact builds its trees at the first
// step.
double build_us_per_vertex(IntegratorKind integrator) {
  switch (integrator) {
    case IntegratorKind::implicit_euler:
    case IntegratorKind::bdf2:
      return 20.0;
    default:
      return 12.0;
  }
}

// local_global factors its global matrix (a sparse Cholesky) once: 4.5 s at 256 x 256, 11.2 s at
// 362 x 362 and 458 s at 1000 x 1000, about n^1.7 (nested dissection fill grows as n log n and
// its work as n^1.5 on a grid, George 1973; the cache adds the rest).
constexpr double kLocalGlobalMillion = 458.0;  // s at 1e6 vertices
constexpr double kLocalGlobalExponent = 1.7;

}  // namespace

double estimated_build_seconds(const Scene& scene) {
  const double vertices = scene_vertices(scene);
  if (scene.solver.integrator == IntegratorKind::local_global)
    return kLocalGlobalMillion * std::pow(vertices / 1e6, kLocalGlobalExponent);
  return 1e-6 * vertices * build_us_per_vertex(scene.solver.integrator);
}

}  // namespace clothlab
