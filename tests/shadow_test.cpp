// Lighting and shadows on real pixels (headless EGL; llvmpipe on CI), measured in image regions
// rather than whole images so they survive a change of Mesa or CPU (docs/rendering.md section 0):
// linear lighting (the cosine law), no shadow acne on a lit floor, no peter-panning at a post's
// foot, PCSS penumbrae that widen with the distance to the blocker while PCF's stay put, the
// depth view (key 7) separating floor, cloth and an object, and a sky that does not move with
// the camera.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "pixels.hpp"
#include "render_frame.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/headless_renderer.hpp"

namespace clothlab {
namespace {

constexpr int kShadowW = 320, kShadowH = 240;

struct ShadowShot {
  std::vector<std::uint8_t> rgba;
  double lum(int x, int y) const {  // linear, mean of the channels
    const std::size_t k =
        4 * (static_cast<std::size_t>(y) * kShadowW + static_cast<std::size_t>(x));
    return (testing::srgb_byte_to_linear(rgba[k]) + testing::srgb_byte_to_linear(rgba[k + 1]) +
            testing::srgb_byte_to_linear(rgba[k + 2])) /
           3.0;
  }
  int byte(int x, int y, int c) const {
    return rgba[4 * (static_cast<std::size_t>(y) * kShadowW + static_cast<std::size_t>(x)) + c];
  }
};

// A small cloth (the renderer needs one) hanging far off to the side at x = 3, out of the way.
Scene shadow_side_cloth() {
  Scene s = testing::sheet(4, 0.3, 0.05, 100.0, IntegratorKind::symplectic_euler, 1e-3);
  s.cloths[0].origin = {3.0, 1.0, 0.0};
  s.cloths[0].pins = {{0, 0}, {3, 0}};
  return s;
}

MeshSpec box(Vec3d center, Vec3d half, Vec3d color = {1.0, 1.0, 1.0}) {
  MeshSpec m;
  m.kind = MeshKind::box;
  m.center = center;
  m.half_extents = half;
  m.color = color;
  return m;
}

class ShadowTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    renderer_ = std::make_unique<vis::HeadlessRenderer>(kShadowW, kShadowH);
    solver_ = make_solver(shadow_side_cloth());
    renderer_->set_cloth(*solver_);
  }
  static void TearDownTestSuite() {
    solver_.reset();
    renderer_.reset();
  }

  // A view of the floor around the origin from above, a directional light `from_vertical_deg`
  // off the vertical (travelling towards +x), no sky, no ambient.
  static vis::ViewSettings view(float from_vertical_deg, ShadowFilter filter) {
    vis::ViewSettings v = vis::default_view(*solver_);
    v.floor_height = 0.0f;
    v.camera.target = {0.0f, 0.0f, 0.0f};
    v.camera.pitch_deg = 80.0f;
    v.camera.yaw_deg = 0.0f;
    v.camera.distance = 3.0f;
    v.light_type = LightType::directional;
    const float a = glm::radians(from_vertical_deg);
    v.light_direction = {std::sin(a), -std::cos(a), 0.0f};
    v.light_intensity = 1.0f;
    v.light_color = {1.0f, 1.0f, 1.0f};
    v.light_size = 0.05f;
    v.ambient = 0.0f;
    v.sky = false;
    v.shadows = filter;
    return v;
  }
  static ShadowShot shoot(const std::vector<MeshSpec>& meshes, const vis::ViewSettings& v) {
    RenderSpec spec;
    spec.pole.enabled = false;
    spec.meshes = meshes;
    renderer_->set_scene(spec, *solver_);
    return {test::render_frame(*renderer_, *solver_, v)};
  }
  static glm::vec2 pixel(const vis::ViewSettings& v, glm::vec3 p) {
    return testing::screen_position(v.camera, kShadowW, kShadowH, p);
  }

  static std::unique_ptr<vis::HeadlessRenderer> renderer_;
  static std::unique_ptr<Solver> solver_;
};
std::unique_ptr<vis::HeadlessRenderer> ShadowTest::renderer_;
std::unique_ptr<Solver> ShadowTest::solver_;

