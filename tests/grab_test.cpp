// Ctrl + drag (Solver::grab): the grabbed vertex follows the hand for every integrator, a pinned
// vertex cannot be grabbed, and letting go lets the cloth swing back.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

std::string grab_name_of(const ::testing::TestParamInfo<IntegratorKind>& info) {
  return to_string(info.param);
}

class Grab : public ::testing::TestWithParam<IntegratorKind> {};

// A 1 m sheet hanging from two corners; its bottom middle vertex pulled 0.3 m towards the viewer
// and 0.1 m up is there within 2 cm after 0.5 s (the pull is a stiff spring: it stays short by
// what the taut sheet pulls back), and after the release the sheet swings back below half the
// pull within 1 s (a 1 m sheet swings with a period of about 2 s).
TEST_P(Grab, GrabbedVertexFollowsTheHand) {
  Scene scene = testing::sheet(16, 1.0, 0.2, 400.0, GetParam(), 1e-3);
  scene.cloths[0].pins = {{0, 0}, {15, 0}};
  scene.springs.damping = 0.05;
  if (is_explicit(GetParam())) scene.solver.dt_auto = true;
  std::unique_ptr<Solver> s = make_solver(scene);
  ASSERT_TRUE(s->advance(0.5).ok());  // settle
  const int v = 8 + 15 * 16;
  const Vec3d at = s->position(v);
  EXPECT_FALSE(s->grab(0, at)) << "a pin stays a pin";
  const Vec3d target{at[0], at[1] + 0.1, at[2] + 0.3};
  ASSERT_TRUE(s->grab(v, target));
  EXPECT_EQ(s->grabbed(), v);
  ASSERT_TRUE(s->advance(0.5).ok());
  const Vec3d p = s->position(v);
  EXPECT_LT(std::hypot(p[0] - target[0], p[1] - target[1], p[2] - target[2]), 0.02);
  s->release_grab();
  EXPECT_FALSE(s->grabbed());
  double lowest = INFINITY;
  for (int k = 0; k < 50; ++k) {
    ASSERT_TRUE(s->advance(0.02).ok());
    lowest = std::min(lowest, s->position(v)[2]);
  }
  EXPECT_LT(lowest, at[2] + 0.15);
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, Grab, ::testing::ValuesIn(kAllIntegrators), grab_name_of);

}  // namespace
}  // namespace clothlab
