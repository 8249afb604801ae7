// Mode 6's tangent frame on real pixels (docs/rendering.md section 3): the weave's normal map is
// read in a frame built per vertex from positions and UVs (T along dP/du, B along dP/dv, N the
// surface normal), so a map that turns with the UV layout must give the same picture whatever
// the layout. The map here is one constant tilted normal, chosen per layout so that it means
// the same world-space normal; a tangent or bitangent of the wrong sign, or swapped, would tilt
// the shading the wrong way. (A grid's winding follows its UVs, so its frame's handedness never
// flips; mesh cloth with mirrored UVs will test that.)
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "pixels.hpp"
#include "render_frame.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/textures/image.hpp"
#include "vis/textures/weave_maps.hpp"

namespace clothlab {
namespace {

constexpr int kTangentW = 240, kTangentH = 240;

struct Layout {
  const char* name;
  Vec3d origin, u_axis, v_axis;
};

// One horizontal 1.5 m sheet at 0.5 m, its UVs laid three ways: u along x and v along z; the
// same turned a quarter (u along z, v along -x); mirrored (u along z, v along x), which turns
// the grid's triangles and normal over, so the camera sees its back and the relief inside out.
const Layout kLayouts[] = {
    {"u along x, v along z", {-0.75, 0.5, -0.75}, {1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}},
    {"turned: u along z, v along -x", {0.75, 0.5, -0.75}, {0.0, 0.0, 1.0}, {-1.0, 0.0, 0.0}},
    {"mirrored: u along z, v along x", {-0.75, 0.5, -0.75}, {0.0, 0.0, 1.0}, {1.0, 0.0, 0.0}},
};

std::unique_ptr<Solver> sheet_in(const Layout& layout) {
  Scene s = testing::sheet(16, 1.5, 0.2, 100.0, IntegratorKind::symplectic_euler, 1e-3);
  s.cloths[0].origin = layout.origin;
  s.cloths[0].u_axis = layout.u_axis;
  s.cloths[0].v_axis = layout.v_axis;
  s.forces.gravity = {0.0, 0.0, 0.0};
  return make_solver(s);
}

// The constant map whose normal, in this layout's frame, is the world-space normal `seen` on
// the upper side. The relief belongs to the cloth's front (its normal N); seen from the other
// side it is turned inside out, so when N points down the map holds -seen.
Image tilted_map(const Layout& layout, Solver& solver, glm::vec3 seen) {
  std::vector<float> normals(3 * solver.vertex_count());
  solver.copy_normals(normals.data());
  const glm::vec3 n(normals[0], normals[1], normals[2]);
  const float side = n.y > 0.0f ? 1.0f : -1.0f;
  const glm::vec3 t(layout.u_axis[0], layout.u_axis[1], layout.u_axis[2]);
  const glm::vec3 b(layout.v_axis[0], layout.v_axis[1], layout.v_axis[2]);
  const glm::vec3 m = side * glm::vec3(glm::dot(seen, t), glm::dot(seen, b), glm::dot(seen, n));
  Image map(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      encode_normal(m, map.at(x, y));
      map.at(x, y)[3] = 255;
    }
  return map;
}

class TangentFrame : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    renderer_ = std::make_unique<vis::HeadlessRenderer>(kTangentW, kTangentH);
  }
  static void TearDownTestSuite() { renderer_.reset(); }

