// clothlab: the command-line entry point. Only wires the command line to the subcommands.
#include <CLI/CLI.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "apps/clothlab/commands.hpp"
#include "apps/clothlab/output_path.hpp"
#include "apps/view/input.hpp"
#include "bench/suites/suites.hpp"
#include "sim/core/passive_openmp.hpp"
#include "sim/core/temp_files.hpp"
#include "sim/forces/force_source.hpp"
#include "sim/scene/scene_error.hpp"
#include "vis/colormap/colormap.hpp"
#include "vis/render/scalar_field.hpp"

namespace {

namespace vis = clothlab::vis;

void add_scene_options(CLI::App& cmd, std::string& scene, std::vector<std::string>& overrides,
                       bool scene_required = true) {
  auto* s = cmd.add_option("scene", scene, "scene file (TOML)");
  if (scene_required) s->required();
  cmd.add_option("--set", overrides, "override a scene value, key.path=value (repeatable)")
      ->take_last()
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

using namespace clothlab::app;

// `trace`: run a scene headless and write a CSV trace.
CLI::App* add_trace(CLI::App& app, TraceArgs& trace) {
  auto* trace_cmd = app.add_subcommand("trace", "run a scene headless and write a CSV trace");
  add_scene_options(*trace_cmd, trace.scene, trace.overrides);
  trace_cmd->add_option("--duration", trace.duration, "simulated seconds to run")
      ->required()
      ->check(CLI::Validator(
          [](std::string& s) {
            const double d = std::strtod(s.c_str(), nullptr);
            return std::isfinite(d) && d > 0.0 && d <= 1e6
                       ? std::string()
                       : std::string("must be a finite number in (0, 1e6] seconds");
          },
          "SECONDS"));
  trace_cmd->add_option("--out", trace.out, "CSV file to write")->required()->check(output_file());
  trace_cmd->add_flag("--quiet", trace.quiet,
                      "print only errors and warnings (no estimate, progress or summary)");

  return trace_cmd;
}

// The command line of `render` as parsed, before the size and the probe are checked.
struct RenderCli {
  RenderArgs args;
  std::string size = "1280x720";
  std::string probe;
  CLI::Option* probe_opt = nullptr;
};

// A number in [lo, hi], said as a sentence ("must be between 1 and 10000, got 0") where CLI11's
// own Range would say "Value 0 not in range 1.000000 to 10000.000000".
CLI::Validator between(double lo, double hi) {
  // Whole numbers in full (1000000, not 1e+06).
  auto number = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, x == std::floor(x) && std::fabs(x) < 1e15 ? "%.0f" : "%g", x);
    return std::string(text);
  };
  const std::string range = number(lo) + " and " + number(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) {
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        if (end != text.c_str() && *end == '\0' && x >= lo && x <= hi) return std::string();
        return "must be between " + range + ", got " + text;
      },
      number(lo) + " to " + number(hi));
}

// An option naming one of `all` by its name (`name`, the same function the rest of ClothLab
// prints it with): CLI11 checks the name and the value lands in `target`.
template <class E, std::size_t N, class NameFn>
CLI::Option* add_choice(CLI::App* cmd, const std::string& flag, E& target,
                        const std::array<E, N>& all, NameFn name, const std::string& help) {
  std::vector<std::string> names;
  for (E e : all) names.emplace_back(name(e));
  return cmd
      ->add_option_function<std::string>(
          flag,
          [&target, all, name](const std::string& v) {
            for (E e : all)
              if (name(e) == v) target = e;
          },
          help)
      ->check(CLI::IsMember(names));
}

