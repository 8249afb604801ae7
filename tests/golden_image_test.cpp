// Golden images of display modes 1, 2 and 3 (and 2 and 3 on the transform-feedback backend) and
// of the force and normal arrows (320 x 240) of a
// fixed scene after a fixed number of steps, rendered headless (EGL; Mesa llvmpipe on CI) and
// compared with tests/golden/modeK.png. Tolerance: at most 0.5 % of the pixels may differ by more
// than 8/255 in any channel, and the mean absolute difference over all channels must stay below
// 1/255. On failure the actual image and a difference image (|actual - golden| x 8) are written
// next to the test's output. Regenerate on purpose with scripts/update-golden
// (CLOTHLAB_UPDATE_GOLDEN=1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "factory/solver_factory.hpp"
#include "image_compare.hpp"
#include "render_frame.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/textures/image.hpp"

namespace clothlab {
namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 320, kHeight = 240;

// A 1.2 m sheet pinned at its top corners, 0.3 s after release: folds, stretch near the pins.
Scene golden_scene() {
  Scene s = testing::sheet(24, 1.2, 0.3, 600.0, IntegratorKind::symplectic_euler, 5e-4);
  s.cloths[0].origin = {-0.6, 1.6, 0.0};
  s.cloths[0].pins = {{0, 0}, {23, 0}};
  s.springs.damping = 0.01;
  s.forces.wind = {true, {0.0, 0.0, 1.5}, 0.0, 0, 1.0, 1.0};
  return s;
}

using testing::compare;
using testing::Comparison;

class GoldenImage : public ::testing::TestWithParam<int> {
 protected:
  static void SetUpTestSuite() {
    renderer_ = std::make_unique<vis::HeadlessRenderer>(kWidth, kHeight);
    solver_ = testing::solver<float>(golden_scene());
    ASSERT_TRUE(solver_->step(600).ok());
    renderer_->set_cloth(*solver_);
    // The pole from the pins and a sphere beside the cloth: casters and receivers besides it.
    RenderSpec spec;
    MeshSpec sphere;
    sphere.center = {0.9, 0.35, 0.5};
    sphere.radius = 0.3;
    sphere.color = {0.3, 0.5, 0.8};
    spec.meshes = {sphere};
    renderer_->set_scene(spec, *solver_);
  }
  static void TearDownTestSuite() {
    solver_.reset();
    renderer_.reset();
  }
  static std::unique_ptr<vis::HeadlessRenderer> renderer_;
  static std::unique_ptr<Solver> solver_;
};
std::unique_ptr<vis::HeadlessRenderer> GoldenImage::renderer_;
std::unique_ptr<Solver> GoldenImage::solver_;

// The reference look: the stored goldens are render.quality full (fast has its own below).
vis::ViewSettings full_view(const Solver& solver) {
  vis::ViewSettings view = vis::default_view(solver);
  view.quality = RenderQuality::full;
  return view;
}

// Renders `view` and compares it with tests/golden/NAME.png (or rewrites it on request);
// returns the rendered image.
Image check_golden(vis::HeadlessRenderer& renderer, Solver& solver, const vis::ViewSettings& view,
                   const std::string& name) {
  Image actual(kWidth, kHeight);
  actual.rgba = test::render_frame(renderer, solver, view);
  const fs::path golden_path = fs::path(CLOTHLAB_SOURCE_DIR) / "tests" / "golden" / (name + ".png");
  if (const char* update = std::getenv("CLOTHLAB_UPDATE_GOLDEN"); update && *update == '1') {
    write_png(actual, golden_path.string(), PngCompression::small);  // kept in the repository
    std::printf("regenerated %s\n", golden_path.c_str());
    return actual;
  }
  EXPECT_TRUE(fs::exists(golden_path)) << golden_path << " is missing: run scripts/update-golden";
  if (!fs::exists(golden_path)) return actual;
  const Image golden = read_png(golden_path.string());
  EXPECT_EQ(golden.width, kWidth);
  EXPECT_EQ(golden.height, kHeight);
  if (golden.width != kWidth || golden.height != kHeight) return actual;
  Image diff;
  const Comparison c = compare(actual, golden, &diff);
  const bool ok = c.fraction_over <= 0.005 && c.mean_abs < 1.0;
  if (!ok) {
    const fs::path out = fs::current_path() / "golden_out";
    fs::create_directories(out);
    write_png(actual, (out / (name + "_actual.png")).string());
    write_png(diff, (out / (name + "_diff.png")).string());
    ADD_FAILURE() << name << ": " << 100.0 * c.fraction_over
                  << " % of pixels differ by more than 8/255 (limit 0.5 %), mean absolute "
                  << "difference " << c.mean_abs << "/255 (limit 1/255); see " << out;
  }
  return actual;
}

TEST_P(GoldenImage, MatchesTheStoredImage) {
  const int mode = GetParam();
  vis::ViewSettings view = full_view(*solver_);
  view.mode = static_cast<vis::DisplayMode>(mode);
  check_golden(*renderer_, *solver_, view, "mode" + std::to_string(mode));
}

// Shadow filters (mode 3) and the light's depth map (key 7) on the same scene.
TEST_F(GoldenImage, ShadowFilters) {
  for (ShadowFilter f : {ShadowFilter::none, ShadowFilter::pcf, ShadowFilter::pcss}) {
    vis::ViewSettings view = full_view(*solver_);
    view.shadows = f;
    check_golden(*renderer_, *solver_, view, std::string("shadows_") + to_string(f));
  }
}

TEST_F(GoldenImage, ClothBrdfMode4) {
  vis::ViewSettings view = full_view(*solver_);
  view.mode = vis::DisplayMode::cloth_brdf;
  check_golden(*renderer_, *solver_, view, "mode4");
}

// Mode 4's terms where they show: gold threads add their colour (green rises on the red cloth
// where silver or none would not add it), and the sheen brightens the cloth seen at grazing
// angles more than where it faces the camera (the rim over centre ratio rises).
TEST_F(GoldenImage, ClothBrdfThreadsAndSheen) {
  vis::ViewSettings view = full_view(*solver_);
  view.mode = vis::DisplayMode::cloth_brdf;
  view.shadows = ShadowFilter::none;
  auto mean = [&](const vis::ViewSettings& v, int channel, int x0, int x1, int y0, int y1) {
    const std::vector<std::uint8_t> img = test::render_frame(*renderer_, *solver_, v);
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) sum += img[4 * (std::size_t(y) * kWidth + x) + channel];
    return sum / ((x1 - x0) * (y1 - y0));
  };
  // The cloth's middle (it fills the centre of the default view).
  const int x0 = kWidth / 2 - 30, x1 = kWidth / 2 + 30, y0 = kHeight / 2 - 30,
            y1 = kHeight / 2 + 30;
  view.look.threads = ThreadMetal::none;
  const double plain_green = mean(view, 1, x0, x1, y0, y1);
  view.look.threads = ThreadMetal::gold;
  view.look.thread_fraction = 0.5;
  const double gold_green = mean(view, 1, x0, x1, y0, y1);
  EXPECT_GT(gold_green, plain_green + 3.0) << plain_green << " -> " << gold_green;
  // Sheen: seen almost edge-on (yaw 80 degrees) the cloth brightens more than head-on.
  view.look.threads = ThreadMetal::none;
  auto brightness = [&](float sheen, float yaw) {
    vis::ViewSettings v = view;
    v.look.sheen = sheen;
    v.camera.yaw_deg = yaw;
    return mean(v, 0, x0 + 20, x1 - 20, y0, y1);
  };
  const double gain_grazing = brightness(1.0f, 78.0f) / brightness(0.0f, 78.0f);
  const double gain_facing = brightness(1.0f, 0.0f) / brightness(0.0f, 0.0f);
  EXPECT_GT(gain_grazing, gain_facing)
      << "sheen gain " << gain_facing << " facing, " << gain_grazing << " grazing";
}

