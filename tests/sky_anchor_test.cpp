// The sky's sun stays put while the cloth moves (vis/render/renderer.hpp, sky_anchor_;
// docs/rendering.md "The sky's bake"): a spot light's sun lies from the casters' centre as the
// scene was set, so a sheet swinging down from horizontal bakes the sky once, where a sun taken
// from the moving cloth's centre would turn by more than the re-bake tolerance.
#include <gtest/gtest.h>

#include <cmath>

#include "render_frame.hpp"
#include "test_scenes.hpp"
#include "vis/sky/preetham_sky.hpp"

namespace clothlab {
namespace {

TEST(SkyAnchor, ASwingingSheetBakesTheSkyOnce) {
  vis::HeadlessRenderer renderer(160, 120);
  auto solver = testing::solver<float>(testing::falling_sheet(32, IntegratorKind::xpbd, 1.0 / 60));
  renderer.set_cloth(*solver);
  vis::ViewSettings view = vis::default_view(*solver);
  ASSERT_TRUE(view.sky);
  ASSERT_EQ(view.light_type, LightType::spot);
  test::render_frame(renderer, *solver, view);
  const glm::vec3 light = renderer.renderer().light().position;
  auto centre = [&] {
    const auto p = testing::positions_of(*solver);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const Vec3d& x : p) {
      const glm::vec3 v{float(x[0]), float(x[1]), float(x[2])};
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    return 0.5f * (lo + hi);
  };
  const glm::vec3 first = centre();
  double widest = 0.0;  // the largest turn of a sun taken from the cloth's centre, degrees
  for (int frame = 0; frame < 30; ++frame) {  // half a second: the sheet swings down
    ASSERT_TRUE(solver->step(1).ok());
    test::render_frame(renderer, *solver, view);
    const double c = glm::dot(glm::normalize(light - first), glm::normalize(light - centre()));
    widest = std::max(widest, glm::degrees(std::acos(std::min(1.0, c))));
  }
  EXPECT_GT(widest, 10.0 * vis::kSkySunToleranceDeg);
  EXPECT_EQ(renderer.renderer().sky_bakes(), 1);
}

}  // namespace
}  // namespace clothlab
