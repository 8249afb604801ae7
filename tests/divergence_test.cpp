// A run that blows up stops with a report (step, time, vertex, quantity) and never hands out NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "load/scene_load.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

TEST(Divergence, UnstableStepIsReportedWithStepTimeVertexAndQuantity) {
  // Symplectic Euler is stable only for dt < 0.654 sqrt(m / k0) (docs/design.md): 2.3e-4 s here.
  Scene scene = testing::sheet(16, 1.0, 0.2, 1000.0, IntegratorKind::symplectic_euler, 1e-3);
  scene.cloths[0].pins = {{0, 0}, {15, 0}};
  const auto s = testing::solver<float>(scene);
  const AdvanceResult r = s->advance(10.0);
  ASSERT_TRUE(r.divergence);
  const Divergence& d = *r.divergence;
  EXPECT_GT(d.step, 1);
  EXPECT_LT(d.step, 10000);
  EXPECT_DOUBLE_EQ(d.time, d.step * 1e-3);
  EXPECT_EQ(r.steps, d.step);
  EXPECT_GE(d.vertex.i, 0);
  EXPECT_LT(d.vertex.i, 16);
  EXPECT_FALSE(d.quantity.empty());
  EXPECT_NE(d.message().find("step " + std::to_string(d.step)), std::string::npos);
  // Caught before anything became NaN: every value handed out is still finite.
  for (std::size_t i = 0; i < s->vertex_count(); ++i)
    for (double c : s->position(static_cast<int>(i))) ASSERT_TRUE(std::isfinite(c));
  // Further steps are refused with the same report.
  const AdvanceResult again = s->step(5);
  EXPECT_EQ(again.steps, 0);
  ASSERT_TRUE(again.divergence);
  EXPECT_EQ(again.divergence->step, d.step);
}

// Springs far too stiff for the step stretch the lattice beyond the scene's energy scale a step
// before the velocities show it: the per-step kinetic check lets that step through, the energy
// check (run where the energy is computed anyway: a trace's rows and summary) catches it and
// names a vertex. The state at rest passes it.
TEST(Divergence, ElasticEnergyBeyondTheScaleIsADivergence) {
  Scene scene = read_scene_file(std::string(CLOTHLAB_SOURCE_DIR "/scenes/default.toml"));
  scene.solver.integrator = IntegratorKind::explicit_euler;
  scene.solver.dt_auto = false;
  scene.solver.dt = 1e-3;
  scene.springs.stiffness = 1e9;
  const auto s = make_solver(scene);
  EXPECT_FALSE(s->energy_divergence(s->energy()));
  std::optional<Divergence> caught;
  for (int step = 1; step <= 10 && !caught; ++step) {
    if (!s->step(1).ok()) break;  // the kinetic check fired first
    caught = s->energy_divergence(s->energy());
  }
  ASSERT_TRUE(caught) << "the kinetic check caught the run first, or nothing did";
  EXPECT_EQ(caught->step, s->step_count());
  EXPECT_NE(caught->quantity.find("exceeds 1000 x the scene's energy scale"), std::string::npos)
      << caught->quantity;
  EXPECT_NE(caught->quantity.find("elastic"), std::string::npos);
  EXPECT_GE(s->vertex_index(caught->vertex), 0);
}

TEST(Divergence, StableStepRunsClean) {
  Scene scene = testing::sheet(16, 1.0, 0.2, 1000.0, IntegratorKind::symplectic_euler, 2e-4);
  scene.cloths[0].pins = {{0, 0}, {15, 0}};
  scene.springs.damping = 0.05;
  const auto s = testing::solver<float>(scene);
  EXPECT_TRUE(s->advance(1.0).ok());
}

TEST(Stepping, AdvanceTakesTheStepsThatFitAndCarriesTheRest) {
  const Scene scene = testing::sheet(4, 1.0, 0.2, 100.0, IntegratorKind::verlet, 1e-3);
  const auto a = testing::solver<double>(scene);
  const auto b = testing::solver<double>(scene);
  for (int frame = 0; frame < 30; ++frame) ASSERT_TRUE(a->advance(1.0 / 30.0).ok());
  EXPECT_EQ(b->advance(1.0).steps, 1000);
  EXPECT_EQ(a->step_count(), 1000);
  EXPECT_EQ(a->position(15), b->position(15));  // same steps, same state
  EXPECT_EQ(a->advance(0.0004).steps, 0);
  EXPECT_EQ(a->advance(0.0007).steps, 1);  // 0.0004 + 0.0007 s hold one step
}

}  // namespace
}  // namespace clothlab
