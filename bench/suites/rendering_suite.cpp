// `clothlab bench --suite rendering`: what each display mode and shadow filter costs per
// headless frame, split by pass (gl/pass_timer.hpp): the shadow map, the diffusion passes,
// the scene (floor, scenery, cloth), the sky and the overlays (arrows, colour bars); and the
// default scene with every optional pass off against the usual mode 3. The scene is the default
// one with a sphere, a box and a torus knot beside the cloth, so shadows fall on objects too.
// Variants are measured round-robin, several rounds, median per variant (features_suite).
#include <algorithm>
#include <array>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "bench/suites/step_timing.hpp"
#include "bench/suites/suites.hpp"
#include "gl/draw_state.hpp"
#include "load/scene_load.hpp"
#include "sim/fields/frame_fields.hpp"
#include "sim/solver.hpp"
#include "vis/render/headless_renderer.hpp"

namespace clothlab::bench {
namespace {

struct RenderVariant {
  std::string name;
  std::function<void(vis::ViewSettings&)> edit;
};

MeshSpec mesh(MeshKind kind, Vec3d centre, double radius, Vec3d colour) {
  MeshSpec m;
  m.kind = kind;
  m.center = centre;
  m.radius = radius;
  m.half_extents = {radius, radius, radius};
  m.color = colour;
  return m;
}

std::vector<RenderVariant> render_variants() {
  auto mode = [](vis::DisplayMode m, ShadowFilter f) {
    return [m, f](vis::ViewSettings& v) {
      v.mode = m;
      v.shadows = f;
    };
  };
  return {
      {"mode 3, every optional pass off (no shadows, no sky)",
       [](vis::ViewSettings& v) {
         v.mode = vis::DisplayMode::lambert;
         v.shadows = ShadowFilter::none;
         v.sky = false;
       }},
      {"mode 1 springs, PCF", mode(vis::DisplayMode::springs, ShadowFilter::pcf)},
      {"mode 2 normals, PCF", mode(vis::DisplayMode::normals, ShadowFilter::pcf)},
      {"mode 3, sky, no shadows", mode(vis::DisplayMode::lambert, ShadowFilter::none)},
      {"mode 3, sky, PCF (the default)", mode(vis::DisplayMode::lambert, ShadowFilter::pcf)},
      {"mode 3, sky, PCSS", mode(vis::DisplayMode::lambert, ShadowFilter::pcss)},
      {"mode 4 cloth BRDF, PCF", mode(vis::DisplayMode::cloth_brdf, ShadowFilter::pcf)},
      {"mode 5 translucent, coloured PCF", mode(vis::DisplayMode::translucent, ShadowFilter::pcf)},
      {"mode 6 weave relief + subsurface, PCF", mode(vis::DisplayMode::weave, ShadowFilter::pcf)},
      {"mode 6 weave relief, no subsurface, PCF",
       [](vis::ViewSettings& v) {
         v.mode = vis::DisplayMode::weave;
         v.shadows = ShadowFilter::pcf;
         v.look.subsurface = 0.0;
       }},
      {"mode 7 light depth map", mode(vis::DisplayMode::light_depth, ShadowFilter::pcf)},
      {"mode 3, PCF, force arrows + colour bar",
       [](vis::ViewSettings& v) {
         v.shadows = ShadowFilter::pcf;
         v.arrows.force = true;
       }},
  };
}

// One variant's timings over the rounds: per pass, the passes' sum, and the whole frame (ms).
struct RenderSeries {
  std::vector<double> pass[vis::kPassCount], gpu, wall;
};

// One round of one variant: an untimed frame first (maps and textures a variant needs are built
// on its first frame), then `frames` frames as a user gets them (draw, resolve, read back) and
// the same frames again split into passes.
void time_variant(vis::HeadlessRenderer& renderer, Solver& solver, const vis::ViewSettings& view,
                  int frames, RenderSeries& series) {
  FieldSnapshot snapshot;
  renderer.draw(solver, snapshot.take(solver, renderer.request(view)), view);
  vis::finish_gpu_work();
  std::array<double, vis::kPassCount> sum{};
  double wall = 0.0;
  for (int f = 0; f < frames; ++f) {
    renderer.renderer().enable_pass_timing(false);
    Stopwatch clock;
    (void)renderer.render(solver, snapshot.take(solver, renderer.request(view)), view);
    wall += clock.seconds();
    renderer.renderer().enable_pass_timing(true);
    renderer.draw(solver, snapshot.take(solver, renderer.request(view)), view);
    const auto ms = renderer.renderer().pass_timer()->collect();
    for (std::size_t p = 0; p < vis::kPassCount; ++p) sum[p] += ms[p];
  }
  double gpu = 0.0;
  for (std::size_t p = 0; p < vis::kPassCount; ++p) {
    series.pass[p].push_back(sum[p] / frames);
    gpu += sum[p] / frames;
  }
  series.gpu.push_back(gpu);
  series.wall.push_back(1e3 * wall / frames);
}

Table rendering_table(const std::vector<RenderVariant>& variants,
                      const std::vector<RenderSeries>& series, const std::string& title) {
  Table table;
  table.title = title;
  table.columns = {"variant",           "shadow map (ms)", "diffusion (ms)",
                   "scene (ms)",        "sky (ms)",        "overlay (ms)",
                   "passes total (ms)", "frame wall (ms)", "frame / all off"};
  const double reference = median(series[0].wall);
  for (std::size_t k = 0; k < variants.size(); ++k) {
    const RenderSeries& s = series[k];
    std::vector<std::string> row = {variants[k].name};
    for (std::size_t p = 0; p < vis::kPassCount; ++p) row.push_back(fixed(median(s.pass[p]), 2));
    row.push_back(fixed(median(s.gpu), 2));
    row.push_back(fixed(median(s.wall), 2));
    row.push_back(fixed(median(s.wall) / reference, 3));
    table.add(row);
  }
  return table;
}

// Every variant at one render quality, round-robin over `rounds` rounds.
std::vector<RenderSeries> measure_quality(vis::HeadlessRenderer& renderer, Solver& solver,
                                          const vis::ViewSettings& base, RenderQuality quality,
                                          const std::vector<RenderVariant>& variants, int rounds,
                                          int frames, std::ostream* log) {
  std::vector<RenderSeries> series(variants.size());
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t k = 0; k < variants.size(); ++k) {
      vis::ViewSettings view = base;
      variants[k].edit(view);
      view.quality = quality;
      time_variant(renderer, solver, view, frames, series[k]);
    }
    if (log)
      *log << "rendering: " << to_string(quality) << " round " << round + 1 << " of " << rounds
           << " done\n";
  }
  return series;
}

}  // namespace

