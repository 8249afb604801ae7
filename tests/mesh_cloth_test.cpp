// Cloth from a triangle mesh (shape = "mesh", sim/cloth/mesh_cloth.hpp): springs along every edge
// and across every interior edge with the rest-length rule, area-lumped masses, pins by OBJ
// vertex number; the physics of the general solver on it (a hung cloth carries its weight on its
// pins, a dropped one rests on a sphere without sinking in, the same for any thread count);
// scene errors; the tangent frame the renderer computes from its triangles.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "load/scene_load.hpp"
#include "sim/cloth/mesh_cloth.hpp"
#include "sim/contact/collider.hpp"
#include "sim/mesh/triangle_mesh.hpp"
#include "sim/scene/scene_error.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/scene/validate.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/textures/cloth_tangents.hpp"

namespace clothlab {
namespace {

const std::string kRoundCloth = std::string(CLOTHLAB_SOURCE_DIR) + "/assets/meshes/round_cloth.obj";

// A mesh cloth scene in code: the OBJ at `path` scaled by `scale`, placed at `origin`.
Scene mesh_scene(std::shared_ptr<const TriangleMesh> mesh, Vec3d origin,
                 std::vector<int> pin_numbers) {
  Scene s;
  ClothSpec c;
  c.shape = "mesh";
  c.mesh = std::move(mesh);
  c.resolution = {static_cast<int>(c.mesh->positions.size()), 1};
  c.origin = origin;
  c.mass = 0.2;
  for (int p : pin_numbers) c.pins.push_back({p - 1, 0});
  c.key = "cloth";
  s.cloths.push_back(c);
  s.springs.stiffness = 600.0;
  s.springs.damping = 0.05;
  s.forces.drag = 0.01;
  s.solver.integrator = IntegratorKind::symplectic_euler;
  s.solver.dt_auto = true;
  s.solver.threads = 1;
  s.solver.precision = Precision::f64;
  return s;
}

// The unit square as two triangles (0, 1, 2) and (0, 2, 3) in the x-z plane.
std::shared_ptr<const TriangleMesh> unit_square() {
  auto m = std::make_shared<TriangleMesh>();
  m->positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  m->triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// The round cloth's rim starts at vertex number 722 (16 rings of 6k vertices round a centre).
constexpr int kRim = 722, kRimCount = 96;

}  // namespace

// Two triangles: five edge springs and one bending spring across the shared diagonal (between
// the two opposite corners), each k = stiffness * edge / rest with edge the median edge (1 m).
TEST(MeshCloth, EdgeAndBendingSpringsFollowTheRestLengthRule) {
  Scene s = mesh_scene(unit_square(), {0, 0, 0}, {});
  const GridCloth g = build_mesh_cloth(s.cloths[0]);
  EXPECT_TRUE(g.mesh);
  EXPECT_EQ(g.nu, 4);
  EXPECT_EQ(g.nv, 1);
  EXPECT_DOUBLE_EQ(g.edge, 1.0);
  const std::vector<Spring> springs = mesh_springs(g, SpringStiffness::uniform(100.0));
  std::map<std::pair<int, int>, Spring> by_ends;
  for (const Spring& sp : springs) by_ends[{sp.a, sp.b}] = sp;
  ASSERT_EQ(springs.size(), 6u);
  for (auto e : {std::pair{0, 1}, {1, 2}, {2, 3}, {0, 3}}) {
    ASSERT_TRUE(by_ends.count(e));
    EXPECT_DOUBLE_EQ(by_ends[e].rest_length, 1.0);
    EXPECT_DOUBLE_EQ(by_ends[e].stiffness, 100.0);
  }
  for (auto e : {std::pair{0, 2}, {1, 3}}) {  // the diagonal edge, and the bend across it
    ASSERT_TRUE(by_ends.count(e));
    EXPECT_DOUBLE_EQ(by_ends[e].rest_length, std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(by_ends[e].stiffness, 100.0 / std::sqrt(2.0));
  }
}

// On the round cloth: one spring per edge plus one per interior edge (E + E_interior), masses
// lumped by area sum to the cloth's mass, and the centre vertex (six equal triangles round it)
// carries a third of their area's share.
TEST(MeshCloth, RoundClothHasOneBendPerInteriorEdgeAndAreaMasses) {
  auto mesh = std::make_shared<const TriangleMesh>(load_obj(kRoundCloth));
  Scene s = mesh_scene(mesh, {0, 1, 0}, {});
  const GridCloth g = build_mesh_cloth(s.cloths[0]);
  const auto edges = mesh_edges(g.triangles);
  std::map<std::pair<int, int>, int> faces_at;
  for (const auto& t : g.triangles)
    for (int c = 0; c < 3; ++c)
      ++faces_at[{std::min(t[c], t[(c + 1) % 3]), std::max(t[c], t[(c + 1) % 3])}];
  std::size_t interior = 0;
  for (const auto& [e, count] : faces_at) interior += count == 2;
  EXPECT_EQ(edges.size(), 2352u);
  EXPECT_EQ(interior, edges.size() - kRimCount);
  EXPECT_EQ(mesh_springs(g, SpringStiffness::uniform(600.0)).size(), edges.size() + interior);

  double total = 0.0;
  for (double m : g.masses) total += m;
  EXPECT_NEAR(total, 0.2, 1e-12);
  double area = 0.0;
  for (const auto& t : g.triangles) {
    const Eigen::Vector3d a(g.positions[t[0]].data()), b(g.positions[t[1]].data()),
        c(g.positions[t[2]].data());
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  // Ring 1 is a regular hexagon of radius 0.05 m round the centre (written to 6 digits).
  const double r = 0.8 / 16.0, hexagon = 1.5 * std::sqrt(3.0) * r * r;
  EXPECT_NEAR(g.masses[0], 0.2 * (hexagon / 3.0) / area, 1e-5 * g.masses[0]);  // 6-digit OBJ
}

// Hung by six rim points and settled, the round cloth's pins carry its weight: the springs'
// vertical pull on the pinned vertices equals the free vertices' weight within 0.5 %, and the
// pins have not moved.
TEST(MeshCloth, HungClothCarriesItsWeightOnItsPins) {
  auto mesh = std::make_shared<const TriangleMesh>(load_obj(kRoundCloth, 0.5));
  std::vector<int> pins;
  for (int k = 0; k < 6; ++k) pins.push_back(kRim + 16 * k);
  Scene scene = mesh_scene(mesh, {0, 1, 0}, pins);
  scene.springs.damping = 0.2;
  scene.forces.drag = 0.02;
  std::unique_ptr<Solver> s = make_solver(scene);
  ASSERT_TRUE(s->advance(4.0).ok());
  s->update_force_field(ForceSource::springs);
  double pull = 0.0, free_mass = 0.0, mass = 0.0;
  const GridCloth g = build_mesh_cloth(scene.cloths[0]);
  for (std::size_t i = 0; i < s->vertex_count(); ++i) {
    mass += g.masses[i];
    if (s->pinned(int(i))) {
      pull += s->force(int(i))[1];
      const Vec3d p = s->position(int(i));
      EXPECT_EQ(p, g.positions[i]) << "pin " << i + 1;
    } else {
      free_mass += g.masses[i];
    }
  }
  EXPECT_NEAR(mass, 0.2, 1e-12);
  // The springs pull the pins down by the weight they hold up.
  EXPECT_NEAR(-pull, free_mass * 9.81, 0.005 * free_mass * 9.81);
  // It sags: the centre below the rim.
  EXPECT_LT(s->position(0)[1], 1.0 - 0.02);
}

// Dropped onto a sphere, the round cloth never sinks into it (1e-3 R below the thickness at every
// step), comes to rest on its top, and drapes down its sides; the same, bit for bit, on
// 2 threads (a mesh cloth's edge contacts run in a fixed order).
TEST(MeshCloth, DropOntoASphereRestsWithoutSinkingOnAnyThreadCount) {
  auto mesh = std::make_shared<const TriangleMesh>(load_obj(kRoundCloth, 0.75));
  Scene scene = mesh_scene(mesh, {0.0, 0.75, 0.0}, {});
  ColliderSpec ball;
  ball.kind = ColliderKind::sphere;
  ball.center = {0.0, 0.3, 0.0};
  ball.radius = 0.3;
  ball.static_friction = ball.kinetic_friction = 0.5;
  ball.key = "colliders[0]";
  scene.colliders = {ball};
  const auto one_owner = testing::solver<double>(scene);
  Solver& one = *one_owner;
  const Collider c(ball);
  double worst = -INFINITY;
  while (one.time() < 1.5) {
    ASSERT_TRUE(one.step(1).ok());
    const ColliderPose pose = c.pose(one.time());
    for (std::size_t i = 0; i < one.vertex_count(); ++i) {
      const Vec3d p = one.position(int(i));
      worst =
          std::max(worst, c.thickness() - c.local_distance(pose.to_local({p[0], p[1], p[2]})).phi);
    }
  }
  EXPECT_LE(worst, 1e-3 * 0.3);
  EXPECT_NEAR(one.position(0)[1], 0.6 + ball.thickness, 0.01) << "the centre rests on the top";
  double rim = 0.0, highest = -INFINITY;
  for (int k = 0; k < kRimCount; ++k) {
    rim += one.position(kRim - 1 + k)[1] / kRimCount;
    highest = std::max(highest, one.position(kRim - 1 + k)[1]);
  }
  EXPECT_LT(highest, 0.5) << "the whole rim hangs down the sides (the top is at 0.6)";
  EXPECT_LT(rim, 0.42);

  scene.solver.threads = 2;
  std::unique_ptr<Solver> two = make_solver(scene);
  ASSERT_TRUE(two->step(one.step_count()).ok());
  for (std::size_t i = 0; i < one.vertex_count(); ++i)
    ASSERT_EQ(one.position(int(i)), two->position(int(i))) << "vertex " << i;
}

// The shipped scene parses, and mesh errors name the file, line and key.
TEST(MeshCloth, SceneFileAndErrors) {
  const Scene s = read_scene_file(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/round_cloth.toml");
  ASSERT_EQ(s.cloths.size(), 1u);
  EXPECT_EQ(s.cloths[0].resolution[0], 817);
  EXPECT_EQ(s.cloths[0].pins.front()[0], kRim - 1);

  auto error_of = [](const std::string& text) -> std::string {
    try {
      validate_scene(read_scene_string(text, "m.toml"));
    } catch (const SceneError& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string head = "[cloth]\nshape = \"mesh\"\nfile = \"" + kRoundCloth + "\"\n";
  std::string e = error_of(head + "pins = [1, 900]\n");
  EXPECT_NE(e.find("m.toml:4"), std::string::npos) << e;
  EXPECT_NE(e.find("cloth.pins[1]"), std::string::npos) << e;
  EXPECT_NE(e.find("not an OBJ vertex number (1..817)"), std::string::npos) << e;
  e = error_of(head + "resolution = [4, 4]\n");
  EXPECT_NE(e.find("cloth.resolution"), std::string::npos) << e;
  EXPECT_NE(e.find("belongs to a grid or tube cloth"), std::string::npos) << e;
  e = error_of("[cloth]\nshape = \"mesh\"\n");
  EXPECT_NE(e.find("cloth.file"), std::string::npos) << e;
  e = error_of("[cloth]\nshape = \"mesh\"\nfile = \"no_such_cloth.obj\"\n");
  EXPECT_NE(e.find("m.toml:3"), std::string::npos) << e;
  EXPECT_NE(e.find("no_such_cloth.obj"), std::string::npos) << e;
}

// A vertex no face uses is refused (it would fall alone), naming the OBJ file and vertex.
TEST(MeshCloth, LooseVertexIsRefused) {
  auto mesh = std::make_shared<TriangleMesh>(*unit_square());
  mesh->positions.push_back({5, 5, 5});
  Scene s = mesh_scene(mesh, {0, 0, 0}, {});
  s.cloths[0].file = "square.obj";
  try {
    validate_scene(s);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("square.obj: OBJ vertex 5 belongs to no face"),
              std::string::npos)
        << e.what();
  }
}

// The renderer's tangent frame from a mesh's triangles and UVs: on a flat sheet with UVs along
// x and z, T = +x and w = +1 at every vertex; mirroring u flips T and w.
TEST(MeshCloth, TangentsFromTrianglesFollowTheUvs) {
  const TriangleMesh sq = *unit_square();
  std::vector<float> pos, nrm, uv, tangents(16);
  for (const Eigen::Vector3d& p : sq.positions) {
    pos.insert(pos.end(), {float(p.x()), float(p.y()), float(p.z())});
    nrm.insert(nrm.end(), {0.0f, -1.0f, 0.0f});  // (b - a) x (c - a) of these triangles
    uv.insert(uv.end(), {float(p.x()), float(p.z())});
  }
  std::vector<float> scratch;
  compute_mesh_tangents(0, 4, sq.triangles, pos.data(), nrm.data(), uv.data(), tangents.data(),
                        scratch);
  for (int v = 0; v < 4; ++v) {
    EXPECT_NEAR(tangents[4 * v], 1.0f, 1e-6f);
    EXPECT_NEAR(tangents[4 * v + 1], 0.0f, 1e-6f);
    EXPECT_NEAR(tangents[4 * v + 2], 0.0f, 1e-6f);
    // B = w N x T must point along +z (dP/dv): (0,-1,0) x (1,0,0) = (0,0,1), so w = +1.
    EXPECT_EQ(tangents[4 * v + 3], 1.0f);
  }
  for (int v = 0; v < 4; ++v) uv[2 * v] = 1.0f - uv[2 * v];
  compute_mesh_tangents(0, 4, sq.triangles, pos.data(), nrm.data(), uv.data(), tangents.data(),
                        scratch);
  for (int v = 0; v < 4; ++v) {
    EXPECT_NEAR(tangents[4 * v], -1.0f, 1e-6f);
    EXPECT_EQ(tangents[4 * v + 3], -1.0f);
  }
}

}  // namespace clothlab
