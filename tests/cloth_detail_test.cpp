// Coarser drawings of large grid cloths (vis/render/cloth_detail.hpp): the levels cover the same
// rest area with the solver's winding, small cloths and tubes keep every triangle, the stride
// follows the cloth's size on screen, and at fast quality a large sheet drawn at every second
// vertex looks as when drawn at every one (320 x 240, headless).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "image_compare.hpp"
#include "render_frame.hpp"
#include "test_scenes.hpp"
#include "vis/render/cloth_detail.hpp"
#include "vis/render/cloth_layout.hpp"

namespace clothlab {
namespace {

using vis::ClothDetail;

// A 2 m sheet of n x n vertices lying in the x-z plane, pinned at two corners.
Scene large_sheet(int n) {
  Scene s = testing::sheet(n, 2.0, 0.5, 1000.0, IntegratorKind::xpbd, 1.0 / 60.0);
  s.cloths[0].origin = {-1.0, 1.5, -1.0};
  s.cloths[0].v_axis = {0.0, 0.0, 1.0};
  s.cloths[0].pins = {{0, 0}, {n - 1, 0}};
  return s;
}

glm::dvec3 rest_of(const vis::ClothLayout& l, std::uint32_t v) {
  const float* rest = l.fixed.data() + 2 * l.render_vertices() + 3 * std::size_t(v);
  return {rest[0], rest[1], rest[2]};
}

// Twice the rest area of triangle t of `indices`, signed along +y (the sheet's rest normal side).
glm::dvec3 doubled_area(const vis::ClothLayout& l, const std::uint32_t* t) {
  const glm::dvec3 a = rest_of(l, t[0]), b = rest_of(l, t[1]), c = rest_of(l, t[2]);
  return glm::cross(b - a, c - a);
}

TEST(ClothDetail, LinesKeepEveryStrideAndTheLast) {
  EXPECT_EQ(vis::detail_lines(10, 4), (std::vector<int>{0, 4, 8, 9}));
  EXPECT_EQ(vis::detail_lines(9, 4), (std::vector<int>{0, 4, 8}));
  EXPECT_EQ(vis::detail_lines(5, 1), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(ClothDetail, NoteNamesTheStride) {
  EXPECT_EQ(vis::detail_note(1), "");
  EXPECT_EQ(vis::detail_note(2), "every 2nd vertex");
  EXPECT_EQ(vis::detail_note(4), "every 4th vertex");
  EXPECT_EQ(vis::detail_note(32), "every 32nd vertex");
}

TEST(ClothDetail, LevelsCoverTheSheetWithTheSolversWinding) {
  const auto solver = testing::solver<float>(large_sheet(65));
  const vis::ClothLayout l = vis::make_cloth_layout(*solver);
  const ClothDetail d = vis::make_cloth_detail(l);
  ASSERT_EQ(d.levels.size(), 2u);  // 64 cells: strides 2 and 4 keep 16 or more
  EXPECT_NEAR(d.cell, 2.0 / 64.0, 1e-6);
  const double fine_side = doubled_area(l, l.triangles.data()).y;
  for (const vis::DetailLevel& level : d.levels) {
    SCOPED_TRACE(level.stride);
    const int kept = 64 / level.stride + 1;
    EXPECT_EQ(level.count, std::size_t(6 * (kept - 1) * (kept - 1)));
    std::set<std::uint32_t> used;
    double area = 0.0;
    for (std::size_t t = level.first; t < level.first + level.count; t += 3) {
      const glm::dvec3 n = doubled_area(l, d.indices.data() + t);
      EXPECT_GT(n.y * fine_side, 0.0) << "triangle " << t / 3 << " wound the other way";
      area += 0.5 * glm::length(n);
      for (int k = 0; k < 3; ++k) used.insert(d.indices[t + std::size_t(k)]);
    }
    EXPECT_NEAR(area, 4.0, 1e-4);
    EXPECT_EQ(used.size(), std::size_t(kept * kept));
    for (std::uint32_t v : used) {
      EXPECT_EQ(int(v % 65) % level.stride, 0) << v;
      EXPECT_EQ(int(v / 65) % level.stride, 0) << v;
    }
  }
}

TEST(ClothDetail, SmallClothsAndTubesKeepEveryTriangle) {
  // The default-sized sheet gets no level at all.
  const auto small = testing::solver<float>(large_sheet(32));
  EXPECT_TRUE(vis::make_cloth_detail(vis::make_cloth_layout(*small)).levels.empty());
  // Beside a large sheet, a 20 x 20 sheet and a tube are drawn whole at every level.
  Scene s = large_sheet(129);
  ClothSpec little = s.cloths[0];
  little.resolution = {20, 20};
  little.origin = {3.0, 1.5, 0.0};
  little.pins = {};
  ClothSpec tube = little;
  tube.shape = "tube";
  tube.resolution = {12, 6};
  s.cloths.push_back(little);
  s.cloths.push_back(tube);
  const auto solver = testing::solver<float>(s);
  const vis::ClothLayout l = vis::make_cloth_layout(*solver);
  const ClothDetail d = vis::make_cloth_detail(l);
  ASSERT_EQ(d.levels.size(), 3u);  // 128 cells: strides 2, 4 and 8
  const std::size_t others = 3 * (2 * 19 * 19 + 2 * 12 * 5);
  for (const vis::DetailLevel& level : d.levels) {
    const int kept = 128 / level.stride + 1;
    EXPECT_EQ(level.count, std::size_t(6 * (kept - 1) * (kept - 1)) + others) << level.stride;
  }
}

TEST(ClothDetail, StrideFollowsTheSizeOnScreen) {
  const auto solver = testing::solver<float>(large_sheet(129));
  const ClothDetail d = vis::make_cloth_detail(vis::make_cloth_layout(*solver));
  const double cell = d.cell;  // 15.6 mm
  // Cells of 1 pixel: stride 4 keeps them within kDetailCellPixels, 8 would not.
  EXPECT_EQ(vis::detail_stride(d, 1.0 / cell), 4);
  EXPECT_EQ(vis::detail_stride(d, 1.9 / cell), 2);
  EXPECT_EQ(vis::detail_stride(d, 0.49 / cell), 8);
  EXPECT_EQ(vis::detail_stride(d, 3.0 / cell), 1);
  EXPECT_EQ(vis::detail_stride(d, INFINITY), 1);
  // A metre 2 m in front of the eye across a 40 degree view 720 pixels high.
  const double ppm = vis::pixels_per_metre({0, 0, 0}, {-1, -1, -3}, {1, 1, -2}, 40.0f, 720);
  EXPECT_NEAR(ppm, 720.0 / (2.0 * 2.0 * std::tan(glm::radians(20.0))), 1e-3);
  EXPECT_TRUE(std::isinf(vis::pixels_per_metre({0, 0, 0}, {-1, -1, -1}, {1, 1, 1}, 40.0f, 720)));
}

TEST(ClothDetail, FastQualityDrawsALargeSheetCoarserWithTheSameLook) {
  vis::HeadlessRenderer renderer(320, 240);
  auto solver = testing::solver<float>(large_sheet(129));
  ASSERT_TRUE(solver->step(30).ok());  // half a second of falling: folds and a swing
  renderer.set_cloth(*solver);
  vis::ViewSettings view = vis::default_view(*solver);
  view.quality = RenderQuality::fast;
  Image coarse(320, 240), every(320, 240);
  coarse.rgba = test::render_frame(renderer, *solver, view);
  const int stride = renderer.renderer().cloth_stride();
  EXPECT_GT(stride, 1);
  renderer.renderer().enable_coarse_cloth(false);
  every.rgba = test::render_frame(renderer, *solver, view);
  EXPECT_EQ(renderer.renderer().cloth_stride(), 1);
  const testing::Comparison c = testing::compare(coarse, every);
  std::printf("[ stride %d vs 1 ] mean %.3f/255, %.2f %% of pixels off by more than 8/255\n",
              stride, c.mean_abs, 100.0 * c.fraction_over);
  EXPECT_LT(c.mean_abs, 0.5);
  EXPECT_LT(c.fraction_over, 0.005);
  // Full quality draws every triangle.
  renderer.renderer().enable_coarse_cloth(true);
  view.quality = RenderQuality::full;
  test::render_frame(renderer, *solver, view);
  EXPECT_EQ(renderer.renderer().cloth_stride(), 1);
}

}  // namespace
}  // namespace clothlab
