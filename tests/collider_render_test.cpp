// Colliders on real pixels (headless EGL): each is drawn where the solver has it, with its shape
// (a sphere, a rotated box, a capsule), lit from above; a ground plane collider becomes the floor
// at its height; a moving collider is drawn at its pose at the solver's time; colliders cast
// shadows. Pixels are compared with the same view rendered without the colliders, so the tests
// do not depend on the floor texture or the light's exact numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "pixels.hpp"
#include "render_frame.hpp"
#include "sim/mesh/triangle_mesh.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/textures/image.hpp"

namespace clothlab {
namespace {

constexpr int kW = 200, kH = 150;

struct Shot {
  std::vector<std::uint8_t> rgba;
  int byte(glm::vec2 p, int c) const {
    const auto x = static_cast<std::size_t>(p.x), y = static_cast<std::size_t>(p.y);
    return rgba[4 * (y * kW + x) + static_cast<std::size_t>(c)];
  }
  double lum(glm::vec2 p) const {  // linear, mean of the channels
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) sum += testing::srgb_byte_to_linear(byte(p, c));
    return sum / 3.0;
  }
  // Largest channel difference at p.
  int differs(const Shot& o, glm::vec2 p) const {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(byte(p, c) - o.byte(p, c)));
    return d;
  }
};

// A small cloth (the renderer needs one) far off to the side at x = 3, out of the way.
Scene side_cloth(std::vector<ColliderSpec> colliders = {}) {
  Scene s = testing::sheet(4, 0.3, 0.05, 100.0, IntegratorKind::symplectic_euler, 1e-3);
  s.cloths[0].origin = {3.0, 1.0, 0.0};
  s.cloths[0].pins = {{0, 0}, {3, 0}};
  s.colliders = std::move(colliders);
  return s;
}

ColliderSpec sphere(Vec3d c, double r) {
  ColliderSpec s;
  s.kind = ColliderKind::sphere;
  s.center = c;
  s.radius = r;
  return s;
}

class ColliderRenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { renderer_ = std::make_unique<vis::HeadlessRenderer>(kW, kH); }
  static void TearDownTestSuite() { renderer_.reset(); }

  // From the front (+z) and above, the origin in view; a spot light above; no sky.
  static vis::ViewSettings view(const Solver& solver) {
    vis::ViewSettings v = vis::default_view(solver);
    v.floor_height = 0.0f;
    v.camera.target = {0.0f, 0.4f, 0.0f};
    v.camera.yaw_deg = 0.0f;
    v.camera.pitch_deg = 25.0f;
    v.camera.distance = 3.5f;
    v.light_type = LightType::spot;
    v.light_position = {0.0f, 4.0f, 1.0f};
    v.light_target = glm::vec3(0.0f, 0.0f, 0.0f);
    v.light_intensity = 16.0f;
    v.sky = false;
    v.shadows = ShadowFilter::none;
    return v;
  }
  // The view rendered with `colliders` drawn (the solver's own, or none).
  static Shot shoot(Solver& solver, const std::vector<ColliderSpec>& colliders,
                    const vis::ViewSettings& v, RenderSpec spec = {}) {
    spec.pole.enabled = false;
    renderer_->set_cloth(solver);
    renderer_->set_scene(spec, solver, colliders);
    Shot shot{test::render_frame(*renderer_, solver, v)};
    // CLOTHLAB_TEST_IMAGES=DIR keeps every image for a look (named by test and count).
    if (const char* dir = std::getenv("CLOTHLAB_TEST_IMAGES")) {
      static int count = 0;
      Image image(kW, kH);
      image.rgba = shot.rgba;
      write_png(image, std::string(dir) + "/" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                           std::to_string(count++) + ".png");
    }
    return shot;
  }
  // A white directional light travelling along the view direction, no ambient: a surface facing
  // the camera is lit head-on (brighter than any floor tile, which the light grazes).
  static vis::ViewSettings head_on(vis::ViewSettings v) {
    v.light_type = LightType::directional;
    v.light_direction = glm::normalize(v.camera.target - v.camera.eye());
    v.light_intensity = 1.0f;
    v.light_color = {1.0f, 1.0f, 1.0f};
    v.ambient = 0.0f;
    return v;
  }
  static glm::vec2 pixel(const vis::ViewSettings& v, glm::vec3 p) {
    return testing::screen_position(v.camera, kW, kH, p);
  }

  static std::unique_ptr<vis::HeadlessRenderer> renderer_;
};
std::unique_ptr<vis::HeadlessRenderer> ColliderRenderTest::renderer_;

