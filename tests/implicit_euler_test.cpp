// Backward Euler by Newton's method, its first iteration Baraff & Witkin's linearised step (1998),
// with its PCG solve: first-order convergence on the single spring, the exact backward-Euler step
// where the force is linear, the Jacobian checked through the size of the backward-Euler residual
// of one linearised step, Newton's quadratic convergence, unconditional stability of a falling
// sheet at frame-size steps, agreement with RK4 at small steps, thread determinism, pinning and
// the solver statistics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

#include "sim/forces/force_field.hpp"
#include "sim/integrators/integrator.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

using testing::kGravity, testing::kSpringAmplitude, testing::kSpringMass;
using testing::kSpringOmega, testing::kSpringRest, testing::kSpringStiffness;
using testing::spring_exact_y;

// Largest position error over [0, 0.5 s] against the closed form (as in single_spring_test.cpp).
double implicit_euler_error_over_half_second(long steps) {
  const auto s_owner = testing::solver<double>(
      testing::single_spring(kSpringMass, kSpringStiffness, kSpringRest,
                             IntegratorKind::implicit_euler, 0.5 / double(steps)));
  Solver& s = *s_owner;
  double worst = 0.0;
  for (long k = 0; k < steps; ++k) {
    EXPECT_TRUE(s.step(1).ok());
    worst = std::max(worst, std::abs(s.position(1)[1] - spring_exact_y(s.time())));
  }
  return worst;
}

TEST(ImplicitEuler, FirstOrderOnTheSingleSpring) {
  const double e1 = implicit_euler_error_over_half_second(2000);
  const double e2 = implicit_euler_error_over_half_second(4000);
  const double e4 = implicit_euler_error_over_half_second(8000);
  std::printf("errors %.3g %.3g %.3g: orders %.3f %.3f\n", e1, e2, e4, std::log2(e1 / e2),
              std::log2(e2 / e4));
  EXPECT_NEAR(std::log2(e1 / e2), 1.0, 0.2) << "errors " << e1 << " and " << e2;
  EXPECT_NEAR(std::log2(e2 / e4), 1.0, 0.2) << "errors " << e2 << " and " << e4;
}

// Along its axis the single spring's force is linear in (x, v), so the linearised step is the
// exact backward-Euler step: m (v1 - v0) = h f(x0 + h v1, v1), solved here in closed form with
// spring damping c and drag on: (m + h (c + drag) + h^2 k) v1 = m v0 + h (k (l0 - L) - m g).
TEST(ImplicitEuler, OneStepOfALinearSpringIsExactBackwardEuler) {
  const double c = 0.3, drag = 0.05, y0 = -0.7, v0 = -0.4;
  for (double h : {1e-3, 0.05, 1.0}) {
    Scene scene = testing::single_spring(kSpringMass, kSpringStiffness, kSpringRest,
                                         IntegratorKind::implicit_euler, h);
    scene.springs.damping = c;
    scene.forces.drag = drag;
    const auto s_owner = testing::solver<double>(scene);
    Solver& s = *s_owner;
    std::vector<Vec3d> x = testing::positions_of(s), v = testing::velocities_of(s);
    x[1][1] = y0;
    v[1][1] = v0;
    s.set_state(x, v);
    ASSERT_TRUE(s.step(1).ok());
    const double v1 =
        (kSpringMass * v0 + h * (kSpringStiffness * (-y0 - kSpringRest) - kSpringMass * kGravity)) /
        (kSpringMass + h * (c + drag) + h * h * kSpringStiffness);
    EXPECT_NEAR(s.velocity(1)[1], v1, 1e-12 * (1.0 + std::abs(v1))) << "h = " << h;
    EXPECT_NEAR(s.position(1)[1], y0 + h * v1, 1e-12) << "h = " << h;
    EXPECT_EQ(s.position(1)[0], 0.0);
    EXPECT_EQ(s.position(1)[2], 0.0);
    EXPECT_EQ(s.position(0)[1], 0.0);  // the pinned top
  }
}

