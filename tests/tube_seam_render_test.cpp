// A tube's seam on screen (vis/render/renderer.cpp): the renderer gives each ring one extra
// render vertex, a copy of column 0 at u = 1, so the woven texture wraps round the ring instead
// of running back from u = 1 to 0 across the seam's quads (which squashed the whole texture into
// one vertical stripe). Looks at the seam face on and compares it with the cloth beside it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "pixels.hpp"
#include "render_frame.hpp"
#include "sim/solver.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/textures/cloth_tangents.hpp"
#include "vis/textures/image.hpp"

namespace clothlab {
namespace {

constexpr int kSeamW = 320, kSeamH = 240;
constexpr float kRadius = 0.3f, kTop = 1.0f, kLength = 0.6f;

// A vertical cylinder of cloth, free and weightless (it stays as built), its seam along +x.
Scene tube() {
  Scene s;
  ClothSpec c;
  c.shape = "tube";
  c.resolution = {24, 8};
  c.origin = {0.0, kTop, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, -1.0, 0.0};
  c.radius = {kRadius, kRadius};
  c.length = kLength;
  c.mass = 0.2;
  c.key = "cloth";
  s.cloths.push_back(c);
  s.springs.stiffness = 100.0;
  s.forces.gravity = {0.0, 0.0, 0.0};
  s.solver.integrator = IntegratorKind::symplectic_euler;
  s.solver.dt = 1e-3;
  s.solver.threads = 1;
  return s;
}

// Mid-height point of the tube's surface at angle a from column 0 (towards column 1: +z).
glm::vec3 surface(float a) {
  return {kRadius * std::cos(a), kTop - 0.5f * kLength, kRadius * std::sin(a)};
}

class TubeSeam : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    renderer_ = std::make_unique<vis::HeadlessRenderer>(kSeamW, kSeamH);
    solver_ = make_solver(tube());
    renderer_->set_cloth(*solver_);
    RenderSpec spec;
    spec.pole.enabled = false;
    renderer_->set_scene(spec, *solver_);
  }
  static void TearDownTestSuite() {
    solver_.reset();
    renderer_.reset();
  }
  // Level with the tube's middle, looking at the seam along -x, lit from the camera's side.
  static vis::ViewSettings view(vis::DisplayMode mode) {
    vis::ViewSettings v = vis::default_view(*solver_);
    v.mode = mode;
    v.camera.target = {0.0f, kTop - 0.5f * kLength, 0.0f};
    v.camera.pitch_deg = 0.0f;
    v.camera.yaw_deg = 90.0f;
    v.camera.distance = 1.1f;
    v.sky = false;
    v.shadows = ShadowFilter::none;
    v.light_position = glm::vec3(2.0f, kTop, 0.0f);
    v.light_target = glm::vec3(0.0f, kTop - 0.5f * kLength, 0.0f);
    return v;
  }
  static std::vector<std::uint8_t> shoot(const vis::ViewSettings& v, const char* name) {
    std::vector<std::uint8_t> img = test::render_frame(*renderer_, *solver_, v);
    if (const char* dir = std::getenv("CLOTHLAB_TEST_PNG_DIR")) {  // to look at by eye
      Image out;
      out.width = kSeamW;
      out.height = kSeamH;
      out.rgba = img;
      write_png(out, std::string(dir) + "/" + name + ".png");
    }
    return img;
  }
  static double luminance(const std::vector<std::uint8_t>& img, int x, int y) {
    const std::size_t k = 4 * (static_cast<std::size_t>(y) * kSeamW + static_cast<std::size_t>(x));
    return 0.2126 * testing::srgb_byte_to_linear(img[k]) +
           0.7152 * testing::srgb_byte_to_linear(img[k + 1]) +
           0.0722 * testing::srgb_byte_to_linear(img[k + 2]);
  }
  // Texture detail across a window of (2 half + 1) x 41 pixels centred where the tube's surface
  // at angle a lands: the mean absolute difference of horizontally neighbouring pixels.
  static double horizontal_detail(const std::vector<std::uint8_t>& img, const vis::ViewSettings& v,
                                  float a, int half) {
    const glm::vec2 c = testing::screen_position(v.camera, kSeamW, kSeamH, surface(a));
    const int cx = static_cast<int>(c.x), cy = static_cast<int>(c.y);
    double sum = 0.0;
    int count = 0;
    for (int y = cy - 20; y <= cy + 20; ++y)
      for (int x = cx - half; x < cx + half; ++x, ++count)
        sum += std::abs(luminance(img, x + 1, y) - luminance(img, x, y));
    return sum / count;
  }

  static std::unique_ptr<vis::HeadlessRenderer> renderer_;
  static std::unique_ptr<Solver> solver_;
};
std::unique_ptr<vis::HeadlessRenderer> TubeSeam::renderer_;
std::unique_ptr<Solver> TubeSeam::solver_;

// The seam copies are one per ring and map back to column 0.
TEST_F(TubeSeam, OneCopyOfColumnZeroPerRing) {
  const vis::Renderer& r = renderer_->renderer();
  ASSERT_EQ(r.vertex_count(), solver_->vertex_count());
  ASSERT_EQ(r.render_vertex_count(), r.vertex_count() + 8);
  for (int j = 0; j < 8; ++j)
    EXPECT_EQ(r.physics_vertex(r.vertex_count() + static_cast<std::size_t>(j)), j * 24);
  EXPECT_EQ(r.physics_vertex(5), 5);
}