// A sphere and a box rotated 90 degrees about y cover their projected centres with neutral grey
// shading; beside them (and where the unrotated box would reach) the floor shows as without
// colliders. The light travels along the view direction, so a surface facing the camera is lit
// head-on (brighter than any floor tile, which the light grazes at 25 degrees) and the sphere
// darkens towards its silhouette.
TEST_F(ColliderRenderTest, SphereAndRotatedBoxAppearWhereTheyAre) {
  ColliderSpec box;
  box.kind = ColliderKind::box;
  box.center = {0.6, 0.3, 0.0};
  box.half_extents = {0.45, 0.1, 0.1};
  box.rotation = {0.0, 90.0, 0.0};  // its long side now along z
  const Scene scene = side_cloth({sphere({-0.5, 0.4, 0.0}, 0.3), box});
  auto solver = make_solver(scene);
  const vis::ViewSettings v = head_on(view(*solver));
  const Shot with = shoot(*solver, scene.colliders, v), without = shoot(*solver, {}, v);

  const glm::vec2 centre = pixel(v, {-0.5f, 0.4f, 0.0f});
  // Lit head-on: the albedo 0.7 (linear 0.45) times the light.
  EXPECT_NEAR(with.lum(centre), testing::srgb_to_linear(0.703), 0.05);
  EXPECT_GT(with.lum(centre), 1.6 * without.lum(centre));
  // Neutral grey (the collider colour 0.7, 0.7, 0.72 under a white light).
  EXPECT_NEAR(with.byte(centre, 0), with.byte(centre, 1), 3);
  EXPECT_NEAR(with.byte(centre, 2), with.byte(centre, 1) + 3, 3);
  // Near the silhouette (normal 70 degrees off the light) the cosine law darkens it.
  EXPECT_LT(with.lum(pixel(v, {-0.22f, 0.4f, 0.107f})), 0.5 * with.lum(centre));
  // Beside the sphere: floor as without colliders.
  EXPECT_LE(with.differs(without, pixel(v, {-1.1f, 0.0f, 0.3f})), 2);

  // The box reaches along z (rotated), not along x: its front face (z = 0.45, facing the light)
  // is lit head-on, its side face towards the camera (x = 0.5) is edge-on to the light and black,
  // and where the unrotated box's end would be the floor shows.
  EXPECT_GT(with.lum(pixel(v, {0.6f, 0.3f, 0.45f})),
            1.6 * without.lum(pixel(v, {0.6f, 0.3f, 0.45f})));
  EXPECT_LT(with.lum(pixel(v, {0.5f, 0.3f, 0.2f})),
            0.3 * without.lum(pixel(v, {0.5f, 0.3f, 0.2f})));
  EXPECT_LE(with.differs(without, pixel(v, {0.6f + 0.35f, 0.4f, 0.0f})), 2);
}

// A capsule between its ends a and b: both ends and the middle covered, above it the floor.
TEST_F(ColliderRenderTest, CapsuleSpansItsEnds) {
  ColliderSpec capsule;
  capsule.kind = ColliderKind::capsule;
  capsule.a = {-0.5, 0.3, 0.3};
  capsule.b = {0.5, 0.3, 0.3};
  capsule.radius = 0.12;
  const Scene scene = side_cloth({capsule});
  auto solver = make_solver(scene);
  const vis::ViewSettings v = view(*solver);
  const Shot with = shoot(*solver, scene.colliders, v), without = shoot(*solver, {}, v);
  for (float x : {-0.55f, 0.0f, 0.55f})  // beyond a and b by less than the radius
    EXPECT_GT(with.differs(without, pixel(v, {x, 0.3f, 0.3f})), 20) << "x " << x;
  EXPECT_LE(with.differs(without, pixel(v, {0.75f, 0.3f, 0.3f})), 2);
  EXPECT_LE(with.differs(without, pixel(v, {0.0f, 0.0f, 0.9f})), 2);
}

