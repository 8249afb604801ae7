// Real time against accuracy (issues 36 and 54), shared by `clothlab bench --suite realtime` and
// bench/realtime_accuracy_bench: the accuracy sheet (lab_scenes.hpp: 1 m, 0.2 kg, k0 = 1e3 N/m,
// damping 0.05, two corners pinned, falling from horizontal) at res x res, a setting at dt =
// 1/60 s, measured against a double RK4 run of the same sheet: the RMS distance of all vertices
// at t = 0.2, 0.5 and 1.0 s, and the median wall time of one 1/60 s frame.
#pragma once

#include <string>
#include <vector>

#include "sim/scene/scene.hpp"

namespace clothlab {
class Solver;
}

namespace clothlab::bench {

inline constexpr int kRealtimeHorizons = 3;
inline constexpr int kRealtimeHorizonFrames[kRealtimeHorizons] = {12, 30, 60};  // 0.2, 0.5, 1 s

struct RealtimeSetting {
  std::string label;
  IntegratorKind kind;
  int substeps = 0, iterations = 0;  // 0: automatic / the method's default
  bool tethers = true, coarse = true;
  int newton = 0;  // implicit methods: solver.newton_iterations (0: default)
  LinearSolver linear = LinearSolver::automatic;
  double newton_tolerance = 0.0;  // implicit methods: solver.newton_tolerance (0: default)
  double cg_tolerance = 0.0;      // implicit methods: solver.cg_tolerance (0: automatic)
  bool slack = true;              // xpbd: solver.stretch_slack
};

// The accuracy sheet at res x res with the setting, at 1/60 s.
Scene realtime_sheet(int res, const RealtimeSetting& s, int threads,
                     Precision precision = Precision::f32);

// Double RK4 at `dt` to each horizon, one after another in one vector, read from `path` when a
// run of the same size is there and written there otherwise (through a temporary file and a
// rename); an empty path caches nothing.
std::vector<double> realtime_reference(int res, int threads, double dt, const std::string& path);

struct RealtimeMeasured {
  double rms[kRealtimeHorizons] = {};  // m
  double frame = 0.0;                  // median s a frame over the whole second
};

// Steps the solver through the horizons, measuring each against the reference.
RealtimeMeasured measure_realtime(Solver& solver, const std::vector<double>& reference);

// The median wall time of `frames` frames of 1/60 s (s).
double median_frame_seconds(Solver& solver, int frames);

}  // namespace clothlab::bench
