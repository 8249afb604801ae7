// What does self-collision (sim/contact/self_collision.hpp) cost per solver step? The benchmark
// sheet (bench/bench_scenes.hpp: 2 m, default physics, symplectic Euler) with 10 substeps per
// step, folded into three layers one thickness apart (a Z fold along v; its tight creases set the
// sheet moving, which widens the query), at 64 x 64 and
// 128 x 128, on 1 and 2 threads:
//  - plain: a step with self-collision off;
//  - with: a step with it on;
//  - hash + query: SelfCollision::find_pairs alone (once per step), on the fresh fold at rest;
//  - response: SelfCollision::respond alone, times the 10 substeps, on the same.
// The thickness is 0.75 of the grid spacing (just above SelfCollision::min_thickness()).
//
//   build/release/bench/self_collision_bench
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "bench/bench_scenes.hpp"
#include "sim/core/passive_openmp.hpp"
#include "sim/solver_impl.hpp"

namespace clothlab {
namespace {

constexpr int kSubsteps = 10;

Scene folded_scene(int res, int threads, bool self) {
  Scene s = bench::sheet_scene(res, threads, true);
  s.solver.dt *= kSubsteps;
  s.solver.substeps = kSubsteps;
  s.solver.self_collision = self;
  s.solver.self_thickness = 0.75 * 2.0 / (res - 1);
  return s;
}

// Lays the sheet down in three horizontal layers `gap` apart in y (rows along z), joined by
// half-circle creases of diameter gap (a Z fold along v), at rest.
template <class T>
void fold(SolverT<T>& s, double gap) {
  constexpr double kPi = 3.14159265358979323846;
  const ClothRange& c = s.model().cloths[0];
  const double spacing = 2.0 / (c.nv - 1);
  const double r = 0.5 * gap, bend = kPi * r;  // a crease's radius and arc length
  const double flat = ((c.nv - 1) * spacing - 2.0 * bend) / 3.0;
  State<T>& st = s.state();
  for (int j = 0; j < c.nv; ++j) {
    double arc = j * spacing, y = 1.0, z = 0.0;
    for (int layer = 0; layer < 3; ++layer) {
      const double dir = layer % 2 == 0 ? 1.0 : -1.0, z0 = layer % 2 == 0 ? 0.0 : flat;
      if (arc <= flat || layer == 2) {
        z = z0 + dir * arc;
        break;
      }
      arc -= flat;
      if (arc <= bend) {  // on the crease at this layer's end
        const double a = arc / r - 0.5 * kPi;
        z = (z0 + dir * flat) + dir * r * std::cos(a);
        y += r + r * std::sin(a);
        break;
      }
      arc -= bend;
      y += gap;
    }
    for (int i = 0; i < c.nu; ++i) {
      const auto v = static_cast<std::size_t>(c.offset + i + j * c.nu);
      st.pos.set(v, T(-1.0 + i * spacing), T(y), T(z));
      st.vel.set(v, T(0), T(0), T(0));
    }
  }
  s.state_changed();
}

// The fastest of five batches of `calls` calls, per call: the machine is shared, and another
// program's time slice only ever adds.
template <class Fn>
double seconds_per_call(int calls, Fn&& fn) {
  double best = INFINITY;
  for (int batch = 0; batch < 5; ++batch) {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < calls; ++k) fn();
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    best = std::min(best, took.count() / calls);
  }
  return best;
}

void run(int res, int threads, int steps) {
  SolverT<float> plain(folded_scene(res, threads, false));
  const double gap = folded_scene(res, threads, true).solver.self_thickness;
  fold(plain, gap);
  plain.step(3);
  const double t_plain = seconds_per_call(steps, [&] { plain.step(1); });

  SolverT<float> with(folded_scene(res, threads, true));
  fold(with, gap);
  with.step(3);
  const double t_with = seconds_per_call(steps, [&] { with.step(1); });
  const SelfCollisionStats stats = with.self_collision()->last();

  // The parts alone, on a fresh fold.
  const Scene scene = folded_scene(res, threads, true);
  SolverT<float> parts(scene);
  fold(parts, 0.6 * gap);  // the layers' vertices are not above each other: a little closer
  SelfCollision<float> sc(parts.model(), scene.solver);
  const double h = parts.dt() / kSubsteps;
  const double t_query = seconds_per_call(
      steps, [&] { sc.find_pairs(parts.model(), parts.state(), parts.dt(), threads); });
  const double t_respond = kSubsteps * seconds_per_call(steps * kSubsteps, [&] {
                             sc.respond(parts.model(), parts.state(), h);
                           });
  std::printf(
      "%4dx%-4d %d thr | plain %7.3f ms | with %7.3f ms (x%.2f) | hash+query %6.3f ms (%4.1f%%) | "
      "response %6.3f ms (%4.1f%%) | pairs %d, radius %.1f mm (at rest %d), dropped %d\n",
      res, res, threads, 1e3 * t_plain, 1e3 * t_with, t_with / t_plain, 1e3 * t_query,
      100.0 * t_query / t_plain, 1e3 * t_respond, 100.0 * t_respond / t_plain, stats.pairs,
      1e3 * stats.query_radius, sc.last().pairs, stats.dropped);
}

}  // namespace
}  // namespace clothlab

int main(int /*argc*/, char** argv) {
  clothlab::prefer_passive_openmp(argv);
  std::printf("per solver step of %d substeps (float)\n", clothlab::kSubsteps);
  for (int res : {64, 128})
    for (int threads : {1, 2}) clothlab::run(res, threads, res == 64 ? 20 : 6);
}
