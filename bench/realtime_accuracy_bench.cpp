// Real time at scale against accuracy (issues 36 and 54): the accuracy sheet
// (bench/suites/lab_scenes.hpp: 1 m, 0.2 kg, k0 = 1e3 N/m, damping 0.05, two corners pinned,
// falling from horizontal) at res x res, each setting in float (or double) at dt = 1/60 s on
// `threads` threads: RMS distance of all vertices at t = 0.2, 0.5 and 1.0 s from a double RK4 run
// of the same sheet, and the median wall time of one 1/60 s frame. The RK4 reference is cached in a
// file (it costs minutes at 256^2).
//
//   build/release/bench/realtime_accuracy_bench [res=256] [threads=2] [csv=realtime_accuracy.csv]
//                                               [reference=out/bench/rk4_<res>_1s.bin]
//                                               [only=the settings whose label starts so;
//                                                ending in $, the one so labelled]
//                                               [precision=float or double]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/suites/realtime_accuracy.hpp"
#include "sim/core/passive_openmp.hpp"
#include "sim/solver.hpp"

namespace clothlab {
namespace {

using Setting = bench::RealtimeSetting;
constexpr double kFrame = 1.0 / 60.0;

// The largest square sheet a method runs at 60 Hz with its defaults (median of 9 frames after 2,
// same threads), in steps of 32 vertices a side; prints each size.
int largest_real_time(const Setting& s, int threads) {
  int largest = 0;
  for (int side = 64; side <= 1024; side += 32) {
    auto solver = make_solver(bench::realtime_sheet(side, s, threads));
    solver->step(2);
    const double t = bench::median_frame_seconds(*solver, 9);
    std::printf("%s at %d^2: %d substeps, %.2f ms per frame\n", s.label.c_str(), side,
                solver->substeps(), 1e3 * t);
    if (t > kFrame) break;
    largest = side;
  }
  std::printf("largest real-time sheet (%s, %d threads): %d^2\n", s.label.c_str(), threads,
              largest);
  return largest;
}

}  // namespace
}  // namespace clothlab

int main(int argc, char** argv) {
  clothlab::prefer_passive_openmp(argv);
  using namespace clothlab;
  const int res = argc > 1 ? std::atoi(argv[1]) : 256;
  const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
  const std::string csv_path = argc > 3 ? argv[3] : "realtime_accuracy.csv";
  const std::string ref_path =
      argc > 4 ? argv[4] : "out/bench/rk4_" + std::to_string(res) + "_1s.bin";
  // Double RK4 at 1e-5 s (its automatic step's halving changed nothing above 1e-7 m at 256^2 and
  // 0.2 s, docs/solver.md), cached: it costs minutes at 256^2.
  const std::vector<double> ref = bench::realtime_reference(res, threads, 1e-5, ref_path);
  using K = IntegratorKind;
  const std::vector<Setting> settings = {
      {"xpbd auto", K::xpbd},
      {"xpbd x5", K::xpbd, 5},
      {"xpbd x20", K::xpbd, 20},
      {"xpbd x40", K::xpbd, 40},
      {"xpbd x80", K::xpbd, 80},
      {"xpbd x160", K::xpbd, 160},
      {"xpbd x320", K::xpbd, 320},
      {"xpbd x20 no slack", K::xpbd, 20, 0, true, true, 0, LinearSolver::automatic, 0.0, 0.0,
       false},
      {"xpbd x40 no slack", K::xpbd, 40, 0, true, true, 0, LinearSolver::automatic, 0.0, 0.0,
       false},
      {"xpbd x80 no slack", K::xpbd, 80, 0, true, true, 0, LinearSolver::automatic, 0.0, 0.0,
       false},
      {"xpbd x160 no slack", K::xpbd, 160, 0, true, true, 0, LinearSolver::automatic, 0.0, 0.0,
       false},
      {"xpbd x320 no slack", K::xpbd, 320, 0, true, true, 0, LinearSolver::automatic, 0.0, 0.0,
       false},
      {"xpbd x10 iterations 2", K::xpbd, 10, 2},
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
  const bool in_double = argc > 6 && std::string(argv[6]) == "double";
  const Precision precision = in_double ? Precision::f64 : Precision::f32;
  std::printf("%d^2 sheet, k0 = 1e3, dt = 1/60 s, %s, %d threads: RMS from RK4 (mm)\n", res,
              in_double ? "double" : "float", threads);
  std::printf("%-28s %-9s %-8s %-8s %-8s %s\n", "setting", "substeps", "0.2 s", "0.5 s", "1.0 s",
              "ms per frame");
  const std::string tmp = csv_path + ".tmp";
  std::FILE* csv = std::fopen(tmp.c_str(), "w");
  if (!csv) return 1;
  std::fprintf(csv,
               "setting,substeps,resolution,threads,rms_0.2s_m,rms_0.5s_m,rms_1.0s_m,"
               "seconds_per_frame\n");
  for (const Setting& s : settings) {
    const bool exact = !only.empty() && only.back() == '$';
    if (exact ? s.label != only.substr(0, only.size() - 1) : s.label.find(only) != 0) continue;
    auto solver = make_solver(bench::realtime_sheet(res, s, threads, precision));
    const bench::RealtimeMeasured m = bench::measure_realtime(*solver, ref);
    std::printf("%-28s %-9d %-8.1f %-8.1f %-8.1f %.2f", s.label.c_str(), solver->substeps(),
                1e3 * m.rms[0], 1e3 * m.rms[1], 1e3 * m.rms[2], 1e3 * m.frame);
    const SolveTotals& t = solver->solve_totals();
    if (t.solves > 0)  // the implicit methods: Newton iterations a frame, PCG iterations each
      std::printf("  (%.1f solves a frame, %.1f iterations a solve)",
                  double(t.solves) / double(t.substeps), double(t.iterations) / double(t.solves));
    std::printf("\n");
    std::fprintf(csv, "%s,%d,%d,%d,%.6g,%.6g,%.6g,%.6g\n", s.label.c_str(), solver->substeps(), res,
                 threads, m.rms[0], m.rms[1], m.rms[2], m.frame);
  }
  std::fclose(csv);
  std::rename(tmp.c_str(), csv_path.c_str());
  for (const Setting& s : {Setting{"xpbd auto", K::xpbd}, Setting{"vbd", K::vbd}})
    if (only.empty()) largest_real_time(s, threads);
  return 0;
}
