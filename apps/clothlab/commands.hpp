// The clothlab subcommands. Each returns the process exit status: 0 success, 2 bad input
// (message names file, line and key, or the argument), 1 runtime failure (e.g. divergence).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "sim/scene/scene.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab::app {

struct CheckArgs {
  std::string scene;
  std::vector<std::string> overrides;
  bool force = false;  // build even when the estimate says it takes more than kMaxCheckBuild
};

struct TraceArgs {
  std::string scene;
  std::vector<std::string> overrides;
  double duration = 0.0;
  std::string out;
  bool quiet = false;  // only errors and warnings: no summary, no estimate or progress
};

struct RenderArgs {
  std::string scene;
  std::vector<std::string> overrides;
  int frames = 60;
  int mode = 0;  // display mode (keys 1-3, 7); 0: the scene's render.mode
  int width = 1280, height = 720;
  double fps = 60.0;      // simulated time per frame = 1 / fps
  int copies = 1;         // copies of the scene's cloth side by side (sim/cloth/scene_copies.hpp)
  std::string out;        // directory for frame_00000.png, ...
  std::string video;      // optional MP4 through ffmpeg
  std::string music_out;  // optional: the scene's music as a WAV file
  bool quiet = false;     // only errors, warnings and --probe's line: no progress, no summary
  // --probe PX,PY: after the last frame, one JSON line with `field` under that pixel (row 0 at
  // the top); the force field is computed only then.
  std::optional<std::array<int, 2>> probe;
  std::string field = "force";  // force | velocity | position
  // Scientific views (--color-by, --colormap, --range, --shaded, --arrows, --force-source,
  // --arrow-stride, --arrow-scale, --no-legend), parsed straight into the view's own settings.
  vis::ScientificViews views;
};

struct ViewArgs {
  std::string scene;  // empty: the default scene
  std::vector<std::string> overrides;
  int copies = 1;  // copies of the cloth side by side (the window's [ and ])
};

struct BenchArgs {
  std::string suite = "all";  // accuracy | stability | scaling | features | all
  std::string out;            // CSV file (one suite) or directory (all); default out/bench/
  bool quick = false;         // reduced sweeps: seconds instead of minutes
  int threads = 1;            // solver threads for accuracy, stability and features
  bool verbose = false;       // progress lines on stderr
};

// `clothlab tune` (docs/tuning.md).
struct TuneArgs {
  std::string scene;
  std::vector<std::string> overrides;
  double duration = 1.0;            // s: the horizon
  std::optional<double> tolerance;  // m: RMS at every sample time; none: 60, 20 and 5 mm
  int threads = 0;                  // solver threads of every run; 0: the scene's own
  std::string out;                  // CSV file; the plot beside it as .png
  bool quiet = false;               // no progress lines
  std::string scheduler;            // a Dask scheduler's address: the settings run there
};
int run_bench(const BenchArgs& args);
int run_tune_command(const TuneArgs& args);
int run_check(const CheckArgs& args);
int run_params();  // check_command.cpp
int run_render(const RenderArgs& args);
int run_view(const ViewArgs& args);
int run_trace_command(const TraceArgs& args);

// Parses and validates a scene for subcommand `command`; on bad input prints
// "clothlab <command>: <file:line:col: key: message>" to stderr and returns nothing (the caller
// exits with status 2).
std::optional<Scene> load_scene(const char* command, const std::string& path,
                                const std::vector<std::string>& overrides);
// load_scene, then a solver.tolerance resolved to the cheapest setting `clothlab tune` finds
// within it (from the cache, else tuned now: docs/tuning.md, "A tolerance in the scene"), whose
// --set lines are added after `overrides`. Says the choice on stderr unless quiet.
std::optional<Scene> load_scene_to_run(const char* command, const std::string& path,
                                       const std::vector<std::string>& overrides, bool quiet);
inline constexpr int kBadInput = 2;

// The command line that replays a run, printed with runtime failures (pbrt's habit).
std::string replay_command(const std::string& scene, const std::vector<std::string>& overrides,
                           double duration);

}  // namespace clothlab::app
