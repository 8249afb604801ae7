// `clothlab bench --suite views`: what the scientific views (colour by a scalar, force and normal
// arrows, the probe's field pass) cost per displayed frame, headless, as ratios to a frame with
// every view off; and the check that turning everything off again brings the frame back to the
// reference with no diagnostic state held. One frame = the solver advanced by 1/60 s (the steps
// real time takes) + HeadlessRenderer::render (upload, diagnostics, draw, colour bars, MSAA
// resolve and pixel readback) + for the probe variants one probe at the image centre. The same
// frames are also timed without the readback: HeadlessRenderer::draw, finished with glFinish
// instead of resolve + read. Variants are measured round-robin, several
// rounds, and each ratio is the median over rounds of the ratio within a round (features_suite).
#include <cmath>
#include <functional>
#include <memory>
#include <ostream>
#include <stdexcept>

#include "bench/suites/suites.hpp"
#include "gl/draw_state.hpp"
#include "load/scene_load.hpp"
#include "sim/fields/frame_fields.hpp"
#include "sim/scene/validate.hpp"
#include "sim/solver.hpp"
#include "vis/render/headless_renderer.hpp"

namespace clothlab::bench {

namespace {

struct ViewVariant {
  std::string name;
  std::function<void(vis::ViewSettings&)> edit;
  bool probe = false;  // one probe at the image centre after the render
};

// Per variant, one value per round.
struct ViewSeries {
  std::vector<double> simulate, render, draw;                 // s per frame
  std::vector<double> total_ratio, render_ratio, draw_ratio;  // to the round's "all off"
  bool active = false;  // diagnostics().active() after the variant's last frame
  int probe_hits = 0, probes = 0;
};

constexpr double kAgainLimit = 0.05;  // "all off again" within 5 % of "all off"

// The default scene on `threads` threads at res x res, its top corners still pinned, without
// triangle contact: the suite measures the views, and the hanging sheet never touches itself
// (contact would triple the 128 x 128 sheet's simulation, docs/contact.md section 7).
Scene default_scene(int res, int threads) {
  Scene scene = read_scene_file(CLOTHLAB_DEFAULT_SCENE);
  scene.solver.threads = threads;
  scene.solver.cloth_contact = false;
  if (res != 32) {
    scene.cloths[0].resolution = {res, res};
    scene.cloths[0].pins = {{0, 0}, {res - 1, 0}};
  }
  validate_scene(scene);
  return scene;
}

std::vector<ViewVariant> view_variants() {
  return {
      {"all off", [](vis::ViewSettings&) {}},
      {"colour by |force|", [](vis::ViewSettings& v) { v.color.field = vis::ScalarField::force; }},
      {"colour by strain", [](vis::ViewSettings& v) { v.color.field = vis::ScalarField::strain; }},
      {"colour by contact gap",
       [](vis::ViewSettings& v) { v.color.field = vis::ScalarField::contact; }},
      {"force arrows", [](vis::ViewSettings& v) { v.arrows.force = true; }},
      {"normal arrows", [](vis::ViewSettings& v) { v.arrows.normals = true; }},
      {"force + normal arrows",
       [](vis::ViewSettings& v) {
         v.arrows.force = true;
         v.arrows.normals = true;
       }},
      {"probe (field pass + 1 pixel)", [](vis::ViewSettings&) {}, true},
      {"everything on (|force| colour + both arrows + probe)",
       [](vis::ViewSettings& v) {
         v.color.field = vis::ScalarField::force;
         v.arrows.force = true;
         v.arrows.normals = true;
       },
       true},
      // Right after "everything on" in every round, on the same renderer: the "removes" claim.
      {"all off again (after everything on)", [](vis::ViewSettings&) {}},
  };
}

Table views_table(int width, int height, const std::string& gl, int threads, int frames,
                  int rounds) {
  Table table;
  table.title =
      "Scientific view costs per frame: scenes/default.toml, headless " + std::to_string(width) +
      "x" + std::to_string(height) + " (4x MSAA) on " + gl + ", " + std::to_string(threads) +
      " solver thread(s); frame = advance 1/60 s + render (+ probe); render includes "
      "colour bars and the probe; w/o readback = same draw, glFinish instead of resolve + read; "
      "mean of " +
      std::to_string(frames) + " frames per round, median of " + std::to_string(rounds) + " rounds";
  table.columns = {"scene",
                   "variant",
                   "simulate (ms/frame)",
                   "render (ms/frame)",
                   "render w/o readback (ms/frame)",
                   "total (ms/frame)",
                   "total / all off",
                   "render / all off",
                   "w/o readback / all off",
                   "diagnostics active",
                   "verdict"};
  return table;
}

// One variant's frames of one round: `frames` timed frames (after one untimed, which builds or
// drops the views' state) through render() and as many through draw() + glFinish; the mean
// seconds per frame of simulation, render and draw.
struct ViewTiming {
  double simulate = 0.0, render = 0.0, draw = 0.0;
};

ViewTiming time_view_variant(vis::HeadlessRenderer& renderer, Solver& solver,
                             const vis::ViewSettings& view, bool probing, int frames,
                             ViewSeries& s) {
  const int width = renderer.width(), height = renderer.height();
  auto advance = [&] {
    const AdvanceResult r = solver.advance(1.0 / 60.0);
    if (r.divergence) throw std::runtime_error("views: " + r.divergence->message());
  };
  FieldSnapshot snapshot;  // one per frame, as the window takes it
  auto probe = [&] {
    if (!probing) return;
    const auto sample = renderer.probe(solver, snapshot.fields(), view, width / 2, height / 2);
    ++s.probes;
    if (sample) ++s.probe_hits;
  };
  ViewTiming t;
  for (int path = 0; path < 2; ++path) {
    for (int f = 0; f <= frames; ++f) {
      Stopwatch sim_clock;
      advance();
      const double t_sim = sim_clock.seconds();
      Stopwatch clock;
      const FrameFields& fields = snapshot.take(solver, renderer.request(view, probing));
      if (path == 0) {
        (void)renderer.render(solver, fields, view);
      } else {
        renderer.draw(solver, fields, view);  // render() without the resolve and readback
        vis::finish_gpu_work();               // count the GPU's work
      }
      probe();
      if (f == 0) continue;
      t.simulate += t_sim;
      (path == 0 ? t.render : t.draw) += clock.seconds();
    }
  }
  t.simulate /= 2.0 * frames;
  t.render /= frames;
  t.draw /= frames;
  return t;
}

// The rows of one scene: medians over rounds, and the verdicts.
void add_rows(Table& table, const std::string& scene_name, const std::vector<ViewVariant>& variants,
              const std::vector<ViewSeries>& series) {
  for (std::size_t v = 0; v < variants.size(); ++v) {
    const ViewSeries& s = series[v];
    const double sim = median(s.simulate), ren = median(s.render);
    const double tr = median(s.total_ratio);
    std::string verdict = "-";
    if (v == 0) verdict = "reference";
    if (variants[v].probe)
      verdict =
          "probe hit the cloth " + std::to_string(s.probe_hits) + "/" + std::to_string(s.probes);
    if (v + 1 == variants.size())
      verdict = (!s.active && std::abs(tr - 1.0) <= kAgainLimit)
                    ? "ok: back to reference (within 5 %), no state held"
                    : "FAIL: " + pct(tr - 1.0) + (s.active ? ", state still held" : "");
    table.add({scene_name, variants[v].name, fixed(1e3 * sim, 2), fixed(1e3 * ren, 2),
               fixed(1e3 * median(s.draw), 2), fixed(1e3 * (sim + ren), 2), fixed(tr, 3),
               fixed(median(s.render_ratio), 3), fixed(median(s.draw_ratio), 3),
               s.active ? "yes" : "no", verdict});
  }
}

}  // namespace

std::vector<Table> views_suite(const SuiteOptions& o) {
  const int width = o.quick ? 320 : 1280, height = o.quick ? 240 : 720;
  const std::vector<int> resolutions = o.quick ? std::vector<int>{32} : std::vector<int>{32, 128};
  const int rounds = o.quick ? 2 : 5;
  const int frames = o.quick ? 2 : 3;  // timed frames per variant, round and path
  const std::vector<ViewVariant> variants = view_variants();
  vis::HeadlessRenderer renderer(width, height);
  const std::string gl = renderer.gl_renderer();
  if (o.log) *o.log << "views: GL renderer " << gl << "\n";
  Table table = views_table(width, height, gl, o.threads, frames, rounds);
  table.note = quick_note(o.quick,
                          "the 128x128 cloth (32x32 only), 320x240 instead of "
                          "1280x720, 2 rounds of 2 frames instead of 5 of 3");
  for (const int res : resolutions) {
    auto solver = make_solver(default_scene(res, o.threads));
    const long steps_per_frame = std::max(1L, std::lround(1.0 / 60.0 / solver->dt()));
    const vis::ViewSettings base = vis::default_view(*solver);
    renderer.set_cloth(*solver);
    std::vector<ViewSeries> series(variants.size());
    for (int round = 0; round < rounds; ++round) {
      ViewTiming ref;
      for (std::size_t v = 0; v < variants.size(); ++v) {
        vis::ViewSettings view = base;
        variants[v].edit(view);
        ViewSeries& s = series[v];
        const ViewTiming t =
            time_view_variant(renderer, *solver, view, variants[v].probe, frames, s);
        if (v == 0) ref = t;
        s.simulate.push_back(t.simulate);
        s.render.push_back(t.render);
        s.draw.push_back(t.draw);
        s.total_ratio.push_back((t.simulate + t.render) / (ref.simulate + ref.render));
        s.render_ratio.push_back(t.render / ref.render);
        s.draw_ratio.push_back(t.draw / ref.draw);
        s.active = renderer.diagnostics().active();
      }
      if (o.log)
        *o.log << "views: " << res << "x" << res << " round " << round + 1 << " of " << rounds
               << " done\n";
    }
    add_rows(table,
             std::to_string(res) + "x" + std::to_string(res) + " (" +
                 std::to_string(steps_per_frame) + " steps/frame)",
             variants, series);
  }
  return {table};
}

}  // namespace clothlab::bench