TEST_F(GoldenImage, TranslucentMode5) {
  vis::ViewSettings view = full_view(*solver_);
  view.mode = vis::DisplayMode::translucent;
  view.camera.yaw_deg = 200.0f;  // from behind: the cloth glows against the light
  check_golden(*renderer_, *solver_, view, "mode5");
}

TEST_F(GoldenImage, WeaveMode6) {
  vis::ViewSettings view = full_view(*solver_);
  view.mode = vis::DisplayMode::weave;
  check_golden(*renderer_, *solver_, view, "mode6");
}

// Normal mapping adds only the relief: with a flat map (bump 0) and no subsurface diffusion (a
// zero-width profile) mode 6 is mode 3 (every pixel
// within 2/255: the mapped normal of a flat map is the interpolated normal itself, so the
// tangent frame cancels), and with the relief on, the cloth's pixels change.
TEST_F(GoldenImage, FlatWeaveMapIsMode3) {
  vis::ViewSettings view = full_view(*solver_);
  view.mode = vis::DisplayMode::lambert;
  const std::vector<std::uint8_t> lambert = test::render_frame(*renderer_, *solver_, view);
  view.mode = vis::DisplayMode::weave;
  view.weave_coarsening = 1.0f;  // the weave at mode 3's scale
  view.look.bump = 0.0;
  view.look.subsurface = 0.0;  // a zero-width diffusion profile: plain Lambert
  const std::vector<std::uint8_t> flat = test::render_frame(*renderer_, *solver_, view);
  int worst = 0;
  for (std::size_t i = 0; i < flat.size(); ++i)
    worst = std::max(worst, std::abs(int(flat[i]) - int(lambert[i])));
  EXPECT_LE(worst, 2);
  view.look.bump = 1.0;
  const std::vector<std::uint8_t> bumpy = test::render_frame(*renderer_, *solver_, view);
  long changed = 0;
  for (std::size_t i = 0; i < bumpy.size(); ++i)
    changed += std::abs(int(bumpy[i]) - int(lambert[i])) > 4;
  EXPECT_GT(changed, 500);  // at 320 x 240 the weave is fine and partly filtered away
}

