// Mode 6's texture-space diffusion (vis/passes/diffusion_pass.cpp) on real pixels: blurring a
// smoothly lit cloth changes nothing in its interior (the blurs preserve the irradiance and the
// atlas maps back where it came from), and across a sharp shadow edge on the cloth the light
// spreads farthest in red and least in blue, as the weights say.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "pixels.hpp"
#include "render_frame.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/render/render_quality.hpp"

namespace clothlab {
namespace {

constexpr int kDiffusionW = 320, kDiffusionH = 240;

// A white horizontal 1.5 m sheet at 0.5 m, free, without gravity (it stays as built).
Scene white_sheet() {
  Scene s = testing::sheet(24, 1.5, 0.2, 100.0, IntegratorKind::symplectic_euler, 1e-3);
  s.cloths[0].origin = {-0.75, 0.5, -0.75};
  s.cloths[0].u_axis = {1.0, 0.0, 0.0};
  s.cloths[0].v_axis = {0.0, 0.0, 1.0};
  s.forces.gravity = {0.0, 0.0, 0.0};
  return s;
}

class Diffusion : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    renderer_ = std::make_unique<vis::HeadlessRenderer>(kDiffusionW, kDiffusionH);
    solver_ = make_solver(white_sheet());
    renderer_->set_cloth(*solver_);
  }
  static void TearDownTestSuite() {
    solver_.reset();
    renderer_.reset();
  }
  // From above, the sheet filling the view; mode 6 without relief, white, no sky or ambient.
  static vis::ViewSettings view() {
    vis::ViewSettings v = vis::default_view(*solver_);
    v.mode = vis::DisplayMode::weave;
    v.camera.target = {0.0f, 0.5f, 0.0f};
    v.camera.pitch_deg = 89.0f;
    v.camera.yaw_deg = 0.0f;
    v.camera.distance = 1.6f;
    v.sky = false;
    v.ambient = 0.0f;
    v.look.color = Vec3d{1.0, 1.0, 1.0};
    v.look.bump = 0.0;
    return v;
  }
  static std::vector<std::uint8_t> shoot(const vis::ViewSettings& v,
                                         const std::vector<MeshSpec>& meshes) {
    RenderSpec spec;
    spec.pole.enabled = false;
    spec.meshes = meshes;
    renderer_->set_scene(spec, *solver_);
    return test::render_frame(*renderer_, *solver_, v);
  }
  static std::array<double, 3> at(const std::vector<std::uint8_t>& img, const vis::ViewSettings& v,
                                  glm::vec3 p) {
    const std::size_t k = testing::pixel_index(v.camera, kDiffusionW, kDiffusionH, p);
    return {testing::srgb_byte_to_linear(img[k]), testing::srgb_byte_to_linear(img[k + 1]),
            testing::srgb_byte_to_linear(img[k + 2])};
  }

  static std::unique_ptr<vis::HeadlessRenderer> renderer_;
  static std::unique_ptr<Solver> solver_;
};
std::unique_ptr<vis::HeadlessRenderer> Diffusion::renderer_;
std::unique_ptr<Solver> Diffusion::solver_;

// A spot light close above one corner: the irradiance varies smoothly across the sheet (over
// tens of centimetres, the blurs span millimetres), so with diffusion every interior point keeps
// its brightness within 2 %, in every channel. A flipped or shifted atlas would move the light.
TEST_F(Diffusion, SmoothLightIsUnchangedInTheInterior) {
  vis::ViewSettings v = view();
  v.light_type = LightType::spot;
  v.light_position = {-0.4f, 1.3f, -0.3f};
  v.light_target = glm::vec3(0.0f, 0.5f, 0.0f);
  v.light_intensity = 0.8f;
  v.shadows = ShadowFilter::none;
  v.look.subsurface = 0.0;
  const auto sharp = shoot(v, {});
  v.look.subsurface = 1.0;
  const auto diffused = shoot(v, {});
  for (float x : {-0.5f, -0.2f, 0.1f, 0.4f})
    for (float z : {-0.5f, -0.1f, 0.3f, 0.5f}) {
      const auto a = at(sharp, v, {x, 0.5f, z}), b = at(diffused, v, {x, 0.5f, z});
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(b[ch], a[ch], 0.02 * a[ch] + 1e-4)
            << "at (" << x << ", " << z << ") channel " << ch;
    }
}

// A plate high on the left (x < -0.7 m, 1.2 m up) and a directional light travelling 45 degrees
// towards +x: the plate's shadow edge lands at x = 0 on the sheet, sharp (PCF, no light size).
// The view looks down at the edge from 0.5 m, about 1 mm per pixel.
MeshSpec shadow_plate() {
  MeshSpec plate;
  plate.kind = MeshKind::box;
  plate.center = {-1.45, 1.2, 0.0};
  plate.half_extents = {0.75, 0.01, 1.0};
  return plate;
}