// A static plane facing up is the floor: scene_view puts the floor at its height, and the plane
// is not drawn again as a quad. Seen from above the front, a floor 1 m in half size ends in
// front of the camera at the plane's height: just inside that edge floor, just outside background
// (a floor at 0 would still cover that pixel; a drawn plane quad would cover both).
TEST_F(ColliderRenderTest, FloorSitsAtTheGroundPlane) {
  ColliderSpec ground;
  ground.kind = ColliderKind::plane;
  ground.point = {0.0, 0.25, 0.0};
  ground.normal = {0.0, 1.0, 0.0};
  const Scene scene = side_cloth({ground});
  auto solver = make_solver(scene);
  EXPECT_FLOAT_EQ(vis::scene_view(scene, *solver).floor_height, 0.25f);

  vis::ViewSettings v = view(*solver);
  v.floor_height = vis::scene_view(scene, *solver).floor_height;
  v.floor_half_size = 1.0f;
  const Shot with = shoot(*solver, scene.colliders, v);
  const glm::vec2 background{1.0f, 1.0f};  // the top-left corner, above the horizon
  const glm::vec2 inside = pixel(v, {0.0f, 0.25f, 0.9f}), outside = pixel(v, {0.0f, 0.25f, 1.1f});
  EXPECT_GT(std::abs(with.byte(inside, 0) - with.byte(background, 0)) +
                std::abs(with.byte(inside, 2) - with.byte(background, 2)),
            20);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(with.byte(outside, c), with.byte(background, c), 2);
}

// A sphere moving at v is drawn at c0 + v t for the solver's time t: the centroid of the pixels
// it changes is at the projected centre at t = 0 and after 0.4 s.
TEST_F(ColliderRenderTest, MovingColliderFollowsTheSolverClock) {
  ColliderSpec moving = sphere({-0.6, 0.4, 0.0}, 0.15);
  moving.motion.velocity = {2.0, 0.0, 0.0};
  const Scene scene = side_cloth({moving});
  auto solver = make_solver(scene);
  const vis::ViewSettings v = view(*solver);
  const auto centroid = [&] {
    const Shot with = shoot(*solver, scene.colliders, v), without = shoot(*solver, {}, v);
    glm::dvec2 sum(0.0);
    long n = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        if (with.differs(without, {x + 0.5f, y + 0.5f}) > 10)
          sum += glm::dvec2(x + 0.5, y + 0.5), ++n;
    EXPECT_GT(n, 50);
    return glm::vec2(sum / double(std::max(1L, n)));
  };
  const glm::vec2 at0 = centroid();
  const glm::vec2 expected0 = pixel(v, {-0.6f, 0.4f, 0.0f});
  EXPECT_NEAR(at0.x, expected0.x, 1.0);
  EXPECT_NEAR(at0.y, expected0.y, 1.0);
  solver->advance(0.4);
  const float t = static_cast<float>(solver->time());
  ASSERT_NEAR(t, 0.4f, 1e-6f);
  const glm::vec2 at1 = centroid();
  const glm::vec2 expected1 = pixel(v, {-0.6f + 2.0f * t, 0.4f, 0.0f});
  EXPECT_NEAR(at1.x, expected1.x, 1.0);
  EXPECT_NEAR(at1.y, expected1.y, 1.0);
  EXPECT_GT(at1.x - at0.x, 30.0f);  // it did move across the screen
}

