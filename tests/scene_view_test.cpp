// What a scene file says about the view (vis/render/view_settings.cpp, scene_view): the ground
// plane collider is the floor, the view frames the colliders, and [render.camera] overrides the
// framing key by key. Mesh colliders are framed by their OBJ's box.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "load/scene_load.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/solver.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
namespace {

const std::string kScene = R"([cloth]
resolution = [8, 8]

[[colliders]]
type = "plane"
point = [0, 0.3, 0]

[[colliders]]
type = "sphere"
center = [3, 0.5, 0]
radius = 0.5
)";

TEST(SceneView, FloorAndFramingComeFromTheColliders) {
  const Scene scene = read_scene_string(kScene, "t.toml");
  const std::unique_ptr<Solver> solver = make_solver(scene);
  const vis::ViewSettings plain = vis::default_view(*solver);
  const vis::ViewSettings v = vis::scene_view(scene, *solver);
  EXPECT_FLOAT_EQ(v.floor_height, 0.3f);
  EXPECT_GT(v.camera.target.x, plain.camera.target.x + 0.5f) << "the sphere at x = 3 is framed";
  EXPECT_GT(v.camera.distance, plain.camera.distance);
}

// A mesh collider is framed by its OBJ's box, as an analytic one is (the shipped chair placed
// 3 m off along x draws the view's target that way).
TEST(SceneView, MeshCollidersAreFramedToo) {
  const std::string mesh(
      "[cloth]\nresolution = [8, 8]\n\n[[colliders]]\ntype = \"mesh\"\nfile = "
      "\"" CLOTHLAB_SOURCE_DIR "/assets/meshes/chair.obj\"\ncenter = [3, 0, 0]\n");
  const Scene scene = read_scene_string(mesh, "t.toml");
  const std::unique_ptr<Solver> solver = make_solver(scene);
  const vis::ViewSettings plain = vis::default_view(*solver);
  const vis::ViewSettings v = vis::scene_view(scene, *solver);
  EXPECT_GT(v.camera.target.x, plain.camera.target.x + 0.5f) << "the chair at x = 3 is framed";
}

TEST(SceneView, SceneCameraOverridesTheFraming) {
  const Scene scene = read_scene_string(
      kScene + "\n[render.camera]\ntarget = [1, 2, 3]\npitch = 40\ndistance = 7.5\n", "t.toml");
  const std::unique_ptr<Solver> solver = make_solver(scene);
  const vis::ViewSettings framed = vis::scene_view(read_scene_string(kScene, "t.toml"), *solver);
  const vis::ViewSettings v = vis::scene_view(scene, *solver);
  EXPECT_EQ(v.camera.target, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_FLOAT_EQ(v.camera.pitch_deg, 40.0f);
  EXPECT_FLOAT_EQ(v.camera.distance, 7.5f);
  EXPECT_FLOAT_EQ(v.camera.yaw_deg, framed.camera.yaw_deg) << "yaw not given: framed";
  EXPECT_THROW(read_scene_string(kScene + "\n[render.camera]\npitch = 95\n", "t.toml"),
               std::exception);
}

}  // namespace
}  // namespace clothlab