// Lighting is linear: the top of a white box lit at 60 degrees from its normal is half as bright
// (decoded from sRGB) as lit head-on, within 1 %.
TEST_F(ShadowTest, CosineLawInLinearLight) {
  const std::vector<MeshSpec> top = {box({0.0, 0.2, 0.0}, {0.4, 0.2, 0.4})};
  const vis::ViewSettings head_on = view(0.0f, ShadowFilter::none);
  const glm::vec2 p = pixel(head_on, {0.0f, 0.4f, 0.0f});
  const double lit0 = shoot(top, head_on).lum(int(p.x), int(p.y));
  const double lit60 = shoot(top, view(60.0f, ShadowFilter::none)).lum(int(p.x), int(p.y));
  EXPECT_GT(lit0, 0.2);
  EXPECT_NEAR(lit60 / lit0, 0.5, 0.01);
}

// No acne: a floor with nothing above it looks the same with shadows as without, at a light
// 0, 45 and 75 degrees off the vertical (every pixel of the floor region within 1/255).
TEST_F(ShadowTest, LitFloorHasNoAcne) {
  for (RenderQuality quality : {RenderQuality::full, RenderQuality::fast})
    for (float angle : {0.0f, 45.0f, 75.0f}) {
      for (ShadowFilter f : {ShadowFilter::pcf, ShadowFilter::pcss}) {
        // A box far off (the light's region must hold a caster) that shadows nothing in view.
        const std::vector<MeshSpec> away = {box({-4.0, 0.2, 3.0}, {0.2, 0.2, 0.2})};
        vis::ViewSettings lit = view(angle, ShadowFilter::none), shaded = view(angle, f);
        lit.quality = shaded.quality = quality;
        const ShadowShot plain = shoot(away, lit);
        const ShadowShot shadowed = shoot(away, shaded);
        long differ = 0, total = 0;
        for (int y = kShadowH / 4; y < 3 * kShadowH / 4; ++y)
          for (int x = kShadowW / 4; x < 3 * kShadowW / 4; ++x, ++total)
            for (int c = 0; c < 3; ++c)
              if (std::abs(plain.byte(x, y, c) - shadowed.byte(x, y, c)) > 1) {
                ++differ;
                break;
              }
        EXPECT_LE(double(differ) / double(total), 0.001)
            << differ << " of " << total << " pixels differ at " << angle << " degrees, "
            << to_string(f) << ", quality " << to_string(quality);
      }
    }
}

// How much light reaches the floor point p: the shadowed render over the same render without
// shadows at p's pixel (the floor's texture cancels).
double visibility(const ShadowShot& shadowed, const ShadowShot& plain, const vis::ViewSettings& v,
                  glm::vec3 p) {
  const glm::vec2 s = testing::screen_position(v.camera, kShadowW, kShadowH, p);
  const int x = int(s.x), y = int(s.y);
  return shadowed.lum(x, y) / std::max(plain.lum(x, y), 1e-6);
}

// No peter-panning: the shadow of a post standing on the floor starts at its foot. With the
// light 45 degrees off the vertical towards +x, floor points 2 cm and 10 cm beyond the post's
// +x face get under 20 % of the light, points beside it and behind it (-x) all of it (> 90 %).
TEST_F(ShadowTest, PostShadowTouchesItsFoot) {
  const std::vector<MeshSpec> post = {box({0.0, 0.5, 0.0}, {0.05, 0.5, 0.05})};
  for (RenderQuality quality : {RenderQuality::full, RenderQuality::fast}) {
    SCOPED_TRACE(to_string(quality));
    vis::ViewSettings v = view(45.0f, ShadowFilter::pcf);
    v.quality = quality;
    const ShadowShot s = shoot(post, v);
    v.shadows = ShadowFilter::none;
    const ShadowShot plain = shoot(post, v);
    EXPECT_LT(visibility(s, plain, v, {0.07f, 0.0f, 0.0f}), 0.2);
    EXPECT_LT(visibility(s, plain, v, {0.15f, 0.0f, 0.0f}), 0.2);
    EXPECT_GT(visibility(s, plain, v, {0.0f, 0.0f, 0.4f}), 0.9);
    EXPECT_GT(visibility(s, plain, v, {-0.1f, 0.0f, 0.0f}), 0.9);
  }
}