// Colliders are shadow casters: the floor under a sphere lit from straight above is much darker
// with the sphere than without it.
TEST_F(ColliderRenderTest, CollidersCastShadows) {
  const Scene scene = side_cloth({sphere({0.0, 1.0, 0.0}, 0.25)});
  auto solver = make_solver(scene);
  vis::ViewSettings v = view(*solver);
  v.light_position = {0.0f, 4.0f, 0.0f};
  v.shadows = ShadowFilter::pcf;
  v.shadow_map_size = 1024;
  const Shot with = shoot(*solver, scene.colliders, v), without = shoot(*solver, {}, v);
  const glm::vec2 under = pixel(v, {0.0f, 0.0f, 0.0f});
  EXPECT_LT(with.lum(under), 0.5 * without.lum(under));
  // Beyond the shadow the floor is as lit as without the sphere.
  const glm::vec2 aside = pixel(v, {0.8f, 0.0f, 0.0f});
  EXPECT_NEAR(with.lum(aside), without.lum(aside), 0.02 * without.lum(aside) + 0.002);
}

// OBJ scenery ([[render.meshes]] type = "obj"): an elongated box read from an OBJ file, turned a
// quarter about y, is drawn where the scene places it (reaching along z, not x), shaded like the
// box collider above, and casts a shadow; it is scenery, so the solver knows nothing of it.
TEST_F(ColliderRenderTest, ObjSceneryIsDrawnTurnedAndCastsShadows) {
  const std::string path = ::testing::TempDir() + "clothlab_scenery_box.obj";
  {
    std::ofstream obj(path);
    obj << "# 0.9 x 0.2 x 0.2 box about the origin\n";
    for (int k = 0; k < 8; ++k)
      obj << "v " << (k & 1 ? 0.45 : -0.45) << ' ' << (k & 2 ? 0.1 : -0.1) << ' '
          << (k & 4 ? 0.1 : -0.1) << '\n';
    obj << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  }
  RenderSpec spec;
  MeshSpec box;
  box.kind = MeshKind::obj;
  box.obj = std::make_shared<const TriangleMesh>(load_obj(path));
  box.center = {0.6, 0.3, 0.0};
  box.rotation = {0.0, 90.0, 0.0};
  box.color = {0.7, 0.7, 0.72};
  spec.meshes = {box};
  std::remove(path.c_str());

  const Scene scene = side_cloth();
  auto solver = make_solver(scene);
  vis::ViewSettings v = head_on(view(*solver));
  const Shot with = shoot(*solver, {}, v, spec), without = shoot(*solver, {}, v);
  // As the box collider: the front face (z = 0.45) lit head-on, the side face (x = 0.5) edge-on
  // and black, the unrotated box's end showing floor.
  EXPECT_GT(with.lum(pixel(v, {0.6f, 0.3f, 0.45f})),
            1.6 * without.lum(pixel(v, {0.6f, 0.3f, 0.45f})));
  EXPECT_LT(with.lum(pixel(v, {0.5f, 0.3f, 0.2f})),
            0.3 * without.lum(pixel(v, {0.5f, 0.3f, 0.2f})));
  EXPECT_LE(with.differs(without, pixel(v, {0.6f + 0.35f, 0.4f, 0.0f})), 2);

  // A shadow on the floor under it, lit from straight above.
  v = view(*solver);
  v.light_position = {0.6f, 4.0f, 0.0f};
  v.shadows = ShadowFilter::pcf;
  v.shadow_map_size = 1024;
  const Shot lit = shoot(*solver, {}, v, spec), bare = shoot(*solver, {}, v);
  // The box floats 0.2 m above the floor: under it (x 0.5..0.7, z -0.45..0.45) the floor is in
  // shadow; 0.2 m beyond its side it is lit as without the box.
  EXPECT_LT(lit.lum(pixel(v, {0.6f, 0.0f, 0.3f})), 0.5 * bare.lum(pixel(v, {0.6f, 0.0f, 0.3f})));
  EXPECT_NEAR(lit.lum(pixel(v, {0.9f, 0.0f, 0.0f})), bare.lum(pixel(v, {0.9f, 0.0f, 0.0f})),
              0.02 * bare.lum(pixel(v, {0.9f, 0.0f, 0.0f})) + 0.002);
}

}  // namespace
}  // namespace clothlab