  // From above; mode 6 with a plain white albedo, no relief of its own, no diffusion, sky, ambient
  // or shadow, under a directional light coming in slanted, so the brightness follows the normal's
  // tilt.
  static vis::ViewSettings view(Solver& solver) {
    vis::ViewSettings v = vis::default_view(solver);
    v.mode = vis::DisplayMode::weave;
    v.camera.target = {0.0f, 0.5f, 0.0f};
    v.camera.pitch_deg = 89.0f;
    v.camera.yaw_deg = 0.0f;
    v.camera.distance = 2.2f;
    v.sky = false;
    v.ambient = 0.0f;
    v.shadows = ShadowFilter::none;
    v.light_type = LightType::directional;
    v.light_direction = kLightTravel;
    v.light_intensity = 1.0f;
    v.look.color = Vec3d{1.0, 1.0, 1.0};
    v.look.subsurface = 0.0;
    v.look.bump = 0.0;  // without a map given, the flat weave
    return v;
  }
  // Linear green channel (the albedo is white) at points spread over the sheet's interior.
  static std::vector<double> samples(Solver& solver, const Image* map) {
    renderer_->set_cloth(solver);
    RenderSpec spec;
    spec.pole.enabled = false;
    renderer_->set_scene(spec, solver);
    renderer_->renderer().set_normal_map(map);
    const vis::ViewSettings v = view(solver);
    const std::vector<std::uint8_t> img = test::render_frame(*renderer_, solver, v);
    renderer_->renderer().set_normal_map(nullptr);
    std::vector<double> out;
    for (float x = -0.55f; x <= 0.56f; x += 0.22f)
      for (float z = -0.55f; z <= 0.56f; z += 0.22f)
        out.push_back(testing::srgb_byte_to_linear(
            img[testing::pixel_index(v.camera, kTangentW, kTangentH, {x, 0.5f, z}) + 1]));
    return out;
  }

  static inline const glm::vec3 kLightTravel = glm::normalize(glm::vec3(0.6f, -1.0f, 0.3f));
  // Tilted about 30 degrees away from the light in x and towards it in z.
  static inline const glm::vec3 kSeen = glm::normalize(glm::vec3(0.45f, 1.0f, 0.3f));
  static std::unique_ptr<vis::HeadlessRenderer> renderer_;
};
std::unique_ptr<vis::HeadlessRenderer> TangentFrame::renderer_;

// Lambert: with the map the brightness is the flat one times (seen . l) / (up . l), at every
// sample, in every layout, within 2 %; and the turned and mirrored layouts agree with the first.
TEST_F(TangentFrame, TiltedMapLightsAsItsWorldNormalInEveryLayout) {
  const glm::vec3 l = -kLightTravel;
  const double expected_ratio = glm::dot(kSeen, l) / l.y;
  ASSERT_LT(expected_ratio, 0.8) << "the tilt must change the light clearly";
  std::vector<double> reference;
  for (const Layout& layout : kLayouts) {
    SCOPED_TRACE(layout.name);
    std::unique_ptr<Solver> solver = sheet_in(layout);
    const std::vector<double> flat = samples(*solver, nullptr);
    const Image map = tilted_map(layout, *solver, kSeen);
    const std::vector<double> tilted = samples(*solver, &map);
    for (std::size_t i = 0; i < flat.size(); ++i) {
      ASSERT_GT(flat[i], 0.1) << "sample " << i << " is not on the lit sheet";
      EXPECT_NEAR(tilted[i] / flat[i], expected_ratio, 0.02) << "sample " << i;
    }
    if (reference.empty()) reference = tilted;
    for (std::size_t i = 0; i < tilted.size(); ++i)
      EXPECT_NEAR(tilted[i], reference[i], 0.02 * reference[i]) << "sample " << i;
  }
}

// The check can fail: the first layout's map on the turned layout tilts the normal another way
// and the picture changes by far more than the tolerance above.
TEST_F(TangentFrame, AMapThatDoesNotTurnWithTheLayoutChangesThePicture) {
  std::unique_ptr<Solver> first = sheet_in(kLayouts[0]);
  const Image map = tilted_map(kLayouts[0], *first, kSeen);
  const std::vector<double> right = samples(*first, &map);
  std::unique_ptr<Solver> turned = sheet_in(kLayouts[1]);
  const std::vector<double> wrong = samples(*turned, &map);
  double worst = 0.0;
  for (std::size_t i = 0; i < right.size(); ++i)
    worst = std::max(worst, std::abs(wrong[i] / right[i] - 1.0));
  EXPECT_GT(worst, 0.15);
}

}  // namespace
}  // namespace clothlab