// The shadow falls away from the light, whichever way the light comes from: with the light 45
// degrees off the vertical from each of four sides, directional and spot, floor points 10 cm
// beyond the post (away from the light) are in its shadow and points 10 cm before it (towards
// the light) are lit. A map mirrored or turned against the lookups would swap them.
TEST_F(ShadowTest, ShadowFallsAwayFromTheLight) {
  const std::vector<MeshSpec> post = {box({0.0, 0.5, 0.0}, {0.05, 0.5, 0.05})};
  for (LightType type : {LightType::directional, LightType::spot}) {
    for (int side = 0; side < 4; ++side) {
      const float azimuth = glm::radians(90.0f * float(side));
      const glm::vec3 away(std::cos(azimuth), 0.0f, std::sin(azimuth));  // along the floor
      vis::ViewSettings v = view(45.0f, ShadowFilter::pcf);
      v.camera.pitch_deg = 89.0f;
      v.light_type = type;
      v.light_direction = glm::normalize(away + glm::vec3(0.0f, -1.0f, 0.0f));
      v.light_position = -3.0f * away + glm::vec3(0.0f, 3.0f, 0.0f);
      v.light_target = glm::vec3(0.0f);
      const ShadowShot s = shoot(post, v);
      v.shadows = ShadowFilter::none;
      const ShadowShot plain = shoot(post, v);
      SCOPED_TRACE(std::string(type == LightType::spot ? "spot" : "directional") +
                   " light, shadow towards (" + std::to_string(away.x) + ", " +
                   std::to_string(away.z) + ")");
      EXPECT_LT(visibility(s, plain, v, 0.15f * away), 0.2);
      EXPECT_GT(visibility(s, plain, v, -0.15f * away), 0.9);
    }
  }
}

// A low light casts long shadows, and the map's depth range reaches their ends: a 1 m post lit
// 60 degrees off the vertical has a shadow 1.73 m long, shadowed at 1.6 m from the post and lit
// beyond its tip, for a directional and for a spot light.
TEST_F(ShadowTest, LongShadowIsNotCutOff) {
  const std::vector<MeshSpec> post = {box({0.0, 0.5, 0.0}, {0.05, 0.5, 0.05})};
  for (LightType type : {LightType::directional, LightType::spot}) {
    SCOPED_TRACE(type == LightType::spot ? "spot" : "directional");
    vis::ViewSettings v = view(60.0f, ShadowFilter::pcf);
    const float a = glm::radians(60.0f);  // travelling towards -x, away from the side cloth
    v.light_direction = {-std::sin(a), -std::cos(a), 0.0f};
    v.light_type = type;
    // The spot 60 degrees off the vertical above the post's top, far enough to be nearly
    // parallel: its shadow tip lands a little beyond 1.73 m.
    v.light_position = glm::vec3(0.0f, 1.0f, 0.0f) - 6.0f * v.light_direction;
    v.light_target = glm::vec3(0.0f, 0.5f, 0.0f);
    v.camera.target = {-1.0f, 0.0f, 0.0f};
    v.camera.pitch_deg = 89.0f;
    v.camera.distance = 4.0f;
    const ShadowShot s = shoot(post, v);
    v.shadows = ShadowFilter::none;
    const ShadowShot plain = shoot(post, v);
    EXPECT_LT(visibility(s, plain, v, {-0.5f, 0.0f, 0.0f}), 0.2);
    EXPECT_LT(visibility(s, plain, v, {-1.6f, 0.0f, 0.0f}), 0.2);
    EXPECT_GT(visibility(s, plain, v, {-2.1f, 0.0f, 0.0f}), 0.9);
  }
}

// Width (m on the floor) over which the shadow of a plate's edge at x = 0 goes from 20 % to 80 %
// of the light, measured along +x between -0.4 and 0.4 m.
double penumbra_width(const ShadowShot& s, const ShadowShot& plain, const vis::ViewSettings& v) {
  double x20 = -0.4, x80 = -0.4;
  for (float x = -0.4f; x <= 0.4f; x += 0.002f) {  // inside the image on both sides
    const double f = visibility(s, plain, v, {x, 0.0f, 0.0f});
    if (f < 0.2) x20 = x;
    if (f < 0.8) x80 = x;
  }
  return x80 - x20;
}