// --range: auto, symmetric or MIN,MAX with MIN < MAX, into `color`; false when malformed.
bool read_range(const std::string& r, vis::ColorSettings& color) {
  if (r == "auto" || r == "symmetric") {
    color.range = r == "auto" ? vis::RangeMode::automatic : vis::RangeMode::symmetric;
    return true;
  }
  double lo = 0.0, hi = 0.0;
  char comma = 0, rest = 0;
  if (std::sscanf(r.c_str(), "%lf%c%lf%c", &lo, &comma, &hi, &rest) != 3 || comma != ',' ||
      !std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    return false;
  color.range = vis::RangeMode::fixed;
  color.fixed = {lo, hi};
  return true;
}

// `render`'s scientific views: colour maps, arrows, legends, into vis::ScientificViews.
void add_render_views(CLI::App* render_cmd, vis::ScientificViews& views) {
  add_choice(render_cmd, "--color-by", views.color.field, vis::kColourScalars,
             vis::scalar_field_name, "colour the cloth by a scalar (modes 2, 3)");
  add_choice(render_cmd, "--colormap", views.color.map, vis::kAllColorMaps, vis::colormap_name,
             "colour map for --color-by and arrows");
  render_cmd
      ->add_option_function<std::string>(
          "--range", [&views](const std::string& r) { read_range(r, views.color); },
          "colour range: auto (min..max), symmetric (-a..a) or MIN,MAX")
      ->check(CLI::Validator(
          [](std::string& r) {
            vis::ColorSettings scratch;
            return read_range(r, scratch)
                       ? std::string()
                       : std::string("must be auto, symmetric or MIN,MAX with MIN < MAX");
          },
          "RANGE"));
  render_cmd->add_flag("--shaded", views.color.shaded, "light the colour-mapped cloth");
  render_cmd
      ->add_option_function<std::vector<std::string>>(
          "--arrows",
          [&views](const std::vector<std::string>& kinds) {
            for (const std::string& k : kinds)
              (k == "force" ? views.arrows.force : views.arrows.normals) = true;
          },
          "arrows at the vertices: force, normals")
      ->delimiter(',')
      ->check(CLI::IsMember({"force", "normals"}));
  add_choice(render_cmd, "--force-source", views.force_source, clothlab::kAllForceSources,
             clothlab::force_source_name,
             "force shown by arrows and --color-by force: total, springs, gravity, drag, wind "
             "(default: the total, or the springs' force where the total is near zero)")
      ->each([&views](const std::string&) { views.springs_at_rest = false; });
  render_cmd->add_option("--arrow-stride", views.arrows.stride, "an arrow every N vertices")
      ->check(between(1, 100000));
  add_choice(
      render_cmd, "--arrow-scale", views.arrows.scale,
      std::array{vis::ArrowScale::linear, vis::ArrowScale::log},
      [](vis::ArrowScale s) { return s == vis::ArrowScale::log ? "log" : "linear"; },
      "force arrow length: linear or log");
  render_cmd->add_flag_callback(
      "--no-legend", [&views] { views.legends = false; },
      "no colour bars (they show with --color-by and force arrows)");
}

// `render`: a scene headless (EGL) to PNGs or MP4.
CLI::App* add_render(CLI::App& app, RenderCli& cli) {
  RenderArgs& render = cli.args;
  auto* render_cmd = app.add_subcommand("render", "render a scene headless (EGL) to PNGs or MP4");
  add_scene_options(*render_cmd, render.scene, render.overrides);
  render_cmd->add_option("--frames", render.frames, "frames to render")
      ->capture_default_str()
      ->check(between(1, 1000000));
  render_cmd
      ->add_option(
          "--mode", render.mode,
          "1 springs, 2 normals, 3 Lambert + texture, 4 cloth BRDF + gold threads, 5 translucent "
          "cloth with coloured shadows, 6 normal-mapped weave, 7 the "
          "light's depth map "
          "(default: the scene's render.mode)")
      ->check(between(1, 7));
  render_cmd->add_option("--size", cli.size, "image size WxH")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](std::string& s) {
            int w = 0, h = 0;
            char x = 0;
            return std::sscanf(s.c_str(), "%d%c%d", &w, &x, &h) == 3 && x == 'x' && w >= 16 &&
                           h >= 16 && w <= 8192 && h <= 8192
                       ? std::string()
                       : std::string("must be WxH with 16 <= W, H <= 8192, e.g. 1280x720");
          },
          "WxH"));
  render_cmd->add_option("--fps", render.fps, "frames per simulated second")
      ->capture_default_str()
      ->check(between(1.0, 10000.0));
  render_cmd
      ->add_option("--out", render.out,
                   "directory for the numbered PNGs (at least one of --out and --video)")
      ->check(output_file_or_directory());
  render_cmd
      ->add_option("--video", render.video,
                   "an MP4 through Debian's ffmpeg: the frames go straight to it, and to PNGs "
                   "only with --out as well")
      ->check(output_file());
  render_cmd
      ->add_option("--music-out", render.music_out,
                   "also write the scene's [music] (e.g. its generated drum track) as WAV")
      ->check(output_file());
  render_cmd->add_flag("--quiet", render.quiet,
                       "print only errors, warnings and --probe's line (no progress or summary)");
  render_cmd
      ->add_option(
          "--copies", render.copies,
          "copies of the scene's cloth side by side, each simulated (as the window's + key)")
      ->check(between(1, 64));
  cli.probe_opt = render_cmd->add_option(
      "--probe", cli.probe, "after the last frame, print the field under pixel PX,PY as JSON");
  render_cmd->add_option("--field", render.field, "probed field: force, velocity or position")
      ->check(CLI::IsMember({"force", "velocity", "position"}));

  add_render_views(render_cmd, render.views);
  return render_cmd;
}

