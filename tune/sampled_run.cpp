#include "tune/sampled_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "sim/solver.hpp"

namespace clothlab::tune {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Positions positions_of(const Solver& solver) {
  Positions p(solver.vertex_count());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = solver.position(int(i));
  return p;
}

}  // namespace

SampledRun run_sampled(const Scene& scene, const std::vector<double>& times, double wall_limit) {
  SampledRun run;
  std::unique_ptr<Solver> solver = make_solver(scene);
  // Steps are taken a 1/60 s frame at a time so that the limit is checked often enough.
  const long per_chunk = std::max(1L, std::lround((1.0 / 60.0) / solver->dt()));
  const auto start = std::chrono::steady_clock::now();
  for (double t : times) {
    const long target = std::lround(t / solver->dt());
    while (solver->step_count() < target) {
      const AdvanceResult a = solver->step(std::min(per_chunk, target - solver->step_count()));
      if (!a.ok()) {
        run.failure = "diverged: " + a.divergence->message();
        run.wall = seconds_since(start);
        return run;
      }
      if (wall_limit > 0.0 && seconds_since(start) > wall_limit) {
        run.timed_out = true;
        run.failure =
            "stopped at t = " + std::to_string(solver->time()) + " s: slower than the reference";
        run.wall = seconds_since(start);
        return run;
      }
    }
    run.at.push_back(positions_of(*solver));
    run.energy.push_back(solver->energy().total());
  }
  run.wall = seconds_since(start);
  return run;
}

Distance distance(const Positions& a, const Positions& b, std::vector<float>* per_vertex) {
  Distance d;
  if (per_vertex) per_vertex->resize(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c) d2 += (a[i][c] - b[i][c]) * (a[i][c] - b[i][c]);
    d.rms += d2;
    d.max = std::max(d.max, std::sqrt(d2));
    if (per_vertex) (*per_vertex)[i] = float(std::sqrt(d2));
  }
  d.rms = a.empty() ? 0.0 : std::sqrt(d.rms / double(a.size()));
  return d;
}

}  // namespace clothlab::tune