// PCSS: a plate 0.8 m above the floor casts a wider penumbra than the same plate 0.2 m above it
// (similar triangles: the width grows with the distance to the blocker, here by more than 2x);
// with PCF the width is the kernel's, the same at both heights (within 1 cm).
TEST_F(ShadowTest, PcssPenumbraWidensWithDistance) {
  // A plate covering x < 0, lit straight from above by a light 0.1 rad wide.
  auto plate = [](double h) {
    return std::vector<MeshSpec>{box({-1.0, h, 0.0}, {1.0, 0.01, 1.0})};
  };
  auto width = [&](double h, ShadowFilter f) {
    vis::ViewSettings v = view(0.0f, f);
    // Low, from +z, close: the line of sight passes under the plate to the floor in its
    // shadow, and x runs across the image (about 4 mm per pixel at the edge).
    v.camera.pitch_deg = 8.0f;
    v.camera.yaw_deg = 0.0f;
    v.camera.distance = 1.2f;
    v.light_size = 0.1f;  // rad: penumbrae of 2 and 8 cm
    const ShadowShot s = shoot(plate(h), v);
    v.shadows = ShadowFilter::none;
    return penumbra_width(s, shoot(plate(h), v), v);
  };
  const double low = width(0.2, ShadowFilter::pcss), high = width(0.8, ShadowFilter::pcss);
  EXPECT_GT(high, 2.0 * low) << "PCSS penumbra " << low << " m at 0.2 m, " << high << " m at 0.8 m";
  EXPECT_GT(low, 0.0);
  const double pcf_low = width(0.2, ShadowFilter::pcf), pcf_high = width(0.8, ShadowFilter::pcf);
  EXPECT_NEAR(pcf_low, pcf_high, 0.01);
  EXPECT_LT(pcf_high, high);
}

// Key 7: the floor, the cloth and a box have separable depths in the light's depth map: the
// depth view's pixels where each lands differ clearly in colour.
TEST_F(ShadowTest, DepthViewSeparatesFloorClothAndObject) {
  const std::vector<MeshSpec> tall = {box({2.0, 0.6, 0.0}, {0.2, 0.6, 0.2})};
  vis::ViewSettings v = view(20.0f, ShadowFilter::pcf);
  v.mode = vis::DisplayMode::light_depth;
  const ShadowShot s = shoot(tall, v);
  const vis::LightRig& light = renderer_->light();
  auto colour_at = [&](glm::vec3 p) {
    const glm::vec4 c = light.view_proj * glm::vec4(p, 1.0f);
    const glm::vec2 uv = glm::vec2(c.x, c.y) / c.w * 0.5f + 0.5f;
    const float side = 0.95f * std::min(kShadowW, kShadowH);
    const float px = 0.5f * (kShadowW - side) + uv.x * side,
                py = kShadowH - (0.5f * (kShadowH - side) + uv.y * side);
    return std::array<int, 3>{s.byte(int(px), int(py), 0), s.byte(int(px), int(py), 1),
                              s.byte(int(px), int(py), 2)};
  };
  const Vec3d cloth = solver_->position(solver_->vertex_index({0, 1, 1}));
  const auto floor = colour_at({2.6f, 0.0f, 0.5f});
  const auto top = colour_at({2.0f, 1.2f, 0.0f});
  const auto sheet = colour_at({float(cloth[0]), float(cloth[1]), float(cloth[2])});
  auto distance = [](const std::array<int, 3>& a, const std::array<int, 3>& b) {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
  };
  EXPECT_GT(distance(floor, top), 40);
  EXPECT_GT(distance(floor, sheet), 40);
  EXPECT_GT(distance(top, sheet), 20);
}

// The sky is at infinity: moving the camera without turning it leaves the sky's pixels as they
// were (within 1/255), and it is brighter towards the sun than away from it.
TEST_F(ShadowTest, SkyStaysPutWhenTheCameraMoves) {
  vis::ViewSettings v = view(40.0f, ShadowFilter::none);
  v.sky = true;
  v.camera.pitch_deg = -20.0f;  // looking up: the top half is sky
  v.camera.yaw_deg = 90.0f;     // the eye on +x looking towards -x, where the light comes from
  v.camera.target = {0.0f, 2.0f, 0.0f};
  const ShadowShot a = shoot({}, v);
  v.camera.target += glm::vec3(0.0f, 0.5f, 0.3f);
  const ShadowShot b = shoot({}, v);
  int worst = 0;
  for (int y = 0; y < kShadowH / 3; ++y)
    for (int x = 0; x < kShadowW; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(a.byte(x, y, c) - b.byte(x, y, c)));
  EXPECT_LE(worst, 1);
  // Towards the light (the sun) against the opposite direction.
  v.camera.yaw_deg = -90.0f;
  const ShadowShot away = shoot({}, v);
  EXPECT_GT(a.lum(kShadowW / 2, kShadowH / 6), 1.5 * away.lum(kShadowW / 2, kShadowH / 6));
}

}  // namespace
}  // namespace clothlab