// The image size, and --probe checked against it (known only once --size is parsed).
int run_render_cli(RenderCli& cli) {
  RenderArgs& render = cli.args;
  if (render.out.empty() && render.video.empty()) {
    std::fprintf(stderr,
                 "clothlab render: nothing to write: give --out DIR for PNG frames, --video "
                 "FILE.mp4 for a video, or both\n");
    return kBadInput;
  }
  std::sscanf(cli.size.c_str(), "%dx%d", &render.width, &render.height);
  // --probe is checked against the image size, known only once --size is parsed.
  if (*cli.probe_opt) {
    int px = -1, py = -1;
    char comma = 0, rest = 0;
    if (std::sscanf(cli.probe.c_str(), "%d%c%d%c", &px, &comma, &py, &rest) != 3 || comma != ',' ||
        px < 0 || py < 0 || px >= render.width || py >= render.height) {
      std::fprintf(stderr,
                   "clothlab render: --probe %s: must be PX,PY, a pixel inside the %dx%d image "
                   "(0 <= PX < %d, 0 <= PY < %d)\n",
                   cli.probe.c_str(), render.width, render.height, render.width, render.height);
      return kBadInput;
    }
    render.probe = std::array<int, 2>{px, py};
  }
  return run_render(render);
}

// `view`: a window on a scene (the default scene if none).
CLI::App* add_view(CLI::App& app, ViewArgs& view) {
  auto* view_cmd = app.add_subcommand("view", "open a window on a scene (default scene if none)");
  add_scene_options(*view_cmd, view.scene, view.overrides, false);
  view_cmd
      ->add_option("--copies", view.copies,
                   "start with this many copies of the cloth side by side (+ and - change it)")
      ->check(between(1, 64));

  // The keys and the mouse, as the window's help overlay (H) lists them.
  std::string keys = "\nKeys in the window:\n";
  auto add_line = [&keys](std::string_view what, std::string_view help, int width) {
    char line[200];
    std::snprintf(line, sizeof line, "  %-*.*s %.*s\n", width, int(what.size()), what.data(),
                  int(help.size()), help.data());
    keys += line;
  };
  for (const vis::KeyBinding& k : vis::key_bindings()) add_line(k.name, k.help, 6);
  keys += "Mouse:\n";
  for (const vis::MouseBinding& m : vis::mouse_bindings()) add_line(m.gesture, m.help, 16);
  view_cmd->footer(keys);
  return view_cmd;
}

// `tune`: run time against error on the scene itself (docs/tuning.md).
CLI::App* add_tune(CLI::App& app, TuneArgs& tune) {
  auto* cmd = app.add_subcommand(
      "tune",
      "run time against error on a scene: a reference, a ladder of settings, the "
      "cheapest within a tolerance");
  add_scene_options(*cmd, tune.scene, tune.overrides);
  cmd->add_option("--duration", tune.duration, "the horizon T in simulated seconds (default 1)")
      ->check(CLI::Range(1.0 / 60.0, 60.0));
  cmd->add_option("--tolerance", tune.tolerance,
                  "m: RMS distance from the reference allowed at every sample time up to T "
                  "(default: say the cheapest within 60, 20 and 5 mm)")
      ->check(CLI::Range(1e-9, 10.0));
  cmd->add_option("--threads", tune.threads, "solver threads of every run (default: the scene's)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--out", tune.out, "CSV file (default out/tune/SCENE.csv); the plot beside it")
      ->check(output_file());
  cmd->add_flag("--quiet", tune.quiet, "no progress lines");
  cmd->add_option("--scheduler", tune.scheduler,
                  "a Dask scheduler's address (tcp://host:8786): the runs go to its workers "
                  "through the Python module (docs/tuning.md)");
  return cmd;
}

