// Mesh colliders (sim/mesh/): an OBJ read by tinyobjloader, its signed distance grid against the
// closed form of a box and of an L-shaped block (a concave notch: the sign by ray parity must
// see it as outside), the same drop on an OBJ cube and on a box collider, and the scene errors
// for a missing, malformed or empty OBJ file.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>

#include "load/scene_load.hpp"
#include "sim/contact/collider.hpp"
#include "sim/mesh/sdf_grid.hpp"
#include "sim/mesh/triangle_mesh.hpp"
#include "sim/scene/scene_error.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

namespace fs = std::filesystem;
using V3 = Eigen::Vector3d;

// A temporary folder for this test's OBJ files, removed at the end.
class MeshCollider : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("clothlab_mesh_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  // An axis-aligned box of half extents h as six quads (the reader fans them into triangles),
  // faces wound outwards.
  std::string box_obj(const V3& h) const {
    std::string text = "# box\n";
    for (int k = 0; k < 8; ++k)
      text += "v " + std::to_string(k & 1 ? h.x() : -h.x()) + " " +
              std::to_string(k & 2 ? h.y() : -h.y()) + " " +
              std::to_string(k & 4 ? h.z() : -h.z()) + "\n";
    text += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    return write("box.obj", text);
  }
  fs::path dir_;
};

