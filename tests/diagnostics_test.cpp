// The scientific views on screen (headless EGL): the cloth coloured by a scalar shows the colour
// map's own table entries at the ends of the range and its middle where the value is halfway
// (mapped per fragment), arrows come one per shown vertex with the map's colour at their
// magnitude, zero arrows draw nothing, and with every view off no diagnostic state exists.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <memory>

#include "pixels.hpp"
#include "render_frame.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/colormap/colormap.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/render/scalar_field.hpp"

namespace clothlab {
namespace {

constexpr int kDiagnosticsWidth = 320, kDiagnosticsHeight = 240;

// A flat res x res sheet, 1 m, lying horizontal at height 1 m and tilted by `rise` (m over its
// depth), all vertices pinned so it stays exactly where it was built.
Scene flat_sheet(double rise, int res = 9) {
  Scene s = testing::sheet(res, 1.0, 0.2, 100.0, IntegratorKind::symplectic_euler, 1e-3);
  ClothSpec& c = s.cloths[0];
  c.origin = {-0.5, 1.0, -0.5};
  c.u_axis = {1.0, 0.0, 0.0};
  const double depth = std::sqrt(1.0 - rise * rise);
  c.v_axis = {0.0, rise, depth};
  c.pins.clear();
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) c.pins.push_back({i, j});
  return s;
}

// Looking straight down on the sheet's centre (pitch 89 degrees).
vis::ViewSettings top_view(const Solver& solver) {
  vis::ViewSettings view = vis::default_view(solver);
  view.camera.target = {0.0f, 1.0f, 0.0f};
  view.camera.pitch_deg = 89.0f;
  view.camera.yaw_deg = 0.0f;
  view.camera.distance = 2.0f;
  return view;
}

std::array<int, 3> pixel(const std::vector<std::uint8_t>& rgba, int x, int y) {
  const std::size_t i =
      4 * (static_cast<std::size_t>(y) * kDiagnosticsWidth + static_cast<std::size_t>(x));
  return {rgba[i], rgba[i + 1], rgba[i + 2]};
}

// Largest channel difference between a pixel and a colour in [0, 1].
int off_by(const std::array<int, 3>& p, glm::vec3 c) {
  int worst = 0;
  for (int k = 0; k < 3; ++k)
    worst = std::max(worst, std::abs(p[k] - static_cast<int>(std::lround(255.0f * c[k]))));
  return worst;
}

std::array<int, 2> pixel_of(const vis::ViewSettings& view, glm::vec3 p) {
  const glm::vec2 s =
      testing::screen_position(view.camera, kDiagnosticsWidth, kDiagnosticsHeight, p);
  return {static_cast<int>(std::floor(s.x)), static_cast<int>(std::floor(s.y))};
}

class DiagnosticsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    renderer_ = std::make_unique<vis::HeadlessRenderer>(kDiagnosticsWidth, kDiagnosticsHeight);
  }
  static void TearDownTestSuite() { renderer_.reset(); }
  static std::unique_ptr<vis::HeadlessRenderer> renderer_;
};
std::unique_ptr<vis::HeadlessRenderer> DiagnosticsTest::renderer_;

// A value at or below the range's minimum shows entry 0, at or above its maximum entry 255,
// exactly (8-bit framebuffer: within 1/255), for every map.
TEST_F(DiagnosticsTest, RangeEndsShowTheTablesEndEntries) {
  const auto solver = make_solver(flat_sheet(0.0));
  renderer_->set_cloth(*solver);
  vis::ViewSettings view = top_view(*solver);
  view.color.field = vis::ScalarField::height;
  view.color.range = vis::RangeMode::fixed;
  for (vis::ColorMap map : vis::kAllColorMaps) {
    view.color.map = map;
    const auto table = vis::colormap_table(map);
    view.color.fixed = {1.0, 2.0};  // the sheet at 1 m is the minimum
    const auto low = pixel(test::render_frame(*renderer_, *solver, view), kDiagnosticsWidth / 2,
                           kDiagnosticsHeight / 2);
    view.color.fixed = {-3.0, 0.5};  // above the maximum
    const auto high = pixel(test::render_frame(*renderer_, *solver, view), kDiagnosticsWidth / 2,
                            kDiagnosticsHeight / 2);
    for (int k = 0; k < 3; ++k) {
      const int lo_entry[3] = {table[0].r, table[0].g, table[0].b};
      const int hi_entry[3] = {table[255].r, table[255].g, table[255].b};
      EXPECT_NEAR(low[k], lo_entry[k], 1) << vis::colormap_name(map) << " channel " << k;
      EXPECT_NEAR(high[k], hi_entry[k], 1) << vis::colormap_name(map) << " channel " << k;
    }
  }
}