// A stretched, spinning sheet (every spring longer than its rest length, so the projection is
// inactive and K is the exact Jacobian), no spring damping (whose Jacobian drops dd/dx) and no
// wind. The backward-Euler residual R = M (v1 - v0) - h f(x1, v1) of one linearised step is the
// Taylor remainder h O((h v)^2) = O(h^3) when K and D are right; a wrong sign or a missing term
// leaves h (K_err h v1) = O(h^2). Symplectic Euler's residual from the same state shows the
// O(h^2) size a Jacobian-free step has.
Vec3Array<double> to_array(const std::vector<Vec3d>& v) {
  Vec3Array<double> a;
  a.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) a.set(i, v[i][0], v[i][1], v[i][2]);
  return a;
}

// m: the solver's model (built again from its scene); start_vel: the velocities before the step.
double free_residual(const Solver& s, const Model<double>& m, const std::vector<Vec3d>& start_vel,
                     double h) {
  ForceWorkspace<double> ws;
  ws.resize(m);
  Vec3Array<double> f;
  f.resize(m.n);
  const std::vector<Vec3d> vel = testing::velocities_of(s);
  compute_forces(m, h, to_array(testing::positions_of(s)), to_array(vel), f, ws, 1);
  double worst = 0.0;
  for (std::size_t i = 0; i < m.n; ++i) {
    if (m.inv_mass[i] == 0.0) continue;
    for (int a = 0; a < 3; ++a) {
      const double r = m.mass[i] * (vel[i][a] - start_vel[i][a]) - h * f.axis(a)[i];
      worst = std::max(worst, std::abs(r));
    }
  }
  return worst;
}

double one_step_residual(IntegratorKind kind, double h, int newton_iterations = 1) {
  Scene scene = testing::sheet(6, 1.0, 0.5, 400.0, kind, h);
  scene.solver.newton_iterations = newton_iterations;
  scene.cloths[0].pins = {{0, 0}, {5, 0}};
  scene.forces.drag = 0.02;  // linear in v: its Jacobian is exact
  scene.solver.precision = Precision::f64;
  scene.solver.cg_tolerance = 1e-14;
  scene.solver.cg_max_iterations = 1000;
  const auto s_owner = testing::solver<double>(scene);
  Solver& s = *s_owner;
  std::vector<Vec3d> x = testing::positions_of(s), v = testing::velocities_of(s);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double k = double(i);
    for (int a = 0; a < 3; ++a) x[i][a] *= 1.05;  // stretch every spring by 5 %
    if (s.pinned(static_cast<int>(i))) continue;
    v[i] = {std::sin(1.3 * k), std::cos(0.7 * k), std::sin(2.1 * k + 0.5)};
  }
  s.set_state(x, v);
  EXPECT_TRUE(s.step(1).ok());
  if (kind == IntegratorKind::implicit_euler) {
    EXPECT_TRUE(s.last_solve().converged);
  }
  return free_residual(s, build_model<double>(scene), v, h);
}

TEST(ImplicitEuler, JacobianLeavesAThirdOrderBackwardEulerResidual) {
  const double r1 = one_step_residual(IntegratorKind::implicit_euler, 2e-4);
  const double r2 = one_step_residual(IntegratorKind::implicit_euler, 1e-4);
  const double r4 = one_step_residual(IntegratorKind::implicit_euler, 5e-5);
  EXPECT_NEAR(std::log2(r1 / r2), 3.0, 0.3) << "residuals " << r1 << ", " << r2;
  EXPECT_NEAR(std::log2(r2 / r4), 3.0, 0.3) << "residuals " << r2 << ", " << r4;
  const double explicit_r = one_step_residual(IntegratorKind::symplectic_euler, 5e-5);
  std::printf("residuals %.3g %.3g %.3g, symplectic Euler %.3g\n", r1, r2, r4, explicit_r);
  EXPECT_LT(r4, 0.05 * explicit_r) << "symplectic Euler's residual " << explicit_r;
}

