// Real time at scale against accuracy (issue 36): the accuracy sheet (bench/suites/lab_scenes.hpp:
// 1 m, 0.2 kg, k0 = 1e3 N/m, damping 0.05, two corners pinned, falling from horizontal) at
// res x res, each setting in float at dt = 1/60 s on `threads` threads: RMS distance of all
// vertices at t = 0.2 s from a double RK4 run of the same sheet, and the median wall time of
// one 1/60 s frame. The RK4 reference is cached in a file (it costs minutes at 256^2).
//
//   build/release/bench/realtime_accuracy_bench [res=256] [threads=2] [csv=realtime_accuracy.csv]
//                                               [reference=out/bench/rk4_<res>.bin]
//                                               [only=the settings whose label starts so;
//                                                ending in $, the one so labelled]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "bench/suites/lab_scenes.hpp"
#include "sim/core/passive_openmp.hpp"
#include "sim/solver.hpp"

namespace clothlab {
namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr double kHorizon = 0.2;
constexpr int kFrames = 12;  // kHorizon / kFrame

struct Setting {
  std::string label;
  IntegratorKind kind;
  int substeps = 0, iterations = 0;  // 0: automatic / the method's default
  bool tethers = true, coarse = true;
  int newton = 0;  // implicit methods: solver.newton_iterations (0: default)
  LinearSolver linear = LinearSolver::automatic;
  double newton_tolerance = 0.0;  // implicit methods: solver.newton_tolerance (0: default)
  double cg_tolerance = 0.0;      // implicit methods: solver.cg_tolerance (0: automatic)
};

Scene sheet(int res, const Setting& s, int threads) {
  bench::SheetParams p;
  p.resolution = res;
  Scene scene = bench::hanging_sheet(p, s.kind, kFrame);
  scene.solver.substeps = s.substeps;
  scene.solver.iterations = s.iterations;
  scene.solver.tethers = s.tethers;
  scene.solver.coarse_stretch = s.coarse;
  scene.solver.newton_iterations = s.newton;
  scene.solver.linear_solver = s.linear;
  if (s.newton_tolerance > 0.0) scene.solver.newton_tolerance = s.newton_tolerance;
  scene.solver.cg_tolerance = s.cg_tolerance;
  scene.solver.threads = threads;
  scene.solver.precision = Precision::f32;
  return scene;
}

std::vector<double> positions(const Solver& solver) {
  std::vector<double> p;
  for (std::size_t i = 0; i < solver.vertex_count(); ++i)
    for (double c : solver.position(static_cast<int>(i))) p.push_back(c);
  return p;
}

// Double RK4 at 1e-5 s to kHorizon (its automatic step's halving changed nothing above 1e-7 m at
// 256^2, docs/solver.md), read from `path` when a run of the same size is there.
std::vector<double> reference(int res, int threads, const std::string& path) {
  std::vector<double> p(static_cast<std::size_t>(res) * res * 3);
  std::ifstream in(path, std::ios::binary);
  if (in.read(reinterpret_cast<char*>(p.data()), std::streamsize(p.size() * sizeof(double))))
    return p;
  Scene scene = sheet(res, {"rk4", IntegratorKind::rk4}, threads);
  scene.solver.precision = Precision::f64;
  scene.solver.dt = 1e-5;
  auto solver = make_solver(scene);
  solver->step(std::lround(kHorizon / 1e-5));
  p = positions(*solver);
  const std::string tmp = path + ".tmp";
  std::ofstream(tmp, std::ios::binary)
      .write(reinterpret_cast<const char*>(p.data()), std::streamsize(p.size() * sizeof(double)));
  std::rename(tmp.c_str(), path.c_str());
  return p;
}

// The median wall time of `frames` frames of 1/60 s (s).
double median_frame(Solver& solver, int frames) {
  std::vector<double> times;
  for (int f = 0; f < frames; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    solver.step(1);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(times.begin(), times.begin() + frames / 2, times.end());
  return times[static_cast<std::size_t>(frames / 2)];
}

// The largest square sheet a method runs at 60 Hz with its defaults (median of 9 frames after 2,
// same threads), in steps of 32 vertices a side; prints each size.
int largest_real_time(const Setting& s, int threads) {
  int largest = 0;
  for (int side = 64; side <= 1024; side += 32) {
    auto solver = make_solver(sheet(side, s, threads));
    solver->step(2);
    const double t = median_frame(*solver, 9);
    std::printf("%s at %d^2: %d substeps, %.2f ms per frame\n", s.label.c_str(), side,
                solver->substeps(), 1e3 * t);
    if (t > kFrame) break;
    largest = side;
  }
  std::printf("largest real-time sheet (%s, %d threads): %d^2\n", s.label.c_str(), threads,
              largest);
  return largest;
}

double rms(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / double(a.size() / 3));
}

}  // namespace
}  // namespace clothlab

