// Real pixels from the headless renderer (EGL; Mesa llvmpipe on CI): normals in world space,
// lighting by the scene's one light.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "gl/gl_error.hpp"
#include "gl/headless_context.hpp"
#include "gl/offscreen_target.hpp"
#include "gl/program.hpp"
#include "sim/fields/frame_fields.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/frame_request.hpp"
#include "vis/render/renderer.hpp"
#include "vis/textures/image.hpp"

namespace clothlab {
namespace {

using vis::DisplayMode;

// One GL context for the whole test program.
class RenderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<vis::HeadlessContext>(); }
  static void TearDownTestSuite() { context_.reset(); }

  struct Pixel {
    int r, g, b;
  };
  // Renders the solver's cloth with the given settings; returns RGBA rows, top first.
  std::vector<std::uint8_t> render(Solver& solver, const vis::ViewSettings& view, int w, int h,
                                   const vis::PixelRect& covered = {}) {
    vis::Renderer renderer;
    renderer.set_cloth(solver);
    FieldSnapshot snapshot;
    renderer.update_cloth(snapshot.take(solver, vis::frame_request(view, renderer)));
    vis::OffscreenTarget target(w, h);
    target.bind();
    renderer.draw(view, w, h, covered);
    return target.read_rgba();
  }
  static Pixel at(const std::vector<std::uint8_t>& img, int w, int x, int y) {
    const std::size_t k = 4 * (static_cast<std::size_t>(y) * w + x);
    return {img[k], img[k + 1], img[k + 2]};
  }

  static std::unique_ptr<vis::HeadlessContext> context_;
};
std::unique_ptr<vis::HeadlessContext> RenderTest::context_;

// A horizontal 1 m sheet at y = 1 whose u x v points up (u = +x, v = -z), no gravity.
Scene render_flat_sheet() {
  Scene s = testing::sheet(16, 1.0, 0.2, 100.0, IntegratorKind::symplectic_euler, 1e-3);
  s.cloths[0].origin = {-0.5, 1.0, 0.5};
  s.cloths[0].v_axis = {0.0, 0.0, -1.0};
  s.forces.gravity = {0.0, 0.0, 0.0};
  return s;
}

TEST_F(RenderTest, FlatClothInNormalModeShowsTheWorldUpNormal) {
  const auto solver_owner = testing::solver<float>(render_flat_sheet());
  Solver& solver = *solver_owner;
  vis::ViewSettings view = vis::default_view(solver);
  view.mode = DisplayMode::normals;
  for (float yaw : {0.0f, 70.0f, 200.0f}) {  // the colour is the world normal from any side
    view.camera.yaw_deg = yaw;
    view.camera.pitch_deg = 60.0f;
    const auto img = render(solver, view, 160, 120);
    const Pixel p = at(img, 160, 80, 60);  // the cloth fills the centre
    EXPECT_NEAR(p.r, 128, 1) << "yaw " << yaw;
    EXPECT_EQ(p.g, 255) << "yaw " << yaw;
    EXPECT_NEAR(p.b, 128, 1) << "yaw " << yaw;
  }
  // Seen from below (floor moved out of the way), the visible side faces down:
  // (0, -1, 0) -> (128, 0, 128).
  view.camera.pitch_deg = -60.0f;
  view.floor_height = -20.0f;
  const auto below = render(solver, view, 160, 120);
  const Pixel q = at(below, 160, 80, 60);
  EXPECT_NEAR(q.r, 128, 1);
  EXPECT_EQ(q.g, 0);
  EXPECT_NEAR(q.b, 128, 1);
}

// Screen position (pixels, top-left origin) of a world point.
glm::vec2 project(const vis::ViewSettings& view, glm::vec3 p, int w, int h) {
  const glm::vec4 c = view.camera.projection(float(w) / h) * view.camera.view() * glm::vec4(p, 1);
  return {(c.x / c.w * 0.5f + 0.5f) * w, (0.5f - c.y / c.w * 0.5f) * h};
}

