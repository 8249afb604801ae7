// Scenes built in code for the physics tests (no parser involved).
#pragma once

#include <cmath>
#include <memory>
#include <type_traits>
#include <vector>

#include "bench/suites/lab_scenes.hpp"
#include "sim/model/model.hpp"
#include "sim/scene/scene.hpp"
#include "sim/solver.hpp"

namespace clothlab::testing {

// Two vertices, the top one pinned, the spring hanging along gravity: the closed-form case.
// Each vertex has mass m (kg); the spring has stiffness k (N/m) and rest length L (m).
inline Scene single_spring(double m, double k, double L, IntegratorKind integrator, double dt) {
  Scene s;
  ClothSpec c;
  c.size = {1.0, L};
  c.resolution = {1, 2};
  c.origin = {0.0, 0.0, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, -1.0, 0.0};
  c.mass = 2.0 * m;
  c.pins = {{0, 0}};
  c.key = "cloth";
  s.cloths.push_back(c);
  s.springs.stiffness = k;  // k = stiffness * edge / rest = stiffness for one spring
  s.springs.damping = 0.0;
  s.forces.gravity = {0.0, -9.81, 0.0};
  s.solver.integrator = integrator;
  s.solver.dt = dt;
  s.solver.threads = 1;
  s.solver.precision = Precision::f64;
  return s;
}

// The single spring of the convergence tests: 0.1 kg on 100 N/m, rest length 0.5 m. Released at
// rest at its rest length, the free vertex follows y(t) = -L - A (1 - cos(w t)) with
// A = m g / k and w = sqrt(k / m).
inline constexpr double kSpringMass = 0.1, kSpringStiffness = 100.0, kSpringRest = 0.5;
inline constexpr double kGravity = 9.81;
inline const double kSpringOmega = std::sqrt(kSpringStiffness / kSpringMass);
inline const double kSpringAmplitude = kSpringMass * kGravity / kSpringStiffness;

inline double spring_exact_y(double t) {
  return -kSpringRest - kSpringAmplitude * (1.0 - std::cos(kSpringOmega * t));
}

// A square sheet in the x-y plane hanging down from y = 0.
inline Scene sheet(int res, double size, double mass, double stiffness, IntegratorKind integrator,
                   double dt) {
  Scene s;
  ClothSpec c;
  c.size = {size, size};
  c.resolution = {res, res};
  c.origin = {-0.5 * size, 0.0, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, -1.0, 0.0};
  c.mass = mass;
  c.key = "cloth";
  s.cloths.push_back(c);
  s.springs.stiffness = stiffness;
  s.solver.integrator = integrator;
  s.solver.dt = dt;
  s.solver.threads = 1;
  return s;
}

// An nu x nv sheet (1 m, 0.3 kg, 500 N/m) pinned at the two ends of its first row, with
// along-spring damping (0: the undamped kernel) and drag 0.01 N*s/m.
inline Scene grid_sheet(int nu, int nv, double damping = 0.07) {
  Scene s = sheet(nu, 1.0, 0.3, 500.0, IntegratorKind::verlet, 1e-4);
  s.cloths[0].resolution = {nu, nv};
  s.cloths[0].pins = {{0, 0}, {nu - 1, 0}};
  s.springs.damping = damping;
  s.forces.drag = 0.01;
  return s;
}

// Every stencil edge case of the band kernel (sim/forces/grid_spring_forces.hpp) and of the update
// inside its sweep (sim/forces/fused_band_pass.hpp): rows too short for the same-row springs (1
// and 2 wide), a grid shorter than the stencil's reach (3x3), one band, several bands whose halos
// cross into the next, a last band holding the remainder, undamped springs, and two cloths (the
// second with anisotropic spacing, so the stencil reaches further along u, and its own undamped
// springs). Row widths against the kernel's vector runs of 16 (for_each_lane): 12 shorter than a
// run, 17 one whole run for di = +-1 and less than one for +-2, 33 two runs and a masked last run.
// Tubes take the neighbour list (sim/model/model.cpp), so the band kernel never sees a seam.
inline std::vector<Scene> band_edge_cases() {
  const auto damped = [](Scene s) {
    s.springs.damping = 0.07;
    s.forces.drag = 0.01;
    return s;
  };
  Scene two = damped(sheet(9, 1.0, 0.4, 600.0, IntegratorKind::symplectic_euler, 1e-4));
  ClothSpec second = two.cloths[0];
  second.resolution = {5, 12};
  second.size = {0.4, 1.3};
  second.origin = {2.0, 0.0, 0.0};
  second.springs = SpringSpec{};
  second.springs->stiffness = 300.0;
  two.cloths.push_back(second);
  two.multi_cloth = true;
  return {damped(sheet(12, 1.0, 0.5, 800.0, IntegratorKind::rk4, 1e-4)),
          grid_sheet(1, 7),
          grid_sheet(2, 30),
          grid_sheet(3, 3),
          grid_sheet(17, 9),
          grid_sheet(33, 10),
          grid_sheet(600, 20),  // 8-row bands: 2 bands, the second of 12 rows
          grid_sheet(20, 100),  // 26-row bands: 3 bands, the last of 48 rows
          grid_sheet(17, 130),  // 31-row bands: 4 bands, the last of 37 rows
          grid_sheet(20, 100, 0.0),
          two};
}

// docs/design.md "Accuracy benchmark scenes": a res x res sheet, 1 m, 0.2 kg, stiffness 1000 N/m,
// along-spring damping 0.05 N*s/m, lying horizontal and pinned at the two corners of one edge,
// released at rest (the accuracy suite's scene, bench/suites/lab_scenes.hpp), in double.
inline Scene falling_sheet(int res, IntegratorKind integrator, double dt) {
  bench::SheetParams p;
  p.resolution = res;
  return bench::hanging_sheet(p, integrator, dt);
}

// The scene's solver in float (T = float) or double (T = double), whatever precision the scene
// names, with the row-sweep or neighbour-list spring kernel.
template <class T>
std::unique_ptr<Solver> solver(Scene scene, SpringKernel kernel = SpringKernel::row_sweep) {
  scene.solver.precision = std::is_same_v<T, double> ? Precision::f64 : Precision::f32;
  return make_solver(scene, kernel);
}

// Every vertex's position or velocity (m, m/s), for set_state after a change.
inline std::vector<Vec3d> positions_of(const SolverState& s) {
  std::vector<Vec3d> x(s.vertex_count());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = s.position(static_cast<int>(i));
  return x;
}
inline std::vector<Vec3d> velocities_of(const SolverState& s) {
  std::vector<Vec3d> v(s.vertex_count());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = s.velocity(static_cast<int>(i));
  return v;
}

}  // namespace clothlab::testing
