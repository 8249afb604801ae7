// What the grid-path tests (xpbd_grid_test.cpp, vbd_grid_test.cpp) share: a run of an integrator
// from disturbed() and the largest difference of two states.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>

#include "disturbed_state.hpp"
#include "test_scenes.hpp"

namespace clothlab::testing {

template <class T>
struct Outcome {
  State<T> state;
  double moved = 0.0;  // largest distance a vertex moved: the comparison is not of idle copies
};

// `steps` steps of h from disturbed() on the scene's model with `kernel`; make(model) gives the
// integrator.
template <class T, class Make>
Outcome<T> run_from_disturbed(const Scene& scene, SpringKernel kernel, int threads, int steps, T h,
                              Make&& make) {
  const Model<T> m = build_model<T>(scene, kernel);
  ForceWorkspace<T> ws;
  ws.resize(m);
  const System<T> sys{m, ws, threads};
  const std::unique_ptr<Integrator<T>> integrator = make(m);
  Outcome<T> r{disturbed(m)};
  const State<T> start = r.state;
  for (int k = 0; k < steps; ++k) integrator->step(sys, r.state, 0.01 * k, h);
  for (std::size_t i = 0; i < m.n; ++i)
    for (int a = 0; a < 3; ++a)
      r.moved = std::max(r.moved, double(std::abs(r.state.pos.axis(a)[i] - start.pos.axis(a)[i])));
  return r;
}

// The comparison both grid-path tests make: grid, the row-sweep model's integrator from
// make_grid(model); else the neighbour-list model's from make_list(model, grid_model), the list
// path told the grid path's order from the row-sweep model of the same scene.
template <class T, class MakeGrid, class MakeList>
Outcome<T> run_grid_or_list(const Scene& scene, bool grid, int threads, int steps, T h,
                            MakeGrid&& make_grid, MakeList&& make_list) {
  const SpringKernel kernel = grid ? SpringKernel::row_sweep : SpringKernel::neighbour_list;
  return run_from_disturbed<T>(
      scene, kernel, threads, steps, h, [&](const Model<T>& m) -> std::unique_ptr<Integrator<T>> {
        if (grid) return make_grid(m);
        return make_list(m, build_model<T>(scene, SpringKernel::row_sweep));
      });
}

template <class T>
double largest_difference(const State<T>& a, const State<T>& b, bool velocity) {
  double worst = 0.0;
  const Vec3Array<T>& pa = velocity ? a.vel : a.pos;
  const Vec3Array<T>& pb = velocity ? b.vel : b.pos;
  for (int c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < pa.size(); ++i)
      worst = std::max(worst, double(std::abs(pa.axis(c)[i] - pb.axis(c)[i])));
  return worst;
}

}  // namespace clothlab::testing