// Mode 3 with the woven texture: the seam's quads show the weave at the same scale as their
// neighbours, not squashed into a stripe with (nearly) no detail across it.
TEST_F(TubeSeam, WovenTextureIsNotSquashedAtTheSeam) {
  const vis::ViewSettings v = view(vis::DisplayMode::lambert);
  const std::vector<std::uint8_t> img = shoot(v, "tube_seam_mode3");
  // One quad spans 2 pi / 24 of the ring: a window of about one quad on the seam's strip
  // (between columns 23 and 0, centred at -pi / 24) and on strips either side of it.
  const float quad = 2.0f * 3.14159265f / 24.0f;
  const int half = 5;
  const double seam = horizontal_detail(img, v, -0.5f * quad, half);
  const double left = horizontal_detail(img, v, -2.5f * quad, half);
  const double right = horizontal_detail(img, v, 1.5f * quad, half);
  EXPECT_GT(seam, 0.6 * std::min(left, right)) << seam << " beside " << left << ", " << right;
  EXPECT_LT(seam, 1.6 * std::max(left, right)) << seam << " beside " << left << ", " << right;
}

// Colour-by height: the seam copies carry their vertex's scalar, so a smooth field stays smooth
// across the seam (a copy left at 0 would draw a stripe of the colour map's low end).
TEST_F(TubeSeam, ColourByHeightIsSmoothAcrossTheSeam) {
  vis::ViewSettings v = view(vis::DisplayMode::lambert);
  v.color.field = vis::ScalarField::height;
  v.color.shaded = false;
  const std::vector<std::uint8_t> img = shoot(v, "tube_seam_height");
  const glm::vec2 c = testing::screen_position(v.camera, kSeamW, kSeamH, surface(0.0f));
  const int cy = static_cast<int>(c.y);
  // Along the row through the seam every pixel has the same height: the same colour.
  const double ref = luminance(img, static_cast<int>(c.x), cy);
  for (int x = static_cast<int>(c.x) - 40; x <= static_cast<int>(c.x) + 40; ++x)
    EXPECT_NEAR(luminance(img, x, cy), ref, 0.02) << "x " << x;
}

// Mode 6 with a flat normal map tilted along the tangent: the shading depends on the tangent
// frame, so a frame that jumps at the seam would show as a step in brightness there. Along the
// row through the seam, the largest step between neighbouring pixels near the seam is no larger
// than the largest step away from it.
TEST_F(TubeSeam, WeaveTangentFrameIsContinuousAcrossTheSeam) {
  Image tilted;
  tilted.width = tilted.height = 4;
  tilted.rgba.clear();
  for (int k = 0; k < 16; ++k)  // (0.5, 0, 0.866) encoded: tilted towards +T
    tilted.rgba.insert(tilted.rgba.end(), {191, 128, 238, 255});
  renderer_->renderer().set_normal_map(&tilted);
  vis::ViewSettings v = view(vis::DisplayMode::weave);
  v.look.color = Vec3d{1.0, 1.0, 1.0};
  v.look.subsurface = 0.0;
  const std::vector<std::uint8_t> img = shoot(v, "tube_seam_mode6");
  renderer_->renderer().set_normal_map(nullptr);
  const float quad = 2.0f * 3.14159265f / 24.0f;
  const glm::vec2 s0 = testing::screen_position(v.camera, kSeamW, kSeamH, surface(-2.0f * quad));
  const glm::vec2 s1 = testing::screen_position(v.camera, kSeamW, kSeamH, surface(1.0f * quad));
  const glm::vec2 far0 = testing::screen_position(v.camera, kSeamW, kSeamH, surface(-5.0f * quad));
  const glm::vec2 far1 = testing::screen_position(v.camera, kSeamW, kSeamH, surface(-3.0f * quad));
  const int y = static_cast<int>(s0.y);
  auto largest_step = [&](float xa, float xb) {
    double m = 0.0;
    for (int x = static_cast<int>(std::min(xa, xb)); x < static_cast<int>(std::max(xa, xb)); ++x)
      m = std::max(m, std::abs(luminance(img, x + 1, y) - luminance(img, x, y)));
    return m;
  };
  const double seam = largest_step(s0.x, s1.x), away = largest_step(far0.x, far1.x);
  EXPECT_LT(seam, 2.0 * away + 0.005) << seam << " away " << away;
}

// The tangents on their own: round a ring the frame turns by the same angle between every pair
// of neighbouring columns, column nu - 1 to column 0 included, with one handedness.
TEST(TubeTangents, CentralDifferencesAcrossTheSeam) {
  const int nu = 12, nv = 2;
  std::vector<float> p, n, t(4 * nu * nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const float a = 2.0f * 3.14159265f * float(i) / float(nu);
      p.insert(p.end(), {std::cos(a), -float(j), -std::sin(a)});
      n.insert(n.end(), {std::cos(a), 0.0f, -std::sin(a)});
    }
  compute_grid_tangents(nu, nv, p.data(), n.data(), t.data(), true);
  auto angle = [&](int a, int b) {
    const glm::vec3 ta(t[4 * a], t[4 * a + 1], t[4 * a + 2]),
        tb(t[4 * b], t[4 * b + 1], t[4 * b + 2]);
    return std::acos(std::clamp(glm::dot(ta, tb), -1.0f, 1.0f));
  };
  const float step = 2.0f * 3.14159265f / float(nu);
  for (int i = 0; i < nu; ++i) {
    EXPECT_NEAR(angle(i, (i + 1) % nu), step, 1e-4f) << "column " << i;
    EXPECT_EQ(t[4 * i + 3], t[3]);  // one handedness all round
  }
}

}  // namespace
}  // namespace clothlab
