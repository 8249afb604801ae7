// Mode 5's coloured shadows (docs/rendering.md section 5), measured as ratios on the floor (the
// render with shadows over the same render without them, at the same pixel, so the floor's
// texture cancels): under a red translucent sheet the light that reaches the floor is the
// sheet's transmittance T = (1 - c) + c tau filter(albedo) per channel, two sheets give T^2, an
// opaque sheet gives a neutral dark shadow, and an object between the light and the sheet stays
// untinted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "pixels.hpp"
#include "render_frame.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/headless_renderer.hpp"

namespace clothlab {
namespace {

constexpr int kColouredShadowW = 320, kColouredShadowH = 240;
constexpr double kCoverage = 0.6, kTau = 0.5;
const Vec3d kRed{0.8, 0.1, 0.1};  // sRGB albedo of the sheets

// Horizontal 1 m sheets at the given heights, free (no gravity, so they stay as built).
Scene sheets(const std::vector<double>& heights) {
  Scene s;
  for (std::size_t k = 0; k < heights.size(); ++k) {
    Scene one = testing::sheet(8, 1.0, 0.1, 100.0, IntegratorKind::symplectic_euler, 1e-3);
    ClothSpec c = one.cloths[0];
    c.origin = {-0.5, heights[k], -0.5};
    c.u_axis = {1.0, 0.0, 0.0};
    c.v_axis = {0.0, 0.0, 1.0};
    c.key = "cloth[" + std::to_string(k) + "]";
    s.cloths.push_back(c);
    s.solver = one.solver;
  }
  s.multi_cloth = heights.size() > 1;
  s.forces.gravity = {0.0, 0.0, 0.0};
  return s;
}

struct Fixture {
  std::unique_ptr<Solver> solver;
  vis::ViewSettings view;
};

class ColouredShadow : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    renderer_ = std::make_unique<vis::HeadlessRenderer>(kColouredShadowW, kColouredShadowH);
  }
  static void TearDownTestSuite() { renderer_.reset(); }

  // Light straight down (white, directional); the camera low under the sheets looking at the
  // floor below them; no sky, no ambient, coloured translucent sheets.
  static Fixture setup(const std::vector<double>& heights, const std::vector<MeshSpec>& meshes) {
    Fixture f{make_solver(sheets(heights)), {}};
    renderer_->set_cloth(*f.solver);
    RenderSpec spec;
    spec.pole.enabled = false;
    spec.meshes = meshes;
    renderer_->set_scene(spec, *f.solver);
    vis::ViewSettings& v = f.view;
    v = vis::default_view(*f.solver);
    v.floor_height = 0.0f;
    v.camera.target = {0.0f, 0.0f, 0.0f};
    v.camera.pitch_deg = 8.0f;
    v.camera.yaw_deg = 0.0f;
    v.camera.distance = 1.5f;
    v.light_type = LightType::directional;
    v.light_direction = {0.0f, -1.0f, 0.0f};
    v.light_intensity = 1.0f;
    v.light_color = {1.0f, 1.0f, 1.0f};
    v.ambient = 0.0f;
    v.sky = false;
    v.mode = vis::DisplayMode::translucent;
    v.shadows = ShadowFilter::pcf;
    v.look.color = kRed;
    v.look.opacity = kCoverage;
    v.look.transmission = kTau;
    return f;
  }

  // Light reaching world point p, per channel: shadowed render over unshadowed, same pixel.
  static std::array<double, 3> ratio(Fixture& f, glm::vec3 p) {
    const std::vector<std::uint8_t> lit_img = [&] {
      vis::ViewSettings v = f.view;
      v.shadows = ShadowFilter::none;
      return test::render_frame(*renderer_, *f.solver, v);
    }();
    const std::vector<std::uint8_t> shadow_img = test::render_frame(*renderer_, *f.solver, f.view);
    const std::size_t k =
        testing::pixel_index(f.view.camera, kColouredShadowW, kColouredShadowH, p);
    std::array<double, 3> out{};
    for (int ch = 0; ch < 3; ++ch)
      out[ch] = testing::srgb_byte_to_linear(shadow_img[k + ch]) /
                std::max(testing::srgb_byte_to_linear(lit_img[k + ch]), 1e-6);
    return out;
  }

  static std::unique_ptr<vis::HeadlessRenderer> renderer_;
};
std::unique_ptr<vis::HeadlessRenderer> ColouredShadow::renderer_;

// T = (1 - c) + c tau filter(albedo), the filter the albedo over its largest channel
// (shaders/yarn.glsl).
std::array<double, 3> transmittance() {
  std::array<double, 3> albedo{}, t{};
  for (int ch = 0; ch < 3; ++ch) albedo[ch] = testing::srgb_to_linear(kRed[ch]);
  const double top = std::max({albedo[0], albedo[1], albedo[2]});
  for (int ch = 0; ch < 3; ++ch) t[ch] = (1.0 - kCoverage) + kCoverage * kTau * albedo[ch] / top;
  return t;
}

double hue_deg(const std::array<double, 3>& c) {
  return glm::degrees(std::atan2(std::sqrt(3.0) * (c[1] - c[2]), 2.0 * c[0] - c[1] - c[2]));
}

TEST_F(ColouredShadow, RatioUnderOneSheetIsItsTransmittance) {
  Fixture f = setup({0.5}, {});
  const auto r = ratio(f, {0.0f, 0.0f, 0.0f});
  const auto t = transmittance();
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(r[ch], t[ch], 0.02 * t[ch] + 0.004) << "channel " << ch;
  EXPECT_NEAR(hue_deg(r), hue_deg(t), 3.0);
  EXPECT_GT(r[0], 1.3 * r[1]);  // red light gets through best
}

TEST_F(ColouredShadow, TwoSheetsGiveTheSquare) {
  Fixture f = setup({0.5, 0.8}, {});
  const auto r = ratio(f, {0.0f, 0.0f, 0.0f});
  const auto t = transmittance();
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(r[ch], t[ch] * t[ch], 0.02 * t[ch] * t[ch] + 0.004) << "channel " << ch;
}

TEST_F(ColouredShadow, OpaqueSheetCastsANeutralDarkShadow) {
  Fixture f = setup({0.5}, {});
  f.view.look.opacity = 1.0;
  f.view.look.transmission = 0.0;
  const auto r = ratio(f, {0.0f, 0.0f, 0.0f});
  for (int ch = 0; ch < 3; ++ch) EXPECT_LT(r[ch], 0.01) << "channel " << ch;
}

// A box standing above the sheet (between it and the light) is lit untinted on top, and the
// floor beside the sheet is lit fully.
TEST_F(ColouredShadow, ObjectsInFrontOfTheSheetStayUntinted) {
  MeshSpec box;
  box.kind = MeshKind::box;
  box.center = {0.0, 1.0, 0.0};
  box.half_extents = {0.1, 0.1, 0.1};
  Fixture f = setup({0.5}, {box});
  f.view.camera.pitch_deg = 40.0f;  // from above, to see the box's top
  f.view.camera.target = {0.0f, 1.1f, 0.0f};
  const auto top = ratio(f, {0.0f, 1.1f, 0.0f});
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(top[ch], 1.0, 0.02) << "channel " << ch;
}

}  // namespace
}  // namespace clothlab