std::vector<Table> rendering_suite(const SuiteOptions& o) {
  const int width = o.quick ? 320 : 1280, height = o.quick ? 240 : 720;
  const int rounds = o.quick ? 1 : 5, frames = o.quick ? 1 : 3;
  Scene scene = read_scene_file(CLOTHLAB_DEFAULT_SCENE);
  scene.solver.threads = o.threads;
  scene.render.meshes = {mesh(MeshKind::sphere, {-1.4, 0.4, 0.8}, 0.4, {0.8, 0.3, 0.2}),
                         mesh(MeshKind::box, {1.5, 0.3, 0.6}, 0.3, {0.3, 0.5, 0.8}),
                         mesh(MeshKind::torus_knot, {0.0, 0.5, 1.4}, 0.45, {0.85, 0.75, 0.3})};
  auto solver = make_solver(scene);
  vis::HeadlessRenderer renderer(width, height);
  renderer.set_cloth(*solver);
  renderer.set_scene(scene.render, *solver);
  const vis::ViewSettings base = vis::scene_view(scene, *solver);
  const std::vector<RenderVariant> variants = render_variants();
  std::vector<Table> tables;
  for (RenderQuality quality : {RenderQuality::full, RenderQuality::fast}) {
    const std::vector<RenderSeries> series =
        measure_quality(renderer, *solver, base, quality, variants, rounds, frames, o.log);
    const std::string title =
        "Render cost per headless frame, quality " + std::string(to_string(quality)) + ": " +
        "scenes/default.toml + 3 meshes, " + std::to_string(width) + "x" + std::to_string(height) +
        " on " + renderer.gl_renderer() +
        "; pass times: wall clock between glFinish at each pass boundary; frame = draw + "
        "resolve + readback, timed separately without the boundaries; median of " +
        std::to_string(rounds) + " rounds of " + std::to_string(frames) + " frames";
    Table t = rendering_table(variants, series, title);
    if (quality == RenderQuality::fast) t.name = "fast";
    t.note = quick_note(o.quick,
                        "320x240 instead of 1280x720, 1 round of 1 frame instead of 5 "
                        "of 3");
    tables.push_back(std::move(t));
  }
  return tables;
}

}  // namespace clothlab::bench
