// The explicit integrators update a grid cloth's rows inside the force sweep
// (sim/forces/fused_band_pass.hpp). That must be the same step, bit for bit, as the force pass
// followed by the update, on every stencil edge case and thread count: the first tests take
// symplectic Euler's unfused step by hand (compute_forces, then the rule on every vertex), the
// next every explicit method with System::fuse off.
#include <gtest/gtest.h>

#include <cmath>

#include "disturbed_state.hpp"
#include "sim/forces/fused_band_pass.hpp"
#include "sim/integrators/integrator.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

// Symplectic Euler as SymplecticEulerRule has it: v += dt a, x += dt v.
template <class T>
void unfused_step(const Model<T>& m, ForceWorkspace<T>& ws, State<T>& s, T dt) {
  Vec3Array<T> f;
  f.resize(m.n);
  compute_forces(m, 0.0, s.pos, s.vel, f, ws, 1);
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < m.n; ++i) {
      T& v = s.vel.axis(a)[i];
      v += dt * (f.axis(a)[i] * m.inv_mass[i]);
      s.pos.axis(a)[i] += dt * v;
    }
  }
}

template <class T>
void expect_same_bits(Scene scene, int threads) {
  scene.solver.integrator = IntegratorKind::symplectic_euler;
  const Model<T> m = build_model<T>(scene);
  ASSERT_TRUE(band_pass_fusable(m));
  ForceWorkspace<T> ws;
  ws.resize(m);
  const System<T> sys{m, ws, threads};
  const auto integrator = make_integrator<T>(m, scene.solver);
  State<T> fused = disturbed(m), by_hand = fused;
  const T dt = T(1e-4);
  for (int k = 0; k < 3; ++k) {
    integrator->step(sys, fused, 0.0, dt);
    unfused_step(m, ws, by_hand, dt);
  }
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < m.n; ++i) {
      ASSERT_EQ(fused.pos.axis(a)[i], by_hand.pos.axis(a)[i]) << "vertex " << i << " axis " << a;
      ASSERT_EQ(fused.vel.axis(a)[i], by_hand.vel.axis(a)[i]) << "vertex " << i << " axis " << a;
    }
  }
  // The step moved the cloth: the comparison is not between two untouched copies.
  EXPECT_NE(fused.pos.x[m.n - 1], m.rest_positions.x[m.n - 1]);
}

TEST(FusedStep, SameBitsAsForcesThenUpdateInFloat) {
  for (const Scene& s : testing::band_edge_cases())
    for (int threads : {1, 2, 3}) expect_same_bits<float>(s, threads);
}

TEST(FusedStep, SameBitsAsForcesThenUpdateInDouble) {
  for (const Scene& s : testing::band_edge_cases())
    for (int threads : {1, 2, 3}) expect_same_bits<double>(s, threads);
}

// Every integrator that updates inside the sweep (System::forces_then) against the same
// integrator making two passes (System::fuse = false), a few steps from a disturbed state.
template <class T>
void expect_fused_equals_two_passes(const Scene& base, IntegratorKind kind, int threads) {
  Scene scene = base;
  scene.solver.integrator = kind;
  const Model<T> m = build_model<T>(scene);
  ForceWorkspace<T> ws;
  ws.resize(m);
  System<T> fused{m, ws, threads}, two_passes{m, ws, threads};
  two_passes.fuse = false;
  const auto a = make_integrator<T>(m, scene.solver), b = make_integrator<T>(m, scene.solver);
  State<T> sa = disturbed(m), sb = sa;
  for (int k = 0; k < 3; ++k) {
    a->step(fused, sa, 0.0, T(1e-4));
    b->step(two_passes, sb, 0.0, T(1e-4));
  }
  for (int c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < m.n; ++i) {
      ASSERT_EQ(sa.pos.axis(c)[i], sb.pos.axis(c)[i]) << to_string(kind) << " vertex " << i;
      ASSERT_EQ(sa.vel.axis(c)[i], sb.vel.axis(c)[i]) << to_string(kind) << " vertex " << i;
    }
  }
}

TEST(FusedStep, EveryExplicitMethodSameBitsAsTwoPasses) {
  using K = IntegratorKind;
  for (const Scene& s : testing::band_edge_cases()) {
    for (K kind : {K::explicit_euler, K::symplectic_euler, K::seed_hack, K::verlet, K::rk4}) {
      for (int threads : {1, 3}) {
        expect_fused_equals_two_passes<float>(s, kind, threads);
        expect_fused_equals_two_passes<double>(s, kind, threads);
      }
    }
  }
}

// The wind needs every normal before any force, so a windy scene keeps the two passes.
TEST(FusedStep, WindKeepsTheSeparatePasses) {
  Scene s = testing::grid_sheet(8, 8);
  s.forces.wind.enabled = true;
  s.forces.wind.velocity = {3.0, 0.0, 1.0};
  EXPECT_FALSE(band_pass_fusable(build_model<float>(s)));
  s.forces.wind.velocity = {0.0, 0.0, 0.0};  // calm air exerts nothing
  EXPECT_TRUE(band_pass_fusable(build_model<float>(s)));
  EXPECT_FALSE(band_pass_fusable(
      build_model<float>(testing::grid_sheet(8, 8), SpringKernel::neighbour_list)));
}

}  // namespace
}  // namespace clothlab
