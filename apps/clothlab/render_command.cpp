// `clothlab render`: the scene headless through EGL, one PNG per frame with --out and an MP4
// with --video (its frames go straight to ffmpeg), with a progress bar and a summary that splits
// the frame time into simulation, rendering and writing.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "apps/clothlab/commands.hpp"
#include "apps/clothlab/progress_bar.hpp"
#include "apps/clothlab/video_pipe.hpp"
#include "factory/solver_factory.hpp"
#include "gl/gl_error.hpp"
#include "music/music_track.hpp"
#include "sim/cloth/scene_copies.hpp"
#include "sim/fields/frame_fields.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/solver.hpp"
#include "vis/render/cloth_detail.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/render/scalar_field.hpp"
#include "vis/textures/image.hpp"

namespace clothlab::app {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string frame_path(const std::string& dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", frame);
  return (std::filesystem::path(dir) / name).string();
}

// One JSON line on stdout: the interpolated value under the pixel and the nearest vertex's
// exact nodal value (null where the pixel misses the cloth), SI units, %.9g (float precision).
void print_probe(Solver& solver, vis::HeadlessRenderer& renderer, const vis::ViewSettings& view,
                 const RenderArgs& args) {
  const vis::Field field = args.field == "velocity"   ? vis::Field::velocity
                           : args.field == "position" ? vis::Field::position
                                                      : vis::Field::force;
  const auto [px, py] = *args.probe;
  FieldSnapshot snapshot;
  const FrameFields& fields = snapshot.take(solver, renderer.request(view, true));
  const std::optional<vis::ProbeSample> s = renderer.probe(solver, fields, view, px, py);
  std::printf("{\"field\": \"%s\", \"pixel\": [%d, %d], ", args.field.c_str(), px, py);
  if (!s) {
    std::printf(
        "\"value\": null, \"magnitude\": null, \"vertex\": null, \"vertex_value\": null}\n");
    return;
  }
  const glm::vec3 v = s->value(field);
  // The nodal value in the solver's precision (the snapshot holds floats).
  if (field == vis::Field::force) solver.update_force_field(ForceSource::total);
  const Vec3d n = field == vis::Field::force      ? solver.force(s->vertex)
                  : field == vis::Field::velocity ? solver.velocity(s->vertex)
                                                  : solver.position(s->vertex);
  const VertexRef ref = solver.vertex_ref(s->vertex);
  const double magnitude = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
  std::printf("\"value\": [%.9g, %.9g, %.9g], \"magnitude\": %.9g, ", v.x, v.y, v.z, magnitude);
  if (solver.cloths().size() > 1) std::printf("\"cloth\": %d, ", ref.cloth);
  std::printf("\"vertex\": [%d, %d], \"vertex_value\": [%.9g, %.9g, %.9g]}\n", ref.i, ref.j, n[0],
              n[1], n[2]);
}

// One line on what the last frame's scientific views showed: the colour range with its unit
// and the arrows (nothing when no view was on).
void print_views(const vis::Diagnostics& d, const vis::ViewSettings& view) {
  std::string line;
  char part[160];
  if (const auto& r = d.color_range()) {
    const std::string unit(vis::scalar_field_unit(view.color.field));
    std::snprintf(part, sizeof part, "colour by %s [%.6g, %.6g]%s%s (%s)",
                  std::string(vis::scalar_field_name(view.color.field)).c_str(), r->min, r->max,
                  unit.empty() ? "" : " ", unit.c_str(),
                  std::string(vis::colormap_name(view.color.map)).c_str());
    line += part;
  }
  if (const auto& r = d.force_range()) {
    std::snprintf(
        part, sizeof part, "%s%zu force arrows (%s%s, |F| %.6g..%.6g N)", line.empty() ? "" : "; ",
        d.force_arrows().size(), std::string(force_source_name(d.shown_force_source())).c_str(),
        d.showing_springs_at_rest() ? " where the total is near zero" : "", r->min, r->max);
    line += part;
  }
  if (!d.normal_arrows().empty()) {
    std::snprintf(part, sizeof part, "%s%zu normal arrows", line.empty() ? "" : "; ",
                  d.normal_arrows().size());
    line += part;
  }
  if (!line.empty()) std::printf("views: %s\n", line.c_str());
}

// Seconds per part of all frames, and the steps taken; `diverged` when the run stopped.
struct FrameTimes {
  double simulate = 0.0, draw = 0.0, output = 0.0;
  long steps = 0;
  bool diverged = false;
};

// Frame 0 shows the initial state; each later frame 1 / fps of simulated time more. Every frame
// goes to a PNG and, with --video, to the video.
FrameTimes render_frames(const RenderArgs& args, Solver& solver, vis::HeadlessRenderer& renderer,
                         const vis::ViewSettings& view, VideoPipe* video) {
  FrameTimes t;
  ProgressBar progress(args.frames, !args.quiet);
  Image image(args.width, args.height);
  FieldSnapshot snapshot;  // one per frame, its buffers reused
  for (int frame = 0; frame < args.frames; ++frame) {
    auto t0 = Clock::now();
    if (frame > 0) {
      const AdvanceResult r = solver.advance(1.0 / args.fps);
      t.steps += r.steps;
      if (r.divergence) {
        std::fprintf(stderr, "\nclothlab render: %s (frame %d)\n", r.divergence->message().c_str(),
                     frame);
        t.diverged = true;
        return t;
      }
    }
    t.simulate += seconds_since(t0);
    t0 = Clock::now();
    image.rgba = renderer.render(solver, snapshot.take(solver, renderer.request(view)), view);
    t.draw += seconds_since(t0);
    t0 = Clock::now();
    if (!args.out.empty()) write_png(image, frame_path(args.out, frame));
    if (video) video->write(image.rgba);
    t.output += seconds_since(t0);
    progress.update(frame + 1);
  }
  return t;
}

// --music-out, and the video (with the scene's music from frame 0, cut to the frames' length).
std::unique_ptr<VideoPipe> open_outputs(const RenderArgs& args, const Scene& scene,
                                        const MusicTrack*& music) {
  if (!args.music_out.empty()) {
    if (!scene.music || !scene.music->track)
      throw std::runtime_error("--music-out: the scene has no [music]");
    write_wav(args.music_out, scene.music->track->clip);
  }
  music =
      scene.music && scene.music->track && !args.video.empty() ? scene.music->track.get() : nullptr;
  if (args.video.empty()) return nullptr;
  return std::make_unique<VideoPipe>(
      args.video, args.width, args.height, args.fps,
      VideoMusic{music ? &music->clip : nullptr, args.frames / args.fps});
}

void print_render_summary(const RenderArgs& args, const FrameTimes& t, const Solver& solver,
                          const vis::HeadlessRenderer& renderer, const vis::ViewSettings& view,
                          const MusicTrack* music) {
  const double frames = args.frames;
  const RenderQuality quality = renderer.renderer().quality(view);
  std::string chosen = view.quality == RenderQuality::automatic
                           ? std::string(to_string(quality)) + " (auto)"
                           : std::string(to_string(quality));
  // Fast quality's coarser drawing of a large grid cloth (vis/render/cloth_detail.hpp).
  const std::string detail = vis::detail_note(renderer.renderer().cloth_stride());
  if (!detail.empty()) chosen += ", cloth drawn at " + detail;
  const std::string written =
      args.out + (args.out.empty() || args.video.empty() ? "" : " and ") + args.video;
  std::printf(
      "render: %d frames of %dx%d (mode %d, quality %s) on %s: %.2f ms/frame simulation (%.1f "
      "steps of %g s on the %s), %.2f ms/frame rendering, %.2f ms/frame writing; %s%s%s\n",
      args.frames, args.width, args.height, static_cast<int>(view.mode), chosen.c_str(),
      renderer.gl_renderer().c_str(), 1e3 * t.simulate / frames,
      frames > 1 ? double(t.steps) / (frames - 1) : 0.0, solver.dt(), backend_name(solver),
      1e3 * t.draw / frames, 1e3 * t.output / frames, written.c_str(), music ? " with music: " : "",
      music ? music->source.c_str() : "");
}

int render_scene(const RenderArgs& args, Scene& scene) {
  vis::HeadlessRenderer renderer(args.width, args.height);
  // After the context: solver.backend = "gpu" steps the cloth in it.
  if (args.copies > 1) {
    if (const std::string why = copies_unsupported_reason(scene); !why.empty())
      throw std::runtime_error("--copies: " + why);
    scene = with_copies(scene, args.copies, copy_spacing(scene));
  }
  std::string backend_note;
  const auto solver = make_backend_solver(scene, backend_note);
  if (!backend_note.empty()) std::printf("clothlab render: %s\n", backend_note.c_str());
  renderer.set_cloth(*solver);
  renderer.set_scene(scene.render, *solver, scene.colliders);
  vis::ViewSettings view = vis::scene_view(scene, *solver);
  if (args.mode != 0) view.mode = static_cast<vis::DisplayMode>(args.mode);
  static_cast<vis::ScientificViews&>(view) = args.views;  // --color-by, --arrows, ...
  const MusicTrack* music = nullptr;
  const std::unique_ptr<VideoPipe> video = open_outputs(args, scene, music);
  const FrameTimes t = render_frames(args, *solver, renderer, view, video.get());
  if (t.diverged) return 1;
  if (video) video->finish();
  if (args.probe) print_probe(*solver, renderer, view, args);
  if (args.quiet) return 0;
  print_render_summary(args, t, *solver, renderer, view, music);
  print_views(renderer.diagnostics(), view);
  return 0;
}

}  // namespace

int run_render(const RenderArgs& args) {
  std::optional<Scene> loaded = load_scene_to_run("render", args.scene, args.overrides, args.quiet);
  if (!loaded) return kBadInput;
  std::error_code ec;
  if (!args.out.empty()) std::filesystem::create_directories(args.out, ec);
  if (!args.out.empty() && (ec || !std::filesystem::is_directory(args.out))) {
    std::fprintf(stderr, "clothlab render: --out: cannot create directory '%s'\n",
                 args.out.c_str());
    return 2;
  }
  try {
    return render_scene(args, *loaded);
  } catch (const vis::GlUnavailable& e) {
    std::fprintf(stderr, "clothlab render: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clothlab render: %s\n", e.what());
    return 1;
  }
}

}  // namespace clothlab::app