// Newton's method converges quadratically where its Jacobian is exact (the stretched sheet without
// spring damping, as above; at 5e-3 s the vertices move less than the 5 % stretch, so no spring
// ends compressed): each iteration squares the relative residual until round-off.
TEST(ImplicitEuler, NewtonIterationsConvergeQuadratically) {
  constexpr double h = 5e-3;
  const double r1 = one_step_residual(IntegratorKind::implicit_euler, h, 1);
  const double r2 = one_step_residual(IntegratorKind::implicit_euler, h, 2);
  const double r3 = one_step_residual(IntegratorKind::implicit_euler, h, 3);
  std::printf("[ measured ] residual after 1, 2, 3 Newton iterations: %.3g %.3g %.3g N s\n", r1, r2,
              r3);
  EXPECT_LT(r2, 1e-2 * r1);
  EXPECT_LT(r3, 1e-2 * r2);
  EXPECT_LT(r3, 1e-10);
}

// Steps of a frame (1/60 s) on the 32x32 falling sheet, 77x symplectic Euler's stability limit
// (2.2e-4 s; it diverges there in 3 steps): no divergence, the total energy never rises above its
// start (backward Euler only dissipates), and PCG converges every step.
TEST(ImplicitEuler, FallingSheetIsStableAtFrameSteps) {
  const auto s_owner = testing::solver<double>(
      testing::falling_sheet(32, IntegratorKind::implicit_euler, 1.0 / 60.0));
  Solver& s = *s_owner;
  const double e0 = s.energy().total();
  for (int k = 0; k < 120; ++k) {
    ASSERT_TRUE(s.step(1).ok()) << "step " << k;
    ASSERT_LE(s.energy().total(), e0 + 1e-9) << "step " << k;
  }
  const SolveTotals& totals = s.solve_totals();
  EXPECT_EQ(totals.unconverged, 0);
  std::printf("32x32 sheet, dt = 1/60: %.1f PCG iterations per step (max %d)\n",
              double(totals.iterations) / double(totals.substeps), totals.max_iterations);
}

// The same material as the reference: the 16x16 falling sheet after 0.25 s at dt = 2e-4 against
// RK4 at 1e-5, RMS over all vertices. Measured 4.2e-4 m (the sheet has fallen about 0.3 m; the
// difference is implicit Euler's O(dt) damping of the fastest swinging modes).
TEST(ImplicitEuler, MatchesRk4OnTheFallingSheetAtSmallSteps) {
  const auto implicit_owner =
      testing::solver<double>(testing::falling_sheet(16, IntegratorKind::implicit_euler, 2e-4));
  Solver& implicit = *implicit_owner;
  const auto reference_owner =
      testing::solver<double>(testing::falling_sheet(16, IntegratorKind::rk4, 1e-5));
  Solver& reference = *reference_owner;
  ASSERT_TRUE(implicit.step(1250).ok());
  ASSERT_TRUE(reference.step(25000).ok());
  double sum = 0.0;
  for (int i = 0; i < int(implicit.vertex_count()); ++i) {
    const Vec3d a = implicit.position(i), b = reference.position(i);
    for (int c = 0; c < 3; ++c) sum += (a[c] - b[c]) * (a[c] - b[c]);
  }
  const double rms = std::sqrt(sum / double(implicit.vertex_count()));
  std::printf("RMS position difference to rk4: %.3g m\n", rms);
  EXPECT_LT(rms, 1e-3);
}