// `bench`: run time against error, stability, scaling, feature, view and render costs.
CLI::App* add_bench(CLI::App& app, BenchArgs& bench) {
  auto* bench_cmd = app.add_subcommand(
      "bench",
      "run time against error, stability, scaling, feature, view and render costs (tables + CSV)");
  std::vector<std::string> suites(std::begin(clothlab::bench::kSuiteNames),
                                  std::end(clothlab::bench::kSuiteNames));
  std::string listed;
  for (const std::string& name : suites) listed += name + ", ";
  suites.push_back("all");
  bench_cmd->add_option("--suite", bench.suite, listed + "or all")
      ->capture_default_str()
      ->check(CLI::IsMember(suites));
  bench_cmd
      ->add_option("--out", bench.out,
                   "CSV file (one suite) or directory (all); default out/bench/SUITE.csv")
      ->check(output_file_or_directory());
  bench_cmd->add_flag("--quick", bench.quick,
                      "reduced sweeps in seconds instead of minutes: smaller grids, fewer "
                      "stiffnesses, rounds and frames, shorter horizons (the tables say which)");
  bench_cmd->add_option("--threads", bench.threads, "solver threads (scaling measures 1 and 2)")
      ->capture_default_str()
      ->check(between(1, 1024));
  bench_cmd->add_flag("--verbose", bench.verbose, "progress lines on stderr");

  return bench_cmd;
}

// A first argument that is neither an option nor a subcommand: named, with the subcommands
// (CLI11 would only say that a subcommand is required).
bool unknown_subcommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == argv[1]) return false;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  std::fprintf(stderr,
               "clothlab: unknown subcommand \"%s\"; the subcommands are %s (clothlab help)\n",
               argv[1], names.c_str());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  clothlab::prefer_passive_openmp(argv);
  clothlab::install_temp_file_cleanup();
  using namespace clothlab::app;
  CLI::App app{"ClothLab: a laboratory for simulating cloth and looking at it scientifically.",
               "clothlab"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "clothlab " CLOTHLAB_VERSION);

  CheckArgs check;
  auto* check_cmd = app.add_subcommand("check", "parse and validate a scene, then exit");
  add_scene_options(*check_cmd, check.scene, check.overrides);
  check_cmd->add_flag("--force", check.force,
                      "build the solver even when that is estimated to take over a minute");
  auto* params_cmd = app.add_subcommand(
      "params", "print every scene key: type, range, default, unit and meaning (Markdown)");
  TraceArgs trace;
  auto* trace_cmd = add_trace(app, trace);
  RenderCli render;
  auto* render_cmd = add_render(app, render);
  ViewArgs view;
  auto* view_cmd = add_view(app, view);
  BenchArgs bench;
  auto* bench_cmd = add_bench(app, bench);
  TuneArgs tune;
  auto* tune_cmd = add_tune(app, tune);
  app.add_subcommand("help", "print this overview of the subcommands");

  if (unknown_subcommand(app, argc, argv)) return 2;
  if (argc >= 2 && std::string(argv[1]) == "help") {  // before parsing: the overview, not help's
    std::fputs(app.help().c_str(), stdout);
    return 0;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // One line naming the subcommand, as every other bad input is said.
    const std::string sub = argc >= 2 && argv[1][0] != '-' ? std::string(" ") + argv[1] : "";
    std::fprintf(stderr, "clothlab%s: %s (clothlab%s --help)\n", sub.c_str(), e.what(),
                 sub.c_str());
    return 2;
  }
  // A scene error found while building (a built state the solver cannot hold) is bad input like
  // any other; running out of memory anywhere is one line and exit 1, never an abort.
  try {
    if (*check_cmd) return run_check(check);
    if (*params_cmd) return run_params();
    if (*trace_cmd) return run_trace_command(trace);
    if (*render_cmd) return run_render_cli(render);
    if (*view_cmd) return run_view(view);
    if (*bench_cmd) return run_bench(bench);
    if (*tune_cmd) return run_tune_command(tune);
  } catch (const clothlab::SceneError& e) {
    std::fprintf(stderr, "clothlab %s: %s\n", argv[1], e.what());
    return kBadInput;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr,
                 "clothlab %s: out of memory (the scene needs more than this machine "
                 "can give; lower cloth.resolution or the copies)\n",
                 argv[1]);
    return 1;
  }
  return 2;
}