// A tilted sheet whose height rises linearly over its depth: at the pixel above its centre the
// interpolated height is halfway through the automatic range, so the pixel shows the map at
// 0.5 (colormap_sample, within 2/255); the pixels a quarter in show 0.25 and 0.75. Mapping
// per-vertex colours instead would show the mean of two entries, not the map.
TEST_F(DiagnosticsTest, InterpolatedValuesAreMappedPerFragment) {
  const auto solver = make_solver(flat_sheet(0.5));
  renderer_->set_cloth(*solver);
  vis::ViewSettings view = top_view(*solver);
  view.color.field = vis::ScalarField::height;
  view.color.map = vis::ColorMap::turbo;  // strongly curved: a wrong mapping is visible
  const std::vector<std::uint8_t> image = test::render_frame(*renderer_, *solver, view);
  const vis::ScalarRange range = *renderer_->diagnostics().color_range();
  EXPECT_NEAR(range.min, 1.0, 1e-6);
  EXPECT_NEAR(range.max, 1.5, 1e-6);
  const double depth = std::sqrt(0.75);
  for (double f : {0.25, 0.5, 0.75}) {
    // The surface point at fraction f of the depth, between vertex rows (not on a vertex).
    const glm::vec3 p{0.03f, float(1.0 + 0.5 * f), float(-0.5 + depth * f)};
    const auto [px, py] = pixel_of(view, p);
    EXPECT_LE(off_by(pixel(image, px, py), vis::colormap_sample(view.color.map, f)), 2)
        << "at fraction " << f;
  }
}

// The colour bar shows the cloth's colours: its pixel at the height of tick value v equals the
// cloth's pixel where the scalar is v (within 3/255: the bar's strips blend in sRGB, the cloth in
// linear light), and it spans the range the cloth was coloured with.
TEST_F(DiagnosticsTest, ColourBarMatchesTheCloth) {
  const auto solver = make_solver(flat_sheet(0.5));
  renderer_->set_cloth(*solver);
  vis::ViewSettings view = top_view(*solver);
  view.color.field = vis::ScalarField::height;
  view.color.map = vis::ColorMap::turbo;
  const std::vector<std::uint8_t> image = test::render_frame(*renderer_, *solver, view);
  ASSERT_EQ(renderer_->legends().size(), 1u);
  const vis::LegendBar& bar = renderer_->legends()[0];
  EXPECT_NEAR(bar.range.min, 1.0, 1e-6);
  EXPECT_NEAR(bar.range.max, 1.5, 1e-6);
  const double depth = std::sqrt(0.75);
  for (double v : {1.1, 1.2, 1.3, 1.4}) {
    const double f = (v - 1.0) / 0.5;
    const auto [cx, cy] = pixel_of(view, glm::vec3{0.03f, float(v), float(-0.5 + depth * f)});
    const int bx = static_cast<int>(bar.top_left.x + 0.5f * bar.size.x);
    const int by = static_cast<int>(bar.top_left.y + bar.size.y * float(1.0 - f));
    const std::array<int, 3> c = pixel(image, cx, cy), b = pixel(image, bx, by);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(b[k], c[k], 3) << "value " << v << " channel " << k;
  }
  // Without legends nothing is drawn there.
  view.legends = false;
  test::render_frame(*renderer_, *solver, view);
  EXPECT_TRUE(renderer_->legends().empty());
}

