// The cloth surface (area-weighted unit normals, vertex areas) by grid row sweeps equals the
// surface from the triangle list, on perturbed cloths of every shape; and a flat sheet's vertex
// areas add up to its area.
#include <gtest/gtest.h>

#include <random>

#include "sim/forces/force_field.hpp"
#include "sim/model/model.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

std::vector<Scene> shapes() {
  Scene square = testing::sheet(9, 1.0, 0.2, 100.0, IntegratorKind::verlet, 1e-4);
  Scene two = square;
  ClothSpec second = square.cloths[0];
  second.resolution = {5, 13};
  second.size = {0.4, 1.3};
  second.origin = {2.0, 0.0, 0.0};
  two.cloths.push_back(second);
  two.multi_cloth = true;
  Scene strip = square;
  strip.cloths[0].resolution = {1, 6};
  return {square, two, strip};
}

TEST(Surface, GridSweepEqualsTriangleList) {
  for (const Scene& scene : shapes()) {
    const Model<double> m = build_model<double>(scene);
    Vec3Array<double> pos = m.rest_positions;
    std::mt19937 rng(3);
    std::normal_distribution<double> normal(0.0, 0.05);
    for (std::size_t i = 0; i < m.n; ++i)
      for (int a = 0; a < 3; ++a) pos.axis(a)[i] += normal(rng);
    ForceWorkspace<double> sweep, list;
    sweep.resize(m);
    list.resize(m);
    compute_surface(m, pos, sweep, 1);
    compute_surface_from_triangles(m, pos, list, 1);
    for (std::size_t i = 0; i < m.n; ++i) {
      for (int a = 0; a < 3; ++a)
        ASSERT_NEAR(sweep.normal.axis(a)[i], list.normal.axis(a)[i], 1e-12) << "vertex " << i;
      ASSERT_NEAR(sweep.vertex_area[i], list.vertex_area[i], 1e-14) << "vertex " << i;
    }
  }
}

TEST(Surface, VertexAreasOfAFlatSheetAddUpToItsArea) {
  Scene scene = testing::sheet(7, 1.0, 0.2, 100.0, IntegratorKind::verlet, 1e-4);
  scene.cloths[0].size = {1.5, 0.8};
  const Model<double> m = build_model<double>(scene);
  ForceWorkspace<double> ws;
  ws.resize(m);
  compute_surface(m, m.rest_positions, ws, 2);
  double area = 0.0;
  for (double a : ws.vertex_area) area += a;
  EXPECT_NEAR(area, 1.5 * 0.8, 1e-12);
  for (std::size_t i = 0; i < m.n; ++i) EXPECT_NEAR(std::abs(ws.normal.z[i]), 1.0, 1e-12);
}

}  // namespace
}  // namespace clothlab
