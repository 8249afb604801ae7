// Momentum balance: internal spring and damping forces cancel pairwise (Newton's third law), so
// without gravity, drag, wind and pins the total momentum is conserved to round-off; a push adds
// exactly the impulse asked for.
#include <gtest/gtest.h>

#include <random>

#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

std::array<double, 3> momentum(const SolverState& s) {
  std::array<double, 3> p{0, 0, 0};
  for (int i = 0; i < static_cast<int>(s.vertex_count()); ++i)
    for (int a = 0; a < 3; ++a) p[a] += s.mass(i) * s.velocity(i)[a];
  return p;
}

Scene free_sheet(IntegratorKind kind) {
  // dt = 1e-4 s: omega_max dt = 0.1, so even explicit Euler (energy x (1 + 0.01) per step on the
  // highest mode) stays far below the divergence limit over the run.
  Scene scene = testing::sheet(8, 1.0, 0.3, 500.0, kind, 1e-4);
  scene.forces.gravity = {0.0, 0.0, 0.0};
  scene.springs.damping = 0.05;
  scene.solver.precision = Precision::f64;
  scene.solver.cg_tolerance = 1e-14;  // implicit_euler: solve to round-off
  scene.solver.cg_max_iterations = 2000;
  return scene;
}

// Force-based and constraint methods conserve momentum to round-off: every internal force or
// position correction acts in equal and opposite pairs. XPBD's velocities are position
// differences divided by the step (1e-4 s), which scales the positions' round-off by 1e4.
// local_global's ten iterations leave the global solve unconverged, and what is left of its
// residual breaks the balance slightly.
// vbd's block descent moves momentum by what its iterations leave unconverged (small at this
// step: its local systems are nearly diagonal).
double relative_tolerance(IntegratorKind kind) {
  if (kind == IntegratorKind::xpbd || kind == IntegratorKind::vbd) return 1e-10;
  return kind == IntegratorKind::local_global ? 1e-9 : 1e-12;
}

class MomentumConservation : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(MomentumConservation, RandomVelocitiesKeepTotalMomentum) {
  const auto s = make_solver(free_sheet(GetParam()));
  std::mt19937 rng(42);
  std::normal_distribution<double> normal(0.0, 0.5);
  double speed_sum = 0.0;
  std::vector<Vec3d> x = testing::positions_of(*s), v(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      v[i][a] = normal(rng);
      x[i][a] += 0.01 * normal(rng);  // start stretched and sheared
    }
    speed_sum += s->mass(static_cast<int>(i)) * std::abs(v[i][0]);
  }
  s->set_state(x, v);
  const auto p0 = momentum(*s);
  ASSERT_TRUE(s->step(500).ok());
  const auto p1 = momentum(*s);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(p1[a], p0[a], relative_tolerance(GetParam()) * speed_sum) << "axis " << a;
  // The test is not trivially true: the velocities did change.
  EXPECT_GT(std::abs(s->velocity(0)[0] - 0.0), 0.0);
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, MomentumConservation, ::testing::ValuesIn(kAllIntegrators),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

TEST(Push, AddsExactlyTheImpulseToFreeVertices) {
  Scene scene = free_sheet(IntegratorKind::symplectic_euler);
  scene.cloths[0].pins = {{0, 0}, {7, 0}};
  const auto owner = make_solver(scene);
  Solver& s = *owner;
  const auto p0 = momentum(s);
  s.apply_impulse({0.0, 0.0, 0.0}, 0.3, {0.02, -0.01, 0.05});
  const auto p1 = momentum(s);
  EXPECT_NEAR(p1[0] - p0[0], 0.02, 1e-15);
  EXPECT_NEAR(p1[1] - p0[1], -0.01, 1e-15);
  EXPECT_NEAR(p1[2] - p0[2], 0.05, 1e-15);
  EXPECT_EQ(s.velocity(0)[2], 0.0);  // pinned vertices do not move
  // Far from every vertex: the nearest free vertex takes it all.
  s.apply_impulse({5.0, 0.0, 0.0}, 0.1, {0.0, 0.0, 0.01});
  EXPECT_NEAR(momentum(s)[2] - p1[2], 0.01, 1e-15);
}

}  // namespace
}  // namespace clothlab