// The contact view (key C): a second sheet 3 mm above the first, both pinned flat, shows the
// map at 3 mm of its range, twice the 5 mm self_thickness (0.3; within 2/255), and the bar spans
// [0, 10 mm]; tilted so that it passes through the first sheet along the middle, the crossing
// triangles show the warning colour, magenta, and the sheet near its edge, 8 mm apart, does not.
TEST_F(DiagnosticsTest, ContactViewShowsTheGapAndCrossingsInMagenta) {
  Scene scene = flat_sheet(0.0);
  scene.cloths.push_back(scene.cloths[0]);
  scene.cloths[1].origin = {-0.5, 1.003, -0.5};
  const auto layered = make_solver(scene);
  renderer_->set_cloth(*layered);
  vis::ViewSettings view = top_view(*layered);
  view.color.field = vis::ScalarField::contact;
  view.color.map = vis::ColorMap::turbo;
  const std::vector<std::uint8_t> image = test::render_frame(*renderer_, *layered, view);
  const vis::ScalarRange range = *renderer_->diagnostics().color_range();
  EXPECT_EQ(range.min, 0.0);
  EXPECT_NEAR(range.max, 0.01, 1e-12);
  const auto [px, py] = pixel_of(view, {0.03f, 1.003f, 0.03f});
  EXPECT_LE(off_by(pixel(image, px, py), vis::colormap_sample(view.color.map, 0.3)), 2);

  // Through the first at z = 0, between its rows and columns (a vertex on the other sheet touches
  // it; it does not cross).
  scene.cloths[1].origin = {-0.44, 0.991, -0.45};
  scene.cloths[1].v_axis = {0.0, 0.02, std::sqrt(1.0 - 0.02 * 0.02)};
  const auto crossing = make_solver(scene);
  renderer_->set_cloth(*crossing);
  const std::vector<std::uint8_t> crossed = test::render_frame(*renderer_, *crossing, view);
  const auto [cx, cy] = pixel_of(view, {0.03f, 1.0f, 0.0f});
  EXPECT_LE(off_by(pixel(crossed, cx, cy), {1.0f, 0.0f, 1.0f}), 2);
  const auto [fx, fy] = pixel_of(view, {0.03f, 1.0f, -0.42f});  // 8 mm apart: not crossed
  EXPECT_GT(off_by(pixel(crossed, fx, fy), {1.0f, 0.0f, 1.0f}), 100);
}

// Gravity arrows all have magnitude m g: with the range fixed at [0, 2 m g] each shows the
// map's middle colour on the side facing the camera, one arrow per shown vertex.
TEST_F(DiagnosticsTest, ArrowsComeOnePerShownVertexInTheMapsColour) {
  constexpr int kRes = 5;  // coarse: arrows several pixels wide
  const auto solver = make_solver(flat_sheet(0.0, kRes));
  renderer_->set_cloth(*solver);
  vis::ViewSettings view = vis::default_view(*solver);
  view.camera.target = {0.0f, 0.95f, 0.5f};
  view.camera.pitch_deg = 0.0f;  // level with the sheet: the arrows hang below it, side on
  view.camera.yaw_deg = 0.0f;
  view.camera.distance = 0.8f;
  view.arrows.force = true;
  view.force_source = ForceSource::gravity;
  view.color.map = vis::ColorMap::viridis;
  view.color.range = vis::RangeMode::fixed;
  const double mg = 0.2 / (kRes * kRes) * 9.81;
  view.color.fixed = {0.0, 2.0 * mg};
  for (int stride : {3, 2, 1}) {
    view.arrows.stride = stride;
    const std::vector<std::uint8_t> image = test::render_frame(*renderer_, *solver, view);
    const vis::Diagnostics& d = renderer_->diagnostics();
    // 0, s, 2s, ... plus the last index, along both sides of the sheet.
    const int per_side = (kRes - 1 + stride - 1) / stride + 1;
    ASSERT_EQ(d.force_arrows().size(), std::size_t(per_side * per_side)) << "stride " << stride;
    ASSERT_EQ(d.arrow_layout().vertices.size(), d.force_arrows().size());
    for (const vis::ArrowInstance& a : d.force_arrows()) EXPECT_NEAR(a.value, 0.5f, 1e-6f);
    if (stride != 1) continue;
    // The front row's middle arrow: half the longest length, pointing down; its shaft's middle.
    const vis::ArrowInstance& a = d.force_arrows()[kRes * (kRes - 1) + kRes / 2];
    EXPECT_NEAR(glm::length(a.vector), 0.5f * 0.9f * d.arrow_layout().spacing, 1e-6f);
    EXPECT_LT(a.vector.y, 0.0f);
    const auto [px, py] = pixel_of(view, a.base + 0.35f * a.vector);
    EXPECT_LE(off_by(pixel(image, px, py), vis::colormap_sample(view.color.map, 0.5)), 2);
  }
}

