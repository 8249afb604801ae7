// Tube cloth (sim/cloth/tube_cloth.*): rings where the spec puts them, the seed rule across the
// seam exactly as elsewhere (every vertex of a ring has the same springs), a hanging tube that
// stays round (a weaker seam would sag on one side), and the scene errors.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "load/scene_load.hpp"
#include "sim/cloth/tube_cloth.hpp"
#include "sim/scene/scene_error.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/solver.hpp"

namespace clothlab {
namespace {

// A frustum 0.6 m long along -y, radius 0.2 at the top ring and 0.35 at the hem: a skirt.
ClothSpec skirt(int around = 24, int rings = 12) {
  ClothSpec c;
  c.shape = "tube";
  c.resolution = {around, rings};
  c.origin = {0.0, 1.0, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, -1.0, 0.0};
  c.radius = {0.2, 0.35};
  c.length = 0.6;
  c.mass = 0.3;
  c.key = "cloth";
  return c;
}

TEST(TubeCloth, RingsLieWhereTheSpecSays) {
  const GridCloth g = build_tube_cloth(skirt());
  ASSERT_EQ(g.positions.size(), 24u * 12u);
  EXPECT_TRUE(g.wrap_u);
  EXPECT_EQ(g.triangles.size(), 2u * 24u * 11u);  // the seam's quads included
  for (int j = 0; j < 12; ++j) {
    const double s = j / 11.0, r = 0.2 + s * 0.15, y = 1.0 - 0.6 * s;
    for (int i = 0; i < 24; ++i) {
      const Vec3d p = g.positions[std::size_t(g.index(i, j))];
      EXPECT_NEAR(std::hypot(p[0], p[2]), r, 1e-12);
      EXPECT_NEAR(p[1], y, 1e-12);
    }
  }
  const Vec3d seam = g.positions[0];
  EXPECT_NEAR(seam[0], 0.2, 1e-12) << "vertex 0 lies along u_axis";
}

// Every vertex of a ring has the same springs (count, summed stiffness and summed rest
// length), whether it is next to the seam or opposite it.
TEST(TubeCloth, SeamIsAsStrongAsTheRest) {
  const GridCloth g = build_tube_cloth(skirt());
  struct Sum {
    int count = 0;
    double stiffness = 0.0, rest = 0.0;
  };
  std::map<int, Sum> per_vertex;
  for (const Spring& s : seed_springs_tube(g, SpringStiffness::uniform(800.0))) {
    for (int v : {s.a, s.b}) {
      per_vertex[v].count += 1;
      per_vertex[v].stiffness += s.stiffness;
      per_vertex[v].rest += s.rest_length;
    }
  }
  for (int j = 0; j < 12; ++j) {
    const Sum& ref = per_vertex[g.index(12, j)];  // opposite the seam
    for (int i : {0, 1, 23}) {
      const Sum& at = per_vertex[g.index(i, j)];
      EXPECT_EQ(at.count, ref.count) << "ring " << j << ", vertex " << i;
      EXPECT_NEAR(at.stiffness, ref.stiffness, 1e-9 * ref.stiffness) << "ring " << j;
      EXPECT_NEAR(at.rest, ref.rest, 1e-12) << "ring " << j;
    }
  }
  EXPECT_EQ(per_vertex[g.index(5, 6)].count, 20) << "an inner ring vertex has the 20 neighbours";
}

// Hung by its top ring with gravity and damping, the skirt settles round: after 1 s every ring's
// vertices share one height and one distance from the axis within 1 micrometre.
TEST(TubeCloth, HangingTubeStaysRound) {
  Scene scene;
  ClothSpec c = skirt();
  for (int i = 0; i < 24; ++i) c.pins.push_back({i, 0});
  scene.cloths = {c};
  scene.springs.stiffness = 800.0;
  scene.springs.damping = 0.05;
  scene.forces.drag = 0.01;
  scene.solver.integrator = IntegratorKind::implicit_euler;
  scene.solver.dt = 2e-3;
  scene.solver.threads = 1;
  scene.solver.precision = Precision::f64;
  std::unique_ptr<Solver> s = make_solver(scene);
  ASSERT_TRUE(s->advance(1.0).ok());
  double worst = 0.0;
  for (int j = 1; j < 12; ++j) {
    const Vec3d ref = s->position(12 + 24 * j);
    for (int i = 0; i < 24; ++i) {
      const Vec3d p = s->position(i + 24 * j);
      worst = std::max({worst, std::abs(p[1] - ref[1]),
                        std::abs(std::hypot(p[0], p[2]) - std::hypot(ref[0], ref[2]))});
    }
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(s->position(24 * 11)[1], 0.4 - 1e-4) << "it hangs (stretched by its weight)";
}

TEST(TubeCloth, SceneErrorsNameTheKey) {
  struct Case {
    std::string text, key, says;
  };
  const Case cases[] = {
      {"[cloth]\nshape = \"tube\"\nsize = [1, 1]\n", "cloth.size", "radius and length"},
      {"[cloth]\nshape = \"tube\"\nresolution = [4, 8]\n", "cloth.resolution", "at least 6"},
      {"[cloth]\nshape = \"tube\"\nradius = [0.3, -0.1]\n", "cloth.radius[1]", "must be > 0"},
      {"[cloth]\nlength = 2\n", "cloth.length", "belongs to shape = \"tube\""},
  };
  for (const Case& c : cases) {
    try {
      read_scene_string(c.text, "t.toml");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.key, c.key) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
  const Scene ok = read_scene_string(
      "[cloth]\nshape = \"tube\"\nradius = 0.25\nlength = 0.5\nresolution = [16, 8]\n", "t.toml");
  EXPECT_EQ(ok.cloths[0].radius, (std::array<double, 2>{0.25, 0.25}));
}

}  // namespace
}  // namespace clothlab
