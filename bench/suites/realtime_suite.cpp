// `clothlab bench --suite realtime`: issue 54's measurements. Real time against accuracy on the
// 256 x 256 accuracy sheet (realtime_accuracy.hpp: xpbd's defaults and more substeps, RMS from
// double RK4 at 0.2, 0.5 and 1.0 s, the median ms of a 1/60 s frame), xpbd's defaults by sheet
// size up to 512 x 512, and `scenes/large_sheet.toml` in the window (`clothlab view` under
// xvfb-run: what a software renderer draws while the simulation keeps up). docs/solver.md quotes
// it.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <ostream>
#include <regex>
#include <string>
#include <vector>

#include "bench/suites/lab_scenes.hpp"
#include "bench/suites/realtime_accuracy.hpp"
#include "bench/suites/suites.hpp"
#include "sim/solver.hpp"

namespace clothlab::bench {
namespace {

constexpr int kWindowFrames = 600;

Table accuracy_table(const SuiteOptions& o) {
  const int res = o.quick ? 32 : 256;
  // At 256^2 RK4 at 1e-5 s takes minutes: cached beside the suites' output, as
  // bench/realtime_accuracy_bench caches it. --quick: 1e-4 s, the small-steps tests' reference
  // (1e-5 s agrees with it to 0.0 mm at 64^2 and 0.5 s).
  const double dt = o.quick ? 1e-4 : 1e-5;
  const std::string cache = o.quick ? "" : "out/bench/rk4_" + std::to_string(res) + "_1s.bin";
  if (!cache.empty()) std::filesystem::create_directories("out/bench");
  const std::vector<double> reference = realtime_reference(res, o.threads, dt, cache);
  Table t;
  t.title = "Real time against accuracy: the accuracy sheet at " + std::to_string(res) + "x" +
            std::to_string(res) + " (k0 = 1e3, falling from horizontal), float, 1/60 s, " +
            std::to_string(o.threads) + " thread(s): RMS distance from double RK4 (dt " + num(dt) +
            " s) and the median time of a frame";
  t.note = quick_note(o.quick, "the 256x256 sheet and the runs beyond 20 substeps");
  t.columns = {"setting",        "substeps",   "rms 0.2 s (mm)", "rms 0.5 s (mm)",
               "rms 1.0 s (mm)", "ms a frame", "real time"};
  using K = IntegratorKind;
  std::vector<RealtimeSetting> settings = {{"xpbd defaults", K::xpbd}, {"xpbd x20", K::xpbd, 20}};
  if (!o.quick)
    for (int n : {40, 80, 160, 320}) settings.push_back({"xpbd x" + std::to_string(n), K::xpbd, n});
  if (!o.quick) {
    RealtimeSetting rigid{"xpbd x40, no stretch slack", K::xpbd, 40};
    rigid.slack = false;
    settings.push_back(rigid);
  }
  for (const RealtimeSetting& s : settings) {
    auto solver = make_solver(realtime_sheet(res, s, o.threads));
    const RealtimeMeasured m = measure_realtime(*solver, reference);
    t.add({s.label, std::to_string(solver->substeps()), fixed(1e3 * m.rms[0], 1),
           fixed(1e3 * m.rms[1], 1), fixed(1e3 * m.rms[2], 1), fixed(1e3 * m.frame, 2),
           m.frame <= kFrame ? "yes" : "no"});
    if (o.log) *o.log << "realtime: " << s.label << " " << 1e3 * m.frame << " ms\n";
  }
  return t;
}

Table sizes_table(const SuiteOptions& o) {
  Table t;
  t.name = "sizes";
  t.title =
      "xpbd's defaults by sheet size: the median time of a 1/60 s frame (9 after 2), float, " +
      std::to_string(o.threads) + " thread(s)";
  t.note = quick_note(o.quick, "the sheets from 256x256 up");
  t.columns = {"grid", "vertices", "substeps", "ms a frame", "real time"};
  const std::vector<int> sides =
      o.quick ? std::vector<int>{32, 48} : std::vector<int>{256, 384, 512};
  for (int side : sides) {
    auto solver =
        make_solver(realtime_sheet(side, {"xpbd defaults", IntegratorKind::xpbd}, o.threads));
    solver->step(2);
    const double frame = median_frame_seconds(*solver, 9);
    t.add({std::to_string(side) + "x" + std::to_string(side),
           std::to_string(solver->vertex_count()), std::to_string(solver->substeps()),
           fixed(1e3 * frame, 2), frame <= kFrame ? "yes" : "no"});
    if (o.log) *o.log << "realtime: " << side << "^2 " << 1e3 * frame << " ms\n";
  }
  return t;
}

// The summary line `clothlab view` prints when it quits by itself (apps/view/view_app.cpp).
struct WindowRun {
  bool ok = false;
  std::string output;
  double frame_ms = 0.0, simulation_ms = 0.0, real_time = 0.0;
  std::string scene_pixels, renderer;
};

// `text` as one word for the shell: in single quotes, each of its own as '\''.
std::string shell_word(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

WindowRun run_window(const std::filesystem::path& scene) {
  WindowRun r;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const std::string command = "CLOTHLAB_VIEW_EXIT_AFTER_FRAMES=" + std::to_string(kWindowFrames) +
                              " CLOTHLAB_VIEW_NO_AUDIO=1 xvfb-run -a -s '-screen 0 1280x720x24' " +
                              shell_word(self) + " view " + shell_word(scene.string()) + " 2>&1";
  std::FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
  const int status = pclose(pipe);
  static const std::regex line(
      R"(frames: ([0-9.]+) ms/frame, ([0-9.]+) ms/frame simulation .*, ([0-9.]+) % of real time)"
      R"( simulated .*scene drawn at ([0-9]+x[0-9]+), drawn by ([^\n]*)\))");
  std::smatch m;
  if (status != 0 || !std::regex_search(r.output, m, line)) return r;
  r.ok = true;
  r.frame_ms = std::atof(m[1].str().c_str());
  r.simulation_ms = std::atof(m[2].str().c_str());
  r.real_time = std::atof(m[3].str().c_str());
  r.scene_pixels = m[4].str();
  r.renderer = m[5].str();
  return r;
}

Table window_table(const SuiteOptions& o) {
  Table t;
  t.name = "window";
  t.title = "scenes/large_sheet.toml in the window: `clothlab view` under xvfb-run at 1280x720, " +
            std::to_string(kWindowFrames) +
            " frames, the scene's own threads, render quality auto (fast on a software renderer)";
  t.columns = {"scene",
               "ms a frame",
               "frames a second",
               "ms simulation a frame",
               "% of real time simulated",
               "scene drawn at",
               "drawn by"};
  const std::filesystem::path scene =
      std::filesystem::path(CLOTHLAB_DEFAULT_SCENE).parent_path() / "large_sheet.toml";
  const WindowRun r = run_window(scene);
  if (!r.ok) {
    t.note = "not measured: the window did not run (needs xvfb-run and a GL 4.5 driver)";
    if (o.log) *o.log << "realtime: the window did not run:\n" << r.output;
    return t;
  }
  t.add({"large_sheet.toml", fixed(r.frame_ms, 1), fixed(1e3 / r.frame_ms, 1),
         fixed(r.simulation_ms, 1), fixed(r.real_time, 0), r.scene_pixels, r.renderer});
  return t;
}

}  // namespace

std::vector<Table> realtime_suite(const SuiteOptions& o) {
  std::vector<Table> tables = {accuracy_table(o), sizes_table(o)};
  if (!o.quick) tables.push_back(window_table(o));
  return tables;
}

}  // namespace clothlab::bench