// The glint lights are specular only, for the metal threads: where there is no metal (threads
// "none") switching them changes no pixel; with gold threads they add highlights.
TEST_F(GoldenImage, GlintLightsTouchOnlyTheMetal) {
  vis::ViewSettings view = full_view(*solver_);
  view.mode = vis::DisplayMode::cloth_brdf;
  auto changed = [&](ThreadMetal threads) {
    view.look.threads = threads;
    view.look.glints = false;
    const std::vector<std::uint8_t> off = test::render_frame(*renderer_, *solver_, view);
    view.look.glints = true;
    const std::vector<std::uint8_t> on = test::render_frame(*renderer_, *solver_, view);
    long n = 0;
    for (std::size_t i = 0; i < on.size(); ++i) n += on[i] != off[i];
    return n;
  };
  EXPECT_EQ(changed(ThreadMetal::none), 0);
  EXPECT_GT(changed(ThreadMetal::gold), 200);
}

TEST_F(GoldenImage, LightDepthView) {
  vis::ViewSettings view = full_view(*solver_);
  view.mode = vis::DisplayMode::light_depth;
  check_golden(*renderer_, *solver_, view, "mode7");
}

// Force arrows (springs only, so every vertex has one, linear scale, magma) over mode 3, and normal
// arrows over the cloth coloured by height: the arrow glyphs, their density, lengths and colours.
TEST_F(GoldenImage, ForceArrows) {
  vis::ViewSettings view = full_view(*solver_);
  view.arrows.force = true;
  view.arrows.stride = 3;
  // Linear lengths: a log scale magnifies the last bits of small forces, which differ between
  // optimised and debug builds.
  view.arrows.scale = vis::ArrowScale::linear;
  view.force_source = ForceSource::springs;
  view.color.map = vis::ColorMap::magma;
  // A fixed range, about this frame's largest free |F|: the automatic top, a quantile, makes the
  // arrows twice as long, and that magnified the last bits in which the sanitizer build differs
  // (0.8 % of the pixels off by more than 8/255 there).
  view.color.range = vis::RangeMode::fixed;
  view.color.fixed = {0.0, 0.025};
  check_golden(*renderer_, *solver_, view, "arrows_force");
}