double centred_box_distance(const V3& p, const V3& h) {
  const V3 q = p.cwiseAbs() - h;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

// Inside, outside and near the surface the grid's distance is the box's within half a cell, and
// its gradient is the face normal where one face is nearest.
TEST_F(MeshCollider, CubeDistanceMatchesTheClosedForm) {
  const V3 h(0.3, 0.2, 0.25);
  const TriangleMesh mesh = load_obj(box_obj(h));
  ASSERT_EQ(mesh.triangles.size(), 12u);
  const SdfGrid sdf(mesh, 64);
  std::mt19937 rng(5);
  double worst = 0.0;
  std::uniform_real_distribution<double> w(0.0, 1.0);
  for (int k = 0; k < 2000; ++k) {  // within the grid (beyond it the distance is an estimate)
    const V3 p = sdf.lo() + (sdf.hi() - sdf.lo()).cwiseProduct(V3(w(rng), w(rng), w(rng)));
    worst = std::max(worst, std::abs(sdf.distance(p) - centred_box_distance(p, h)));
  }
  EXPECT_LT(worst, 0.5 * sdf.cell()) << "cell " << sdf.cell() << " m";
  V3 n;
  EXPECT_NEAR(sdf.distance(V3(0.05, 0.25, 0.02), &n), 0.05, 1e-6);  // above the top face
  EXPECT_NEAR(n.y(), 1.0, 1e-6);
  EXPECT_LT(sdf.distance(V3(0.0, 0.0, 0.0)), -0.19);  // the middle is inside
  EXPECT_NEAR(sdf.distance(V3(2.0, 0.0, 0.0)), 1.7, 1e-6) << "beyond the grid: distance added";
}

// An L-shaped block (a 0.4 m cube with a 0.2 m notch cut from one edge): points in the notch
// are outside (positive), points in the block inside, both within half a cell of the truth.
TEST_F(MeshCollider, ConcaveNotchIsOutside) {
  // Extruded along z from an L in x-y: (0,0) (0.4,0) (0.4,0.2) (0.2,0.2) (0.2,0.4) (0,0.4).
  std::string text;
  const double xy[6][2] = {{0, 0}, {0.4, 0}, {0.4, 0.2}, {0.2, 0.2}, {0.2, 0.4}, {0, 0.4}};
  for (double z : {0.0, 0.4})
    for (const auto& p : xy)
      text +=
          "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(z) + "\n";
  text += "f 1 6 5 4 3 2\nf 7 8 9 10 11 12\n";  // the two L faces (fanned: the L is star-shaped
                                                // from vertex 1)
  for (int i = 0; i < 6; ++i) {
    const int a = i + 1, b = (i + 1) % 6 + 1;
    text += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(b + 6) + " " +
            std::to_string(a + 6) + "\n";
  }
  const SdfGrid sdf(load_obj(write("l.obj", text)), 64);
  EXPECT_NEAR(sdf.distance(V3(0.3, 0.3, 0.2)), 0.1, 0.5 * sdf.cell()) << "in the notch";
  EXPECT_NEAR(sdf.distance(V3(0.1, 0.1, 0.2)), -0.1, 0.5 * sdf.cell()) << "in the block";
  EXPECT_NEAR(sdf.distance(V3(0.3, 0.1, 0.2)), -0.1, 0.5 * sdf.cell()) << "in the short arm";
}

// The same drop onto a 0.6 x 0.4 x 0.5 m box collider and onto an OBJ of that box: after 1.5 s
// every vertex rests within 5 mm of where it rests on the analytic box (measured: 2.5 mm with the
// default 64 cells, whose cell is 9 mm; 15 mm with 32 cells, 0.02 mm with 128).
TEST_F(MeshCollider, DropOnAnObjCubeMatchesTheBoxCollider) {
  const V3 h(0.3, 0.2, 0.25);
  const std::string obj = box_obj(h);
  auto drop = [&](bool mesh) {
    Scene s = testing::sheet(24, 1.0, 0.2, 400.0, IntegratorKind::symplectic_euler, 2.5e-4);
    s.cloths[0].origin = {-0.4, 0.7, -0.5};
    s.cloths[0].u_axis = {1.0, 0.0, 0.0};
    s.cloths[0].v_axis = {0.0, 0.0, 1.0};
    s.springs.damping = 0.02;
    s.forces.drag = 0.002;
    s.solver.precision = Precision::f64;
    ColliderSpec c;
    c.kind = mesh ? ColliderKind::mesh : ColliderKind::box;
    c.center = {0.0, 0.2, 0.0};
    c.half_extents = {h.x(), h.y(), h.z()};
    c.static_friction = c.kinetic_friction = 0.4;
    if (mesh) c.mesh = std::make_shared<const TriangleMesh>(load_obj(obj));
    ColliderSpec floor;
    floor.kind = ColliderKind::plane;
    s.colliders = {c, floor};
    std::unique_ptr<Solver> solver = make_solver(s);
    EXPECT_TRUE(solver->advance(1.5).ok());
    return solver;
  };
  const auto box = drop(false), mesh = drop(true);
  double worst = 0.0;
  for (std::size_t i = 0; i < box->vertex_count(); ++i) {
    const Vec3d a = box->position(int(i)), b = mesh->position(int(i));
    worst = std::max(worst, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
  }
  EXPECT_LT(worst, 0.005);
  EXPECT_GT(box->position(12 + 12 * 24)[1], 0.4) << "the middle rests on the box's top";
}

// A missing, malformed or empty OBJ is a scene error naming the collider's file key.
TEST_F(MeshCollider, BadObjFilesAreSceneErrors) {
  const std::string empty = write("empty.obj", "# nothing here\nv 0 0 0\n");
  const std::string bad_index = write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  struct Case {
    std::string file, says;
  };
  // An index beyond int range: tinyobjloader alone wrapped 4294967297 to 1 and took the face.
  const std::string wrapped = write("wrap.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 4294967297 2 3\n");
  const std::string zero = write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2//2 0\n");
  const std::string pipe = (dir_ / "pipe.obj").string();
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0644), 0);  // reading it would block: refused by its kind
  const Case cases[] = {{(dir_ / "missing.obj").string(), "no such OBJ file"},
                        {dir_.string(), "a directory, not an OBJ file"},
                        {pipe, "a device, pipe or socket, not an OBJ file"},
                        {"/dev/zero", "a device, pipe or socket, not an OBJ file"},
                        {empty, "has no faces"},
                        {bad_index, "bad.obj"},
                        {wrapped, "wrap.obj: line 4: face corner \"4294967297\" has index"},
                        {zero, "zero.obj: line 4: face corner \"0\" has index 0"}};
  for (const Case& c : cases) {
    const std::string text =
        "[cloth]\nresolution = [4, 4]\n\n[[colliders]]\ntype = \"mesh\"\nfile = \"" + c.file +
        "\"\n";
    try {
      read_scene_string(text, "scene.toml");
      ADD_FAILURE() << "accepted " << c.file;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.key, "colliders[0].file") << e.what();
      EXPECT_EQ(e.loc.line, 6) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
  // A relative path is read from the scene file's folder.
  box_obj(V3(0.1, 0.1, 0.1));
  const std::string scene = write("s.toml",
                                  "[cloth]\nresolution = [4, 4]\n\n[[colliders]]\n"
                                  "type = \"mesh\"\nfile = \"box.obj\"\nscale = 2\n");
  const Scene s = read_scene_file(scene);
  ASSERT_TRUE(s.colliders[0].mesh);
  EXPECT_NEAR(s.colliders[0].mesh->positions[7].x(), 0.2, 1e-6);
}

}  // namespace
}  // namespace clothlab