int render_luminance(const std::vector<std::uint8_t>& img, int w, glm::vec2 p) {
  const std::size_t k = 4 * (static_cast<std::size_t>(p.y) * w + static_cast<std::size_t>(p.x));
  return img[k] + img[k + 1] + img[k + 2];
}

TEST_F(RenderTest, FloorIsBrighterUnderTheLightThanFarFromIt) {
  const auto solver_owner = testing::solver<float>(render_flat_sheet());
  Solver& solver = *solver_owner;
  vis::ViewSettings view = vis::default_view(solver);
  view.camera.pitch_deg = 35.0f;
  view.camera.distance *= 2.0f;
  const int w = 320, h = 240;
  // Two floor spots left and right of the cloth, both in view; the light hangs 1.5 m above one
  // and then above the other. Comparing each pixel with itself cancels the tile pattern.
  const glm::vec3 a{-1.5f, view.floor_height, -0.5f}, b{1.5f, view.floor_height, -0.5f};
  const glm::vec2 pa = project(view, a, w, h), pb = project(view, b, w, h);
  for (glm::vec2 p : {pa, pb}) {
    ASSERT_GT(p.x, 0);
    ASSERT_LT(p.x, w);
    ASSERT_GT(p.y, 0);
    ASSERT_LT(p.y, h);
  }
  view.light_position = a + glm::vec3(0, 1.5f, 0);
  const auto over_a = render(solver, view, w, h);
  view.light_position = b + glm::vec3(0, 1.5f, 0);
  const auto over_b = render(solver, view, w, h);
  EXPECT_GT(render_luminance(over_a, w, pa), render_luminance(over_b, w, pa) + 60);
  EXPECT_GT(render_luminance(over_b, w, pb), render_luminance(over_a, w, pb) + 60);
}

// The window's panel covers part of the frame: nothing is shaded there (the background colour
// stays), and every pixel outside it is the same as without the panel, in both qualities.
TEST_F(RenderTest, NothingIsDrawnUnderACoveredRectangle) {
  const auto solver_owner = testing::solver<float>(render_flat_sheet());
  Solver& solver = *solver_owner;
  for (const RenderQuality quality : {RenderQuality::full, RenderQuality::fast}) {
    vis::ViewSettings view = vis::default_view(solver);
    view.quality = quality;
    view.camera.lens_shift = 0.3f;
    const int w = 240, h = 160;
    const vis::PixelRect panel{10, 20, 70, 120};  // bottom-left origin
    const auto whole = render(solver, view, w, h), covered = render(solver, view, w, h, panel);
    int inside = 0, outside_differs = 0, drawn_inside_before = 0;
    const Pixel corner = at(covered, w, panel.x + 1, h - panel.y - 2);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int gl_y = h - 1 - y;  // rows are top first
        const bool in = x >= panel.x && x < panel.x + panel.width && gl_y >= panel.y &&
                        gl_y < panel.y + panel.height;
        const Pixel a = at(whole, w, x, y), b = at(covered, w, x, y);
        const bool same = a.r == b.r && a.g == b.g && a.b == b.b;
        if (in) {
          ++inside;
          EXPECT_TRUE(b.r == corner.r && b.g == corner.g && b.b == corner.b) << x << "," << y;
          drawn_inside_before += !same;
        } else {
          outside_differs += !same;
        }
      }
    EXPECT_EQ(inside, 70 * 120);
    // The clear colour, encoded as GL_FRAMEBUFFER_SRGB writes it.
    const auto encoded = [](float c) {
      return 255.0 * (1.055 * std::pow(double(c), 1.0 / 2.4) - 0.055);
    };
    EXPECT_NEAR(corner.r, encoded(view.background.r), 1.0);
    EXPECT_NEAR(corner.g, encoded(view.background.g), 1.0);
    EXPECT_NEAR(corner.b, encoded(view.background.b), 1.0);
    EXPECT_EQ(outside_differs, 0);
    EXPECT_GT(drawn_inside_before, inside / 2);  // the scene was there: floor, sky, cloth
  }
}