// Wind arrows with the wind off are all zero: nothing is drawn (the image equals the one without
// arrows) and nothing is NaN.
TEST_F(DiagnosticsTest, ZeroArrowsDrawNothing) {
  const auto solver = make_solver(flat_sheet(0.2));
  renderer_->set_cloth(*solver);
  vis::ViewSettings view = vis::default_view(*solver);
  view.legends = false;  // the arrows' colour bar would differ; the arrows must not
  const std::vector<std::uint8_t> plain = test::render_frame(*renderer_, *solver, view);
  view.arrows.force = true;
  view.force_source = ForceSource::wind;
  const std::vector<std::uint8_t> with_zero_arrows = test::render_frame(*renderer_, *solver, view);
  for (const vis::ArrowInstance& a : renderer_->diagnostics().force_arrows()) {
    EXPECT_EQ(glm::length(a.vector), 0.0f);
    EXPECT_TRUE(std::isfinite(a.value));
  }
  EXPECT_EQ(plain, with_zero_arrows);
}

// Normal arrows show the side of the cloth the camera sees (as mode 2 colours it): looked at from
// above or from below, every arrow of the tilted sheet points towards the camera, and the two
// views give opposite arrows of the same length.
TEST_F(DiagnosticsTest, NormalArrowsPointToTheCamerasSide) {
  const auto solver = make_solver(flat_sheet(0.2));
  renderer_->set_cloth(*solver);
  std::vector<glm::vec3> seen[2];
  for (int side = 0; side < 2; ++side) {
    vis::ViewSettings view = top_view(*solver);
    view.camera.pitch_deg = side == 0 ? 60.0f : -60.0f;  // above, then below the sheet
    view.arrows.normals = true;
    test::render_frame(*renderer_, *solver, view);
    const glm::vec3 eye = view.camera.eye();
    ASSERT_FALSE(renderer_->diagnostics().normal_arrows().empty());
    for (const vis::ArrowInstance& a : renderer_->diagnostics().normal_arrows()) {
      EXPECT_GT(glm::dot(a.vector, eye - a.base), 0.0f) << "an arrow faces away from the camera";
      seen[side].push_back(a.vector);
    }
  }
  ASSERT_EQ(seen[0].size(), seen[1].size());
  for (std::size_t k = 0; k < seen[0].size(); ++k)
    EXPECT_NEAR(glm::length(seen[0][k] + seen[1][k]), 0.0f, 1e-6f);
}

// With every view off the diagnostics hold nothing and no force field is computed.
TEST_F(DiagnosticsTest, EverythingOffHoldsNothing) {
  const auto solver = make_solver(flat_sheet(0.2));
  renderer_->set_cloth(*solver);
  vis::ViewSettings view = vis::default_view(*solver);
  view.arrows.force = true;
  view.force_source = ForceSource::springs;
  test::render_frame(*renderer_, *solver, view);
  EXPECT_TRUE(renderer_->diagnostics().active());
  EXPECT_EQ(solver->force_field_source(), ForceSource::springs);
  view = vis::default_view(*solver);
  solver->update_force_field(ForceSource::gravity);
  test::render_frame(*renderer_, *solver, view);
  EXPECT_FALSE(renderer_->diagnostics().active());
  EXPECT_FALSE(renderer_->diagnostics().color_range());
  EXPECT_EQ(solver->force_field_source(), ForceSource::gravity);  // untouched by the render
}

}  // namespace
}  // namespace clothlab
