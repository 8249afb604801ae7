#include "bench/suites/realtime_accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "bench/suites/lab_scenes.hpp"
#include "bench/suites/report.hpp"
#include "sim/solver.hpp"

namespace clothlab::bench {
namespace {

std::vector<double> positions(const Solver& solver) {
  std::vector<double> p;
  p.reserve(3 * solver.vertex_count());
  for (std::size_t i = 0; i < solver.vertex_count(); ++i)
    for (double c : solver.position(static_cast<int>(i))) p.push_back(c);
  return p;
}

// Steps `frames` frames of 1/60 s, adding the wall time of each to `times` (s).
void time_frames(Solver& solver, int frames, std::vector<double>& times) {
  for (int f = 0; f < frames; ++f) {
    const Stopwatch clock;
    solver.step(1);
    times.push_back(clock.seconds());
  }
}

// RMS distance of positions `a` from horizon h of the reference `ref`.
double rms(const std::vector<double>& a, const std::vector<double>& ref, int h) {
  const double* b = ref.data() + std::size_t(h) * a.size();
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / double(a.size() / 3));
}

}  // namespace

Scene realtime_sheet(int res, const RealtimeSetting& s, int threads, Precision precision) {
  SheetParams p;
  p.resolution = res;
  Scene scene = hanging_sheet(p, s.kind, kFrame);
  scene.solver.substeps = s.substeps;
  scene.solver.iterations = s.iterations;
  scene.solver.tethers = s.tethers;
  scene.solver.coarse_stretch = s.coarse;
  scene.solver.stretch_slack = s.slack;
  scene.solver.newton_iterations = s.newton;
  scene.solver.linear_solver = s.linear;
  if (s.newton_tolerance > 0.0) scene.solver.newton_tolerance = s.newton_tolerance;
  scene.solver.cg_tolerance = s.cg_tolerance;
  scene.solver.threads = threads;
  scene.solver.precision = precision;
  return scene;
}

std::vector<double> realtime_reference(int res, int threads, double dt, const std::string& path) {
  const std::size_t n = static_cast<std::size_t>(res) * res * 3;
  std::vector<double> p(kRealtimeHorizons * n);
  if (!path.empty()) {
    std::ifstream in(path, std::ios::binary);
    if (in.read(reinterpret_cast<char*>(p.data()), std::streamsize(p.size() * sizeof(double))))
      return p;
  }
  Scene scene = realtime_sheet(res, {"rk4", IntegratorKind::rk4}, threads, Precision::f64);
  scene.solver.dt = dt;
  auto solver = make_solver(scene);
  long done = 0;
  p.clear();
  for (int frames : kRealtimeHorizonFrames) {
    const long steps = std::lround(frames * kFrame / dt);
    solver->step(steps - done);
    done = steps;
    const std::vector<double> now = positions(*solver);
    p.insert(p.end(), now.begin(), now.end());
  }
  if (!path.empty()) {
    // Complete or absent: a cache file cut short would be read back as a reference.
    const std::string tmp = path + ".tmp";
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(p.data()), std::streamsize(p.size() * sizeof(double)));
    out.close();
    if (out) {
      std::rename(tmp.c_str(), path.c_str());
    } else {
      std::remove(tmp.c_str());
    }
  }
  return p;
}

RealtimeMeasured measure_realtime(Solver& solver, const std::vector<double>& reference) {
  RealtimeMeasured m;
  std::vector<double> times;
  for (int h = 0; h < kRealtimeHorizons; ++h) {
    time_frames(solver, kRealtimeHorizonFrames[h] - int(times.size()), times);
    m.rms[h] = rms(positions(solver), reference, h);
  }
  m.frame = median(times);
  return m;
}

double median_frame_seconds(Solver& solver, int frames) {
  std::vector<double> times;
  time_frames(solver, frames, times);
  return median(times);
}

}  // namespace clothlab::bench