TEST_F(RenderTest, ClothIsLitByTheSameLight) {
  const auto solver_owner = testing::solver<float>(render_flat_sheet());
  Solver& solver = *solver_owner;
  vis::ViewSettings view = vis::default_view(solver);
  view.camera.pitch_deg = 50.0f;
  const int w = 200, h = 150;
  const glm::vec2 centre = project(view, {0.0f, 1.0f, 0.0f}, w, h);
  view.light_position = {0.0f, 2.5f, 0.0f};  // above the cloth: lights the side we see
  const int lit = render_luminance(render(solver, view, w, h), w, centre);
  view.light_position = {0.0f, -0.5f, 0.0f};  // below it: only ambient on our side
  const int unlit = render_luminance(render(solver, view, w, h), w, centre);
  EXPECT_GT(lit, unlit + 100) << "lit " << lit << ", unlit " << unlit;
  EXPECT_GT(unlit, 0);  // ambient keeps it visible
}

// A cloth without triangles (the single spring: two vertices) is drawn as its spring and its
// vertices in every mode, not as nothing: in each of modes 1-6 the free vertex's pixel is
// the vertices' light grey, and the middle of the spring is a light line on the background.
TEST_F(RenderTest, ClothWithoutTrianglesShowsItsSpringAndVerticesInEveryMode) {
  const auto owner =
      testing::solver<float>(testing::single_spring(0.1, 100.0, 0.5, IntegratorKind::verlet, 1e-3));
  Solver& solver = *owner;
  vis::ViewSettings view = vis::default_view(solver);
  view.sky = false;
  view.shadows = ShadowFilter::none;
  const int w = 160, h = 120;
  const Vec3d a = solver.position(0), b = solver.position(1);
  const glm::vec2 free_vertex = project(view, {float(b[0]), float(b[1]), float(b[2])}, w, h);
  const glm::vec2 middle = project(
      view, {float(0.5 * (a[0] + b[0])), float(0.5 * (a[1] + b[1])), float(0.5 * (a[2] + b[2]))}, w,
      h);
  for (int mode = 1; mode <= 6; ++mode) {
    SCOPED_TRACE(mode);
    view.mode = static_cast<DisplayMode>(mode);
    const std::vector<std::uint8_t> img = render(solver, view, w, h);
    const Pixel v = at(img, w, int(free_vertex.x), int(free_vertex.y));
    EXPECT_GE(std::min({v.r, v.g, v.b}), 200) << v.r << " " << v.g << " " << v.b;
    // The spring is a light line: its middle is brighter by 40/255 or more than the background
    // five pixels either side (a one-pixel line, so the brightest of the three nearest columns).
    const int x = int(middle.x), y = int(middle.y);
    int line = 0;
    for (int dx = -1; dx <= 1; ++dx) line = std::max(line, at(img, w, x + dx, y).g);
    EXPECT_GE(line, at(img, w, x - 5, y).g + 40) << "no spring at the spring's middle";
    EXPECT_GE(line, at(img, w, x + 5, y).g + 40) << "no spring at the spring's middle";
  }
}

TEST_F(RenderTest, BrokenShaderNamesFileLineAndDriverLog) {
  try {
    vis::link_program({{GL_FRAGMENT_SHADER, "broken.frag",
                        "#version 450 core\nout vec4 c;\nvoid main() {\n  c = vec4(nope);\n}\n"}});
    FAIL() << "a broken shader compiled";
  } catch (const vis::ShaderError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("shaders/broken.frag:4"), std::string::npos) << what;
    EXPECT_NE(what.find("nope"), std::string::npos) << what;  // the driver's own words
  }
  // After an #include, lines still count in the including file, and errors inside the included
  // file name it.
  try {
    vis::link_program({{GL_FRAGMENT_SHADER, "uses_frame.frag",
                        "#version 450 core\n#include \"frame.glsl\"\nout vec4 c;\n"
                        "void main() { c = vec4(missing_name); }\n"}});
    FAIL() << "a broken shader compiled";
  } catch (const vis::ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("shaders/uses_frame.frag:4"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace clothlab