int main(int argc, char** argv) {
  clothlab::prefer_passive_openmp(argv);
  using namespace clothlab;
  const int res = argc > 1 ? std::atoi(argv[1]) : 256;
  const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
  const std::string csv_path = argc > 3 ? argv[3] : "realtime_accuracy.csv";
  const std::string ref_path = argc > 4 ? argv[4] : "out/bench/rk4_" + std::to_string(res) + ".bin";
  const std::vector<double> ref = reference(res, threads, ref_path);
  using K = IntegratorKind;
  const std::vector<Setting> settings = {
      {"xpbd auto", K::xpbd},
      {"xpbd x5", K::xpbd, 5},
      {"xpbd x20", K::xpbd, 20},
      {"xpbd x10 tethers only", K::xpbd, 10, 0, true, false},
      {"xpbd x26 tethers only", K::xpbd, 26, 0, true, false},
      {"xpbd x10 coarse only", K::xpbd, 10, 0, false, true},
      {"xpbd x10 neither", K::xpbd, 10, 0, false, false},
      {"xpbd x20 neither", K::xpbd, 20, 0, false, false},
      {"xpbd x40 neither", K::xpbd, 40, 0, false, false},
      {"vbd", K::vbd},
      {"bdf2", K::bdf2},
      {"bdf2 newton 2", K::bdf2, 0, 0, true, true, 2},
      {"bdf2 newton 3", K::bdf2, 0, 0, true, true, 3},
      {"bdf2 newton 4", K::bdf2, 0, 0, true, true, 4},
      {"bdf2 tol 0.1", K::bdf2, 0, 0, true, true, 0, LinearSolver::automatic, 0.1},
      {"bdf2 tol 0.3", K::bdf2, 0, 0, true, true, 0, LinearSolver::automatic, 0.3},
      {"bdf2 cg 0.1", K::bdf2, 0, 0, true, true, 0, LinearSolver::automatic, 0, 0.1},
      {"bdf2 block jacobi", K::bdf2, 0, 0, true, true, 0, LinearSolver::block_jacobi},
      {"bdf2 multigrid", K::bdf2, 0, 0, true, true, 0, LinearSolver::multigrid},
      {"implicit_euler", K::implicit_euler},
      {"implicit_euler newton 2", K::implicit_euler, 0, 0, true, true, 2},
      {"implicit_euler newton 3", K::implicit_euler, 0, 0, true, true, 3},
      {"implicit_euler tol 0.1", K::implicit_euler, 0, 0, true, true, 0, LinearSolver::automatic,
       0.1},
      {"implicit_euler block jacobi", K::implicit_euler, 0, 0, true, true, 0,
       LinearSolver::block_jacobi},
      {"implicit_euler multigrid", K::implicit_euler, 0, 0, true, true, 0, LinearSolver::multigrid},
  };
  const std::string only = argc > 5 ? argv[5] : "";
  std::printf("%d^2 sheet, k0 = 1e3, dt = 1/60 s, float, %d threads: RMS at %.1f s from RK4\n", res,
              threads, kHorizon);
  std::printf("%-22s %-9s %-12s %s\n", "setting", "substeps", "rms (mm)", "ms per frame");
  const std::string tmp = csv_path + ".tmp";
  std::FILE* csv = std::fopen(tmp.c_str(), "w");
  if (!csv) return 1;
  std::fprintf(csv, "setting,substeps,resolution,threads,rms_m,seconds_per_frame\n");
  for (const Setting& s : settings) {
    const bool exact = !only.empty() && only.back() == '$';
    if (exact ? s.label != only.substr(0, only.size() - 1) : s.label.find(only) != 0) continue;
    auto solver = make_solver(sheet(res, s, threads));
    const double frame = median_frame(*solver, kFrames);
    const double e = rms(positions(*solver), ref);
    std::printf("%-22s %-9d %-12.1f %.2f", s.label.c_str(), solver->substeps(), 1e3 * e,
                1e3 * frame);
    const SolveTotals& t = solver->solve_totals();
    if (t.solves > 0)  // the implicit methods: Newton iterations a frame, PCG iterations each
      std::printf("  (%.1f solves a frame, %.1f iterations a solve)",
                  double(t.solves) / double(t.substeps), double(t.iterations) / double(t.solves));
    std::printf("\n");
    std::fprintf(csv, "%s,%d,%d,%d,%.6g,%.6g\n", s.label.c_str(), solver->substeps(), res, threads,
                 e, frame);
  }
  std::fclose(csv);
  std::rename(tmp.c_str(), csv_path.c_str());
  for (const Setting& s : {Setting{"xpbd auto", K::xpbd}, Setting{"vbd", K::vbd}})
    if (only.empty()) largest_real_time(s, threads);
  return 0;
}
