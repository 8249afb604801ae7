// Ctrl + drag's geometry (vis/render/view_ray.hpp): the point found under a pixel on the plane
// through an anchor lies on that plane and projects back onto the same pixel.
#include <gtest/gtest.h>

#include "pixels.hpp"
#include "vis/render/view_ray.hpp"

namespace clothlab {
namespace {

TEST(ViewRayTest, PointUnderCursorOnTheCameraFacingPlane) {
  vis::OrbitCamera camera;
  camera.target = {0.2f, 1.0f, -0.3f};
  camera.yaw_deg = 35.0f;
  camera.pitch_deg = 20.0f;
  camera.distance = 4.0f;
  const int w = 640, h = 400;
  const glm::vec3 anchor{0.5f, 1.2f, 0.1f};
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye());
  // The anchor's own pixel gives the anchor back.
  const glm::vec2 a = testing::screen_position(camera, w, h, anchor);
  const glm::vec3 same = vis::point_on_view_plane(camera, w, h, a.x, a.y, anchor);
  EXPECT_NEAR(glm::length(same - anchor), 0.0f, 1e-4f);
  for (const glm::vec2 cursor : {glm::vec2(100.0f, 50.0f), glm::vec2(600.0f, 380.0f)}) {
    const glm::vec3 p = vis::point_on_view_plane(camera, w, h, cursor.x, cursor.y, anchor);
    EXPECT_NEAR(glm::dot(p - anchor, forward), 0.0f, 1e-4f);  // on the plane
    const glm::vec2 back = testing::screen_position(camera, w, h, p);
    EXPECT_NEAR(back.x, cursor.x, 0.01f);
    EXPECT_NEAR(back.y, cursor.y, 0.01f);
  }
}

// The window's lens shift (OrbitCamera::lens_shift) moves the whole image sideways by that much of
// the half-width, without turning the camera: the target lands at device x = shift, every point
// moves by the same shift * w / 2 pixels, and Ctrl + drag's ray still finds the point under the
// cursor.
TEST(ViewRayTest, LensShiftMovesTheImageAndKeepsPicking) {
  vis::OrbitCamera camera;
  camera.target = {0.2f, 1.0f, -0.3f};
  camera.yaw_deg = 35.0f;
  const int w = 640, h = 400;
  const glm::vec3 points[] = {camera.target, {0.5f, 1.2f, 0.1f}, {-1.0f, 0.0f, 0.4f}};
  glm::vec2 before[3];
  for (int k = 0; k < 3; ++k) before[k] = testing::screen_position(camera, w, h, points[k]);
  camera.lens_shift = 0.3f;
  for (int k = 0; k < 3; ++k) {
    const glm::vec2 after = testing::screen_position(camera, w, h, points[k]);
    EXPECT_NEAR(after.x - before[k].x, 0.3f * w / 2, 0.01f);
    EXPECT_NEAR(after.y, before[k].y, 0.01f);
  }
  EXPECT_NEAR(testing::screen_position(camera, w, h, camera.target).x, 0.65f * w, 0.01f);
  const glm::vec3 anchor = points[1];
  const glm::vec3 p = vis::point_on_view_plane(camera, w, h, 500.0f, 120.0f, anchor);
  const glm::vec2 back = testing::screen_position(camera, w, h, p);
  EXPECT_NEAR(back.x, 500.0f, 0.01f);
  EXPECT_NEAR(back.y, 120.0f, 0.01f);
}

}  // namespace
}  // namespace clothlab
