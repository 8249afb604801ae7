// A damped sheet pinned along its top row settles to a static equilibrium: the net force on every
// free vertex vanishes and the pins carry exactly the weight of the free vertices.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

TEST(Equilibrium, SheetPinnedAlongTopRowSettles) {
  const int res = 8;
  Scene scene = testing::sheet(res, 1.0, 0.5, 800.0, IntegratorKind::symplectic_euler, 1e-3);
  for (int i = 0; i < res; ++i) scene.cloths[0].pins.push_back({i, 0});
  scene.springs.damping = 0.2;
  scene.forces.drag = 0.05;
  scene.solver.precision = Precision::f64;
  const auto s = make_solver(scene);
  ASSERT_TRUE(s->advance(15.0).ok());
  s->update_force_field();

  const double g = scene.forces.gravity[1];
  const double vertex_weight = s->mass(0) * 9.81;
  const double tolerance = 1e-6 * vertex_weight;  // N
  double free_mass = 0.0, reaction_y = 0.0, largest = 0.0;
  for (int i = 0; i < static_cast<int>(s->vertex_count()); ++i) {
    const Vec3d f = s->force(i);
    if (s->pinned(i)) {
      reaction_y += f[1] - s->mass(i) * g;  // spring force on the pin
      continue;
    }
    free_mass += s->mass(i);
    largest = std::max(largest, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
  }
  EXPECT_LT(largest, tolerance) << "largest net force on a free vertex, N";
  // The springs pull the pins down by the weight of everything they hold.
  EXPECT_NEAR(reaction_y, free_mass * g, 1e-6 * free_mass * 9.81);
  // And the sheet really hangs: the bottom row sagged below its rest position.
  EXPECT_LT(s->position(res * (res - 1))[1], -1.0);
}

}  // namespace
}  // namespace clothlab
