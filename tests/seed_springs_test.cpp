// The seed spring rule: counts on small grids and equality of the O(N) and O(N^2) builders.
#include "sim/cloth/seed_springs.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace clothlab {
namespace {

GridCloth seed_grid(int nu, int nv, double su, double sv) {
  ClothSpec c;
  c.resolution = {nu, nv};
  c.size = {su, sv};
  c.origin = {0.3, -1.2, 2.0};
  c.u_axis = {0.0, 0.0, 2.0};  // not unit length: the builder normalises
  c.v_axis = {1.0, 0.0, 0.0};
  return build_grid_cloth(c);
}

TEST(SeedSprings, FourByFourGridHas82Springs) {
  // Offsets with di^2 + dj^2 < 8: 12 + 12 horizontal/vertical, 9 + 9 diagonal, 8 + 8 two apart,
  // 4 x 6 knight moves = 82; the (2, 2) pair at exactly 2 sqrt(2) edge is not joined.
  EXPECT_EQ(seed_springs_grid(seed_grid(4, 4, 1.0, 1.0), SpringStiffness::uniform(800.0)).size(),
            82u);
}

TEST(SeedSprings, InteriorVertexHasTwentyNeighbours) {
  const auto springs = seed_springs_grid(seed_grid(5, 5, 1.0, 1.0), SpringStiffness::uniform(1.0));
  int degree = 0;
  const int centre = 2 + 2 * 5;
  for (const auto& s : springs) degree += (s.a == centre) + (s.b == centre);
  EXPECT_EQ(degree, 20);
}

TEST(SeedSprings, OneByTwoGridIsASingleSpring) {
  const auto springs = seed_springs_grid(seed_grid(1, 2, 1.0, 0.7), SpringStiffness::uniform(50.0));
  ASSERT_EQ(springs.size(), 1u);
  EXPECT_DOUBLE_EQ(springs[0].rest_length, 0.7);
  EXPECT_DOUBLE_EQ(springs[0].stiffness, 50.0);  // edge / rest = 1
  EXPECT_TRUE(seed_springs_grid(seed_grid(1, 1, 1.0, 1.0), SpringStiffness::uniform(50.0)).empty());
}

TEST(SeedSprings, StiffnessScalesWithEdgeOverRestLength) {
  for (const auto& s :
       seed_springs_grid(seed_grid(4, 4, 3.0, 3.0), SpringStiffness::uniform(800.0)))
    EXPECT_NEAR(s.stiffness * s.rest_length, 800.0 * 1.0, 1e-9);
}

TEST(SeedSprings, GridBuilderEqualsAllPairsBuilder) {
  // Square, rectangular and anisotropic spacings (the reach then spans more rows than columns).
  const int shapes[][2] = {{4, 4}, {7, 5}, {2, 9}, {10, 3}, {6, 6}};
  const double sizes[][2] = {{1.0, 1.0}, {2.0, 0.5}, {0.3, 1.7}, {1.0, 0.25}};
  for (const auto& shape : shapes) {
    for (const auto& size : sizes) {
      const GridCloth g = seed_grid(shape[0], shape[1], size[0], size[1]);
      const auto fast = seed_springs_grid(g, SpringStiffness::uniform(123.0));
      const auto slow =
          seed_springs_all_pairs(g.positions, g.edge, SpringStiffness::uniform(123.0));
      ASSERT_EQ(fast.size(), slow.size())
          << shape[0] << "x" << shape[1] << " size " << size[0] << "x" << size[1];
      for (std::size_t k = 0; k < fast.size(); ++k) {
        EXPECT_EQ(fast[k].a, slow[k].a);
        EXPECT_EQ(fast[k].b, slow[k].b);
        EXPECT_NEAR(fast[k].rest_length, slow[k].rest_length, 1e-12);
        EXPECT_NEAR(fast[k].stiffness, slow[k].stiffness, 1e-9);
      }
    }
  }
}

}  // namespace
}  // namespace clothlab