vis::ViewSettings edge_view(const vis::ViewSettings& base) {
  vis::ViewSettings v = base;
  v.light_type = LightType::directional;
  const float s = std::sqrt(0.5f);
  v.light_direction = {s, -s, 0.0f};
  v.light_intensity = 1.0f;
  v.light_size = 0.0f;
  v.shadows = ShadowFilter::pcf;
  v.shadow_map_size = 4096;  // the map also spans the plate's shadow on the floor: keep it sharp
  v.camera.distance = 0.5f;
  return v;
}

// Per channel, the width in metres over which the light on the sheet (along z = 0) rises from
// 10 % to 90 % across the plate's shadow edge.
std::array<double, 3> edge_widths(const std::function<std::array<double, 3>(glm::vec3)>& at) {
  std::array<double, 3> width{};
  const auto lit = at({0.14f, 0.5f, 0.0f}), dark = at({-0.14f, 0.5f, 0.0f});
  for (int ch = 0; ch < 3; ++ch) {
    double x10 = -0.12, x90 = -0.12;
    for (float x = -0.12f; x <= 0.12f; x += 0.0005f) {
      const double f = (at({x, 0.5f, 0.0f})[ch] - dark[ch]) / (lit[ch] - dark[ch]);
      if (f < 0.1) x10 = x;
      if (f < 0.9) x90 = x;
    }
    width[ch] = x90 - x10;
  }
  return width;
}

// Across the plate's shadow edge diffusion widens the rise of the light: red most, then green,
// then blue (the weights give red the widest blurs).
TEST_F(Diffusion, ShadowEdgeSpreadsRedWidest) {
  vis::ViewSettings v = edge_view(view());
  auto widths = [&](double subsurface) {
    v.look.subsurface = subsurface;
    const auto img = shoot(v, {shadow_plate()});
    return edge_widths([&](glm::vec3 p) { return at(img, v, p); });
  };
  const auto sharp = widths(0.0), soft = widths(1.0);
  EXPECT_GT(soft[0], sharp[0] + 0.002) << "red: " << sharp[0] << " -> " << soft[0] << " m";
  EXPECT_GT(soft[0], soft[1]) << "red " << soft[0] << ", green " << soft[1];
  EXPECT_GE(soft[1], soft[2]) << "green " << soft[1] << ", blue " << soft[2];
}

// The blurs are widths in the cloth, not in its UV layout (d'Eon & Luebke's stretch map): a
// 0.75 m sheet drawn as it was built and then stretched to twice its length across the edge
// spreads the red light over the same width in the world, within one atlas texel of the
// stretched sheet (1.5 m / 512 at full quality, / 256 at fast). With the blur fixed in atlas units
// the stretched sheet's glow would be twice as wide (about 1 cm more).
TEST_F(Diffusion, StretchedClothKeepsTheWorldWidthOfItsGlow) {
  for (RenderQuality quality : {RenderQuality::full, RenderQuality::fast}) {
    SCOPED_TRACE(to_string(quality));
    Scene scene = white_sheet();
    scene.cloths[0].size = {0.75, 0.75};
    scene.cloths[0].origin = {-0.375, 0.5, -0.375};
    std::unique_ptr<Solver> small = make_solver(scene);
    renderer_->set_cloth(*small);
    vis::ViewSettings v = edge_view(view());
    v.look.subsurface = 1.0;
    v.quality = quality;
    auto red_width = [&] {
      RenderSpec spec;
      spec.pole.enabled = false;
      // A speck off to the side (it shadows nothing in view) keeps the box around the casters,
      // and so the shadow map's texels, the same for both sheets: only the blur may change the
      // edge.
      MeshSpec speck;
      speck.kind = MeshKind::box;
      speck.center = {1.0, 0.5, 0.0};
      speck.half_extents = {0.01, 0.01, 0.01};
      spec.meshes = {shadow_plate(), speck};
      renderer_->set_scene(spec, *small);
      const auto img = test::render_frame(*renderer_, *small, v);
      return edge_widths([&](glm::vec3 p) { return at(img, v, p); })[0];
    };
    const double built = red_width();
    scene.cloths[0].size = {1.5, 0.75};  // the same grid twice as long along x
    scene.cloths[0].origin = {-0.75, 0.5, -0.375};
    small->load_state(*make_solver(scene));
    const double stretched = red_width();
    renderer_->set_cloth(*solver_);  // the other tests' sheet
    EXPECT_GT(built, 0.008) << "the glow must be wide enough to tell";
    // Within one texel of the stretched sheet's atlas (fast: an atlas of half the texels).
    EXPECT_NEAR(stretched, built, 1.5 / vis::diffusion_atlas_texels(quality))
        << built << " m as built, " << stretched << " m stretched";
  }
}

}  // namespace
}  // namespace clothlab
