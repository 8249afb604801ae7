// What is the largest square grid that still runs in real time at dt = 1 ms, i.e. keeps 60 frames
// per second of simulated time (16.7 steps per 16.7 ms frame, so one whole step in <= 1 ms)?
// Bisects the resolution for 1 and 2 threads, springs only and the default scene's full physics;
// prints a table and writes CSV (first argument, default realtime_grid.csv).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "sim/solver_impl.hpp"

namespace clothlab {
namespace {

constexpr double kBudgetSeconds = 1e-3;  // dt = 1 ms of simulated time per 1 ms of wall time

Scene grid_scene(int res, int threads, bool full_physics) {
  Scene s;
  ClothSpec c;
  c.size = {2.0, 2.0};
  c.resolution = {res, res};
  c.origin = {-1.0, 2.5, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, -1.0, 0.0};
  c.mass = 1.0;
  c.pins = {{0, 0}, {res - 1, 0}};
  s.cloths.push_back(c);
  s.springs.stiffness = 800.0;
  s.springs.damping = 0.05 * (32.0 * 32.0) / (res * res);  // the default sheet's damping rate
  if (full_physics) {
    s.forces.drag = 0.001;
    s.forces.wind = {true, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
  }
  // The cost of a step does not depend on dt; a stable dt keeps the run physical.
  s.solver.dt = 0.5 * 0.654 * std::sqrt(c.mass / (res * res) / s.springs.stiffness);
  s.solver.threads = threads;
  return s;
}

// Median wall time of one step, over batches of steps lasting about 0.2 s in all.
double step_seconds(int res, int threads, bool full_physics) {
  using Clock = std::chrono::steady_clock;
  SolverT<float> solver(grid_scene(res, threads, full_physics));
  solver.step(10);
  std::vector<double> samples;
  const auto start = Clock::now();
  while (samples.size() < 5 || Clock::now() - start < std::chrono::milliseconds(200)) {
    const auto t0 = Clock::now();
    solver.step(5);
    samples.push_back(std::chrono::duration<double>(Clock::now() - t0).count() / 5.0);
  }
  std::nth_element(samples.begin(), samples.begin() + samples.size() / 2, samples.end());
  return samples[samples.size() / 2];
}

}  // namespace
}  // namespace clothlab

int main(int argc, char** argv) {
  using namespace clothlab;
  const std::string csv_path = argc > 1 ? argv[1] : "realtime_grid.csv";
  std::ifstream load("/proc/loadavg");
  std::string load1;
  load >> load1;
  std::printf("largest square grid with one step <= 1 ms (real time at dt = 1 ms, 60 fps)\n");
  std::printf("one-minute load average before the run: %s\n\n", load1.c_str());
  std::printf("%-9s %-8s %-8s %-10s %-10s %s\n", "physics", "threads", "grid", "vertices",
              "springs", "ms/step");
  const std::string tmp = csv_path + ".tmp";
  std::FILE* csv = std::fopen(tmp.c_str(), "w");
  if (!csv) return 1;
  std::fprintf(csv, "physics,threads,resolution,vertices,springs,seconds_per_step\n");
  for (int full = 0; full <= 1; ++full) {
    for (int threads = 1; threads <= 2; ++threads) {
      int lo = 16, hi = 1024;  // step(lo) fits the budget, step(hi) does not
      while (hi - lo > 2) {
        const int mid = (lo + hi) / 2;
        (step_seconds(mid, threads, full) <= kBudgetSeconds ? lo : hi) = mid;
      }
      const double seconds = step_seconds(lo, threads, full);
      SolverT<float> probe(grid_scene(lo, threads, full));
      const char* name = full ? "full" : "springs";
      std::printf("%-9s %-8d %4d^2    %-10zu %-10zu %.3f\n", name, threads, lo,
                  probe.vertex_count(), probe.spring_count(), 1e3 * seconds);
      std::fprintf(csv, "%s,%d,%d,%zu,%zu,%.6g\n", name, threads, lo, probe.vertex_count(),
                   probe.spring_count(), seconds);
    }
  }
  std::fclose(csv);
  std::rename(tmp.c_str(), csv_path.c_str());
  std::printf("\nwrote %s\n", csv_path.c_str());
  return 0;
}