template <class T>
std::vector<Vec3d> positions_after_gusts(int threads) {
  Scene scene = testing::sheet(34, 1.0, 0.5, 400.0, IntegratorKind::implicit_euler, 1.0 / 120.0);
  scene.cloths[0].pins = {{0, 0}, {33, 0}};
  scene.springs.damping = 0.02;
  scene.forces.drag = 0.001;
  scene.forces.wind = {true, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
  scene.solver.threads = threads;
  const auto s_owner = testing::solver<T>(scene);
  Solver& s = *s_owner;
  EXPECT_TRUE(s.step(50).ok());
  std::vector<Vec3d> p;
  for (int i = 0; i < int(s.vertex_count()); ++i) p.push_back(s.position(i));
  return p;
}

TEST(ImplicitEuler, OneAndTwoThreadsGiveTheSameBits) {
  EXPECT_EQ(positions_after_gusts<double>(1), positions_after_gusts<double>(2));
  EXPECT_EQ(positions_after_gusts<float>(1), positions_after_gusts<float>(2));
}

TEST(ImplicitEuler, PinnedVerticesStayAndStatsReportTheSolve) {
  const auto s_owner =
      testing::solver<double>(testing::falling_sheet(16, IntegratorKind::implicit_euler, 1e-3));
  Solver& s = *s_owner;
  std::vector<int> pinned;
  std::vector<Vec3d> start;
  for (int p = 0; p < static_cast<int>(s.vertex_count()); ++p)
    if (s.pinned(p)) pinned.push_back(p), start.push_back(s.position(p));
  ASSERT_EQ(pinned.size(), 2u);
  ASSERT_TRUE(s.step(100).ok());
  for (std::size_t k = 0; k < pinned.size(); ++k) EXPECT_EQ(s.position(pinned[k]), start[k]);
  const SolveStats stats = s.last_solve();
  EXPECT_GT(stats.iterations, 0);
  EXPECT_TRUE(stats.converged);
  // The automatic tolerance: Newton iterates by default, so each solve stops at 1e-2 (inexact
  // Newton, implicit_euler.cpp); a tolerance set in the scene is kept.
  EXPECT_LE(stats.residual, 1e-2);
  std::printf("16x16 sheet, dt = 1e-3: %d PCG iterations in the last step\n", stats.iterations);
  Scene tight = testing::falling_sheet(16, IntegratorKind::implicit_euler, 1e-3);
  tight.solver.cg_tolerance = 1e-6;
  const auto t_owner = testing::solver<double>(tight);
  Solver& t = *t_owner;
  ASSERT_TRUE(t.step(100).ok());
  EXPECT_TRUE(t.last_solve().converged);
  EXPECT_LE(t.last_solve().residual, 1e-6);
  EXPECT_GT(t.last_solve().iterations, stats.iterations);
}

// A sheet hanging in the x-y plane: gravity pulls along its springs, so the first step's system
// couples the vertices and one PCG iteration cannot solve it. (The falling sheet's first step
// would: its right side, gravity across the flat sheet, meets only the mass there.)
TEST(ImplicitEuler, IterationCapIsReportedAsNotConverged) {
  Scene scene = testing::sheet(16, 1.0, 0.2, 1000.0, IntegratorKind::implicit_euler, 1.0 / 60.0);
  scene.cloths[0].pins = {{0, 0}, {15, 0}};
  scene.solver.precision = Precision::f64;
  scene.solver.cg_max_iterations = 1;
  scene.solver.newton_iterations = 1;  // one PCG solve per step
  const auto s_owner = testing::solver<double>(scene);
  Solver& s = *s_owner;
  ASSERT_TRUE(s.step(1).ok());
  EXPECT_EQ(s.last_solve().iterations, 1);
  EXPECT_FALSE(s.last_solve().converged);
  EXPECT_GT(s.last_solve().residual, 1e-6);
  EXPECT_EQ(s.solve_totals().unconverged, 1);
}

// Float: the falling sheet at frame steps, stable and close to the double run (measured 7e-5 m
// after 0.5 s: PCG stops at a relative residual of 1e-6 in either precision).
TEST(ImplicitEuler, FloatFollowsDoubleOnTheFallingSheet) {
  Scene scene = testing::falling_sheet(32, IntegratorKind::implicit_euler, 1.0 / 60.0);
  const auto d_owner = testing::solver<double>(scene);
  Solver& d = *d_owner;
  scene.solver.precision = Precision::f32;
  const auto f_owner = testing::solver<float>(scene);
  Solver& f = *f_owner;
  ASSERT_TRUE(d.step(30).ok());
  ASSERT_TRUE(f.step(30).ok());
  double worst = 0.0;
  for (int i = 0; i < int(d.vertex_count()); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(d.position(i)[c] - f.position(i)[c]));
  std::printf(
      "float 32x32 sheet, dt = 1/60: %.1f PCG iterations per step, %ld of 30 steps unconverged; "
      "largest difference to double after 0.5 s %.3g m\n",
      double(f.solve_totals().iterations) / double(f.solve_totals().substeps),
      f.solve_totals().unconverged, worst);
  EXPECT_LT(worst, 5e-4);
}

// The neighbour-index table (the path for meshes whose neighbours are not at a few fixed index
// offsets): the sheet with its vertices renumbered by a scattering permutation must move as the
// original, up to round-off (the sums run in another order).
Model<double> renumbered(const Model<double>& m, const std::vector<int>& to) {
  Model<double> r = m;  // a neighbour_list model: every per-vertex array is permuted below
  const std::size_t n = m.n;
  auto at = [&](std::size_t i) { return static_cast<std::size_t>(to[i]); };
  for (std::size_t i = 0; i < n; ++i) {
    r.mass[at(i)] = m.mass[i];
    r.inv_mass[at(i)] = m.inv_mass[i];
    for (int a = 0; a < 3; ++a) r.rest_positions.axis(a)[at(i)] = m.rest_positions.axis(a)[i];
    for (int s = 0; s < m.slots; ++s) {
      const std::size_t k = static_cast<std::size_t>(s) * n;
      r.neighbour[k + at(i)] = to[static_cast<std::size_t>(m.neighbour[k + i])];
      r.stiffness[k + at(i)] = m.stiffness[k + i];
      r.rest_length[k + at(i)] = m.rest_length[k + i];
      r.damping[k + at(i)] = m.damping[k + i];
    }
    for (int s = 0; s < m.incident_slots; ++s) {
      const std::size_t k = static_cast<std::size_t>(s) * n;
      r.incident_triangle[k + at(i)] = m.incident_triangle[k + i];
    }
  }
  for (int& p : r.pinned) p = to[static_cast<std::size_t>(p)];
  for (auto& t : r.triangles)
    for (int& v : t) v = to[static_cast<std::size_t>(v)];
  return r;
}

State<double> run_integrator(const Model<double>& model, const SolverSpec& spec, int steps) {
  ForceWorkspace<double> ws;
  ws.resize(model);
  State<double> st{model.rest_positions, {}};
  st.vel.resize(model.n);
  auto integrator = make_integrator<double>(model, spec);
  const System<double> sys{model, ws, 1};
  for (int k = 0; k < steps; ++k) {
    integrator->step(sys, st, k * spec.dt, spec.dt);
    EXPECT_TRUE(integrator->last_stats().converged) << "step " << k;
  }
  return st;
}

TEST(ImplicitEuler, RenumberedVerticesMoveTheSame) {
  Scene scene = testing::falling_sheet(24, IntegratorKind::implicit_euler, 1.0 / 60.0);
  scene.solver.cg_tolerance = 1e-12;
  scene.solver.cg_max_iterations = 2000;
  const Model<double> m = build_model<double>(scene, SpringKernel::neighbour_list);
  const State<double> a = run_integrator(m, scene.solver, 30);
  // A shuffle scatters every block's neighbours (the index table); i -> 367 i mod n keeps them
  // at a few offsets, more than the grid's (diagonal storage with wrapped offsets).
  std::vector<int> shuffled(m.n), strided(m.n);
  std::iota(shuffled.begin(), shuffled.end(), 0);
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
  for (std::size_t i = 0; i < m.n; ++i) strided[i] = int((i * 367) % m.n);  // 367 prime to 576
  for (const std::vector<int>* to : {&shuffled, &strided}) {
    const State<double> b = run_integrator(renumbered(m, *to), scene.solver, 30);
    double worst = 0.0;
    for (std::size_t i = 0; i < m.n; ++i) {
      const auto j = static_cast<std::size_t>((*to)[i]);
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(a.pos.axis(c)[i] - b.pos.axis(c)[j]));
    }
    std::printf("renumbered sheet: largest position difference after 0.5 s %.3g m\n", worst);
    EXPECT_LT(worst, 1e-8);
  }
}

}  // namespace
}  // namespace clothlab