TEST_F(GoldenImage, NormalArrowsOverHeight) {
  vis::ViewSettings view = full_view(*solver_);
  view.camera.yaw_deg = 230.0f;  // from behind and the side: the normals point this way
  view.arrows.normals = true;
  view.arrows.stride = 2;
  view.color.field = vis::ScalarField::height;
  view.color.map = vis::ColorMap::viridis;
  check_golden(*renderer_, *solver_, view, "arrows_normals");
}

// The transform-feedback backend (solver.backend = "transform_feedback"): the same sheet stepped
// by the vertex shader and drawn from its captured buffer, each triangle shaded with the geometry
// shader's flat normal (mode 2's colours, mode 3's light). Same tolerance as the others.
TEST_F(GoldenImage, TransformFeedbackModes2And3) {
  Scene scene = golden_scene();
  scene.solver.backend = Backend::transform_feedback;
  std::string note;
  const std::unique_ptr<Solver> tf = make_backend_solver(scene, note);
  ASSERT_EQ(note, "");
  ASSERT_STREQ(backend_name(*tf), "GPU transform feedback");
  ASSERT_TRUE(tf->step(600).ok());
  renderer_->set_cloth(*tf);
  for (int mode : {2, 3}) {
    vis::ViewSettings view = full_view(*tf);
    view.mode = static_cast<vis::DisplayMode>(mode);
    check_golden(*renderer_, *tf, view, "tf_mode" + std::to_string(mode));
  }
  renderer_->set_cloth(*solver_);
}

INSTANTIATE_TEST_SUITE_P(Modes, GoldenImage, ::testing::Values(1, 2, 3),
                         [](const auto& param_info) {
                           return "mode" + std::to_string(param_info.param);
                         });

}  // namespace
}  // namespace clothlab

namespace clothlab {
namespace {

// The views of the full goldens above that fast must keep, by golden name.
struct GoldenView {
  std::string name;
  std::function<void(vis::ViewSettings&)> edit;
};

std::vector<GoldenView> golden_views() {
  std::vector<GoldenView> views;
  for (int mode = 1; mode <= 7; ++mode)
    views.push_back({"mode" + std::to_string(mode), [mode](vis::ViewSettings& v) {
                       v.mode = static_cast<vis::DisplayMode>(mode);
                       if (mode == 5) v.camera.yaw_deg = 200.0f;  // as TranslucentMode5
                     }});
  for (ShadowFilter f : {ShadowFilter::none, ShadowFilter::pcf, ShadowFilter::pcss})
    views.push_back(
        {std::string("shadows_") + to_string(f), [f](vis::ViewSettings& v) { v.shadows = f; }});
  return views;
}

// Mean |fast - full| per channel (1/255) a fast image may be from its full twin: the same
// colours, shadows, relief and translucency; what differs is the geometry's edges (no MSAA) and
// the shadows' penumbrae (a smaller kernel on a coarser map). Measured on these views: at most
// about 1/255 (printed below).
constexpr double kFastMeanLimit = 3.0;

// render.quality fast (docs/rendering.md, "Render quality") has goldens of its own
// (tests/golden/fast_*.png, the same tolerances) and stays within kFastMeanLimit of the full
// golden of the same view.
TEST_F(GoldenImage, FastKeepsTheLookOfFull) {
  for (const GoldenView& g : golden_views()) {
    SCOPED_TRACE(g.name);
    vis::ViewSettings view = full_view(*solver_);
    g.edit(view);
    view.quality = RenderQuality::fast;
    const Image fast = check_golden(*renderer_, *solver_, view, "fast_" + g.name);
    const fs::path full_path =
        fs::path(CLOTHLAB_SOURCE_DIR) / "tests" / "golden" / (g.name + ".png");
    const Image full = read_png(full_path.string());
    const Comparison c = compare(fast, full);
    std::printf("[ fast vs full ] %s: mean %.3f/255, %.2f %% of pixels off by more than 8/255\n",
                g.name.c_str(), c.mean_abs, 100.0 * c.fraction_over);
    EXPECT_LE(c.mean_abs, kFastMeanLimit) << g.name;
  }
}

}  // namespace
}  // namespace clothlab
