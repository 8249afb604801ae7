// solver.backend = "gpu" (gpu/backend_solver.hpp) runs the same physics as the CPU solver: wind
// with gusts, pins that let go, a grab, a push and a sphere to land on all give the CPU's motion
// within float round-off (the library's CPU kernel fuses multiply-adds under -march=native, the
// shaders do not, so the comparison has a tolerance; tests/gpu_cloth_test.cpp shows the two are
// bit-identical without contraction). Copies of the cloth move as the original does, a scene the
// GPU cannot run falls back to the CPU with a reason, and divergence is still caught.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "apps/view/sim_session.hpp"
#include "factory/solver_factory.hpp"
#include "gl_context_fixture.hpp"
#include "gpu/backend_solver.hpp"
#include "render_frame.hpp"
#include "sim/cloth/scene_copies.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
namespace {

constexpr int kGpuSolverRes = 24;

// A 1 m hanging sheet (0.3 kg, 300 N/m, damped, drag) pinned at its top corners.
Scene gpu_hanging(IntegratorKind kind) {
  Scene s = testing::sheet(kGpuSolverRes, 1.0, 0.3, 300.0, kind, 1e-3);
  s.cloths[0].origin = {-0.5, 1.5, 0.0};
  s.cloths[0].pins = {{0, 0}, {kGpuSolverRes - 1, 0}};
  s.springs.damping = 0.05;
  s.forces.drag = 0.005;
  s.solver.dt_auto = true;
  return s;
}

// Wind across the sheet with gusts: the force depends on the surface normals, the velocities and
// the seeded noise, all of which the GPU must reproduce.
Scene windy(IntegratorKind kind) {
  Scene s = gpu_hanging(kind);
  s.forces.wind.enabled = true;
  s.forces.wind.velocity = {2.0, 0.0, 3.0};
  s.forces.wind.gust = 0.6;
  s.forces.wind.seed = 11;
  s.forces.wind.gust_period = 0.05;  // several gusts over the run
  s.forces.wind.coefficient = 1.5;
  return s;
}

struct Difference {
  double position = 0.0, velocity = 0.0, pinned = 0.0;
};

Difference compare(const Solver& a, const Solver& b) {
  Difference d;
  for (int i = 0; i < static_cast<int>(a.vertex_count()); ++i) {
    const Vec3d pa = a.position(i), pb = b.position(i), va = a.velocity(i), vb = b.velocity(i);
    const double dp = std::hypot(pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]);
    d.position = std::max(d.position, dp);
    d.velocity = std::max(d.velocity, std::hypot(va[0] - vb[0], va[1] - vb[1], va[2] - vb[2]));
    if (a.pinned(i)) d.pinned = std::max(d.pinned, dp);
  }
  return d;
}

double largest_move(const Solver& a, const Solver& b) {
  return compare(a, b).position;
}

class GpuSolverTest : public testing::GlContextTest {
 protected:
  static void wind_follows_the_cpu(IntegratorKind kind) {
    const Scene scene = windy(kind);
    const auto cpu_owner = testing::solver<float>(scene, SpringKernel::neighbour_list);
    Solver& cpu = *cpu_owner;
    const auto gpu_owner = gpu::make_gpu_solver(scene);
    Solver& gpu = *gpu_owner;
    ASSERT_EQ(gpu.dt(), cpu.dt());
    ASSERT_TRUE(cpu.step(200).ok());
    ASSERT_TRUE(gpu.step(200).ok());
    const Difference d = compare(cpu, gpu);
    std::printf("%s, gusty wind, 200 steps: positions %.2e m, velocities %.2e m/s\n",
                to_string(kind), d.position, d.velocity);
    EXPECT_LT(d.position, 1e-5);
    EXPECT_LT(d.velocity, 1e-3);
    EXPECT_EQ(d.pinned, 0.0);
    // The wind did move the sheet: without it the GPU's sheet is somewhere else.
    const auto calm_owner = testing::solver<float>(gpu_hanging(kind), SpringKernel::neighbour_list);
    Solver& calm = *calm_owner;
    ASSERT_TRUE(calm.step(200).ok());
    EXPECT_GT(largest_move(calm, gpu), 1e-3);
  }
};

TEST_F(GpuSolverTest, GustyWindFollowsTheCpuWithSymplecticEuler) {
  wind_follows_the_cpu(IntegratorKind::symplectic_euler);
}

TEST_F(GpuSolverTest, GustyWindFollowsTheCpuWithVerlet) {
  wind_follows_the_cpu(IntegratorKind::verlet);
}

// The GPU's force field (arrows, probes) is the CPU's at the same state: gusts included, so the
// noise hash is the CPU's to the bit pattern (a wrong lattice value changes a force by tens of %).
TEST_F(GpuSolverTest, ForceFieldEqualsTheCpusAtTheSameState) {
  const Scene scene = windy(IntegratorKind::symplectic_euler);
  const auto gpu_owner = gpu::make_gpu_solver(scene);
  Solver& gpu = *gpu_owner;
  ASSERT_TRUE(gpu.step(150).ok());
  const auto cpu_owner = testing::solver<float>(scene, SpringKernel::neighbour_list);
  Solver& cpu = *cpu_owner;
  cpu.load_state(gpu);
  ASSERT_EQ(cpu.time(), gpu.time());
  gpu.update_force_field();
  cpu.update_force_field();
  double worst = 0.0, largest = 0.0;
  for (int i = 0; i < static_cast<int>(gpu.vertex_count()); ++i) {
    const Vec3d a = gpu.force(i), b = cpu.force(i);
    worst = std::max(worst, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    largest = std::max(largest, std::hypot(a[0], a[1], a[2]));
  }
  std::printf("force field: largest %.3e N, difference %.2e N\n", largest, worst);
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(worst, 1e-4 * largest);
  // One source alone comes from the CPU's code on the GPU's state.
  gpu.update_force_field(ForceSource::wind);
  cpu.update_force_field(ForceSource::wind);
  EXPECT_EQ(gpu.force_field_source(), ForceSource::wind);
  EXPECT_NEAR(gpu.force(kGpuSolverRes * kGpuSolverRes / 2)[2],
              cpu.force(kGpuSolverRes * kGpuSolverRes / 2)[2], 1e-6);
}

// Release at 0.05 s, a push at 0.08 s and a grab from 0.1 s on: the CPU-side parts of the step
// act on the GPU's state (`backend`: compute or transform feedback) as they act on the CPU's.
void release_push_and_grab(Backend backend) {
  Scene scene = windy(IntegratorKind::symplectic_euler);
  scene.cloths[0].release_at = 0.05;
  scene.solver.backend = backend;
  const auto cpu_owner = testing::solver<float>(scene, SpringKernel::neighbour_list);
  Solver& cpu = *cpu_owner;
  const auto gpu_owner = gpu::make_gpu_solver(scene);
  Solver& gpu = *gpu_owner;
  EXPECT_STREQ(backend_name(gpu), backend == Backend::gpu ? "GPU" : "GPU transform feedback");
  const auto steps_to = [&](double t) { return std::lround(t / cpu.dt()); };
  for (Solver* s : {static_cast<Solver*>(&cpu), static_cast<Solver*>(&gpu)}) {
    ASSERT_TRUE(s->step(steps_to(0.08)).ok());
    EXPECT_TRUE(s->pins_released());
    s->apply_impulse({0.0, 1.0, 0.0}, 0.3, {0.0, 0.0, 0.05});
    ASSERT_TRUE(s->step(steps_to(0.02)).ok());
    ASSERT_TRUE(s->grab(kGpuSolverRes / 2, {0.2, 1.6, 0.3}));
    ASSERT_TRUE(s->step(steps_to(0.05)).ok());
  }
  const Difference d = compare(cpu, gpu);
  std::printf("release, push, grab: positions %.2e m, velocities %.2e m/s\n", d.position,
              d.velocity);
  EXPECT_LT(d.position, 1e-5);
  EXPECT_LT(d.velocity, 1e-3);
  // The corners let go (they left their pins); the grabbed vertex went towards the hand.
  const Vec3d corner = gpu.position(0);
  EXPECT_GT(std::hypot(corner[0] + 0.5, corner[1] - 1.5, corner[2]), 0.01);
  const Vec3d g = gpu.position(kGpuSolverRes / 2);
  EXPECT_LT(std::hypot(g[0] - 0.2, g[1] - 1.6, g[2] - 0.3), 0.1);
  gpu.reset();
  EXPECT_FALSE(gpu.pins_released());
  EXPECT_EQ(gpu.position(0)[1], 1.5);
  ASSERT_TRUE(gpu.step(10).ok());
  EXPECT_EQ(gpu.position(0)[1], 1.5);  // pinned again on the GPU too
}

// A sheet dropped onto a sphere (`backend`: compute or transform feedback): the collision
// response runs on the CPU around every substep.
// Contact with friction amplifies round-off (stick or slip is a threshold): the two runs agree to
// 1e-7 m until the sheet lands at about 0.3 s and to 1e-4 m some 50 ms later, so the comparison
// is made 30 ms after landing, and afterwards on what does not depend on round-off.
void drop_onto_a_sphere(Backend backend) {
  Scene scene = gpu_hanging(IntegratorKind::symplectic_euler);
  scene.solver.backend = backend;
  scene.cloths[0].origin = {-0.5, 0.8, -0.5};
  scene.cloths[0].v_axis = {0.0, 0.0, 1.0};
  scene.cloths[0].pins.clear();
  ColliderSpec ball;
  ball.kind = ColliderKind::sphere;
  ball.center = {0.0, 0.4, 0.0};
  ball.radius = 0.25;
  ball.key = "colliders[0]";
  scene.colliders.push_back(ball);
  const auto cpu_owner = testing::solver<float>(scene, SpringKernel::neighbour_list);
  Solver& cpu = *cpu_owner;
  const auto gpu_owner = gpu::make_gpu_solver(scene);
  Solver& gpu = *gpu_owner;
  EXPECT_STREQ(backend_name(gpu), backend == Backend::gpu ? "GPU" : "GPU transform feedback");
  long landed = -1;  // the step of the first contact
  long steps = 0;
  const long end = std::lround(0.6 / cpu.dt());
  const auto centroid_y = [](const Solver& s) {
    double y = 0.0;
    for (int i = 0; i < static_cast<int>(s.vertex_count()); ++i) y += s.position(i)[1];
    return y / static_cast<double>(s.vertex_count());
  };
  while (steps < end) {
    ASSERT_TRUE(cpu.step(1).ok());
    ASSERT_TRUE(gpu.step(1).ok());
    ++steps;
    if (landed < 0) {
      ASSERT_EQ(gpu.last_contacts().contacts, cpu.last_contacts().contacts) << steps;
      if (gpu.last_contacts().contacts > 0) landed = steps;
    } else if (steps == landed + std::lround(0.03 / cpu.dt())) {
      const Difference d = compare(cpu, gpu);
      std::printf("drop onto a sphere, 30 ms after landing (step %ld): positions %.2e m\n", steps,
                  d.position);
      EXPECT_LT(d.position, 1e-5);
    }
  }
  ASSERT_GT(landed, 0);
  // Draped over the ball alike, nothing inside it.
  std::printf("after 0.6 s: centroid height %.5f m (CPU) %.5f m (GPU)\n", centroid_y(cpu),
              centroid_y(gpu));
  EXPECT_NEAR(centroid_y(gpu), centroid_y(cpu), 2e-3);
  double nearest = INFINITY;
  for (int i = 0; i < static_cast<int>(gpu.vertex_count()); ++i) {
    const Vec3d p = gpu.position(i);
    nearest = std::min(nearest, std::hypot(p[0], p[1] - 0.4, p[2]));
  }
  EXPECT_GT(nearest, ball.radius);
  EXPECT_LT(nearest, ball.radius + 2 * ball.thickness);
}

// Both GPU paths share the CPU-side parts of the step (sim/step_backend.hpp).
class GpuBackends : public GpuSolverTest, public ::testing::WithParamInterface<Backend> {};

TEST_P(GpuBackends, ReleasePushAndGrabActAsOnTheCpu) {
  release_push_and_grab(GetParam());
}

TEST_P(GpuBackends, DropOntoASphereFollowsTheCpu) {
  drop_onto_a_sphere(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Paths, GpuBackends,
                         ::testing::Values(Backend::gpu, Backend::transform_feedback),
                         [](const auto& case_info) {
                           return std::string(to_string(case_info.param));
                         });

TEST_F(GpuSolverTest, ScenesTheGpuCannotRunStayOnTheCpuWithAReason) {
  std::string note;
  Scene scene = gpu_hanging(IntegratorKind::symplectic_euler);
  EXPECT_EQ(make_backend_solver(scene, note)->device_cloth(), nullptr);
  EXPECT_EQ(note, "");
  scene.solver.backend = Backend::gpu;
  EXPECT_NE(make_backend_solver(scene, note)->device_cloth(), nullptr);
  EXPECT_EQ(note, "");
  scene.solver.integrator = IntegratorKind::rk4;
  EXPECT_EQ(make_backend_solver(scene, note)->device_cloth(), nullptr);
  EXPECT_EQ(note,
            "solver.backend = \"gpu\": the GPU step runs symplectic_euler and verlet, not rk4; the "
            "cloth steps on the CPU");
  scene.solver.integrator = IntegratorKind::verlet;
  scene.solver.precision = Precision::f64;
  EXPECT_EQ(make_backend_solver(scene, note)->device_cloth(), nullptr);
  EXPECT_NE(note.find("float, not double"), std::string::npos);
}

// The panel's CPU / GPU switch (SimSession::apply_dynamics with the window's factory) carries the
// running motion over, both ways; a choice the GPU cannot run stays on the CPU with the reason.
TEST_F(GpuSolverTest, PanelSwitchCarriesTheMotionOver) {
  vis::SimSession session(windy(IntegratorKind::symplectic_euler), make_backend_solver);
  const FrameStepper stepper;
  for (int f = 0; f < 5; ++f) session.advance(stepper, 1.0 / 60.0);
  const double t = session.solver().time();
  const Vec3d p = session.solver().position(kGpuSolverRes * kGpuSolverRes - 1);
  session.draft().solver.backend = Backend::gpu;
  session.apply_dynamics();
  ASSERT_NE(session.solver().device_cloth(), nullptr);
  EXPECT_EQ(session.backend_note(), "");
  EXPECT_EQ(session.solver().time(), t);
  EXPECT_EQ(session.solver().position(kGpuSolverRes * kGpuSolverRes - 1), p);
  for (int f = 0; f < 5; ++f) session.advance(stepper, 1.0 / 60.0);
  EXPECT_GT(session.solver().time(), t);
  const Vec3d q = session.solver().position(kGpuSolverRes * kGpuSolverRes - 1);
  session.draft().solver.backend = Backend::cpu;
  session.apply_dynamics();
  EXPECT_EQ(session.solver().device_cloth(), nullptr);
  EXPECT_EQ(session.solver().position(kGpuSolverRes * kGpuSolverRes - 1), q);
  session.draft().solver.backend = Backend::gpu;
  session.draft().solver.integrator = IntegratorKind::rk4;
  session.apply_dynamics();
  EXPECT_EQ(session.solver().device_cloth(), nullptr);
  EXPECT_NE(session.backend_note().find("not rk4"), std::string::npos);
}

// Twice the stable step: the checks on the GPU's state stop the run with a report.
TEST_F(GpuSolverTest, DivergenceIsCaught) {
  Scene scene = gpu_hanging(IntegratorKind::symplectic_euler);
  scene.solver.dt_auto = false;
  scene.solver.dt = 0.02;
  const auto gpu_owner = gpu::make_gpu_solver(scene);
  Solver& gpu = *gpu_owner;
  AdvanceResult r;
  for (int k = 0; k < 50 && r.ok(); ++k) r = gpu.step(20);
  ASSERT_FALSE(r.ok());
  EXPECT_FALSE(r.divergence->quantity.empty());
  EXPECT_FALSE(gpu.step(1).ok());  // stays stopped until reset
}

// Four copies of a drop onto a sphere on the GPU: every copy moves as the original, shifted.
TEST_F(GpuSolverTest, CopiesMoveAsTheOriginal) {
  Scene scene = gpu_hanging(IntegratorKind::verlet);
  scene.cloths[0].origin = {-0.5, 0.8, -0.5};
  scene.cloths[0].v_axis = {0.0, 0.0, 1.0};
  scene.cloths[0].pins = {{0, 0}};
  ColliderSpec ball;
  ball.center = {0.0, 0.4, 0.0};
  ball.radius = 0.25;
  ball.key = "colliders[0]";
  scene.colliders.push_back(ball);
  constexpr int kCopies = 4;
  constexpr double kSpacing = 2.0;  // a power of two: the offsets add no rounding of their own
  const auto gpu_owner = gpu::make_gpu_solver(with_copies(scene, kCopies, kSpacing));
  Solver& gpu = *gpu_owner;
  ASSERT_EQ(gpu.vertex_count(), std::size_t(kCopies * kGpuSolverRes * kGpuSolverRes));
  ASSERT_TRUE(gpu.step(300).ok());
  const int n = kGpuSolverRes * kGpuSolverRes;
  double worst = 0.0;
  for (int k = 1; k < kCopies; ++k) {
    const Vec3d off = copy_offset(k, kCopies, kSpacing);
    for (int i = 0; i < n; ++i) {
      const Vec3d a = gpu.position(i), b = gpu.position(k * n + i);
      worst = std::max(worst, std::hypot(b[0] - off[0] - a[0], b[1] - a[1], b[2] - off[2] - a[2]));
    }
  }
  std::printf("4 copies on the GPU after 300 steps: largest difference from the original %.2e m\n",
              worst);
  EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace clothlab

namespace clothlab {
namespace {

// The renderer draws the GPU backend's cloth from its buffers (shaders/cloth_pack.comp) as it
// draws the CPU's from uploads: the same state rendered both ways gives the same pixels, and the
// probe reads the GPU's force field as it reads the CPU's. The headless renderer binds its own
// framebuffer object before drawing (a surfaceless EGL context has no default framebuffer).
TEST(GpuSolverRender, DrawsAndProbesTheGpuStateAsTheCpus) {
  vis::HeadlessRenderer renderer(320, 240);  // its context is current from here on
  const Scene scene = windy(IntegratorKind::symplectic_euler);
  const auto gpu_owner = gpu::make_gpu_solver(scene);
  Solver& gpu = *gpu_owner;
  const auto cpu_owner = testing::solver<float>(scene, SpringKernel::neighbour_list);
  Solver& cpu = *cpu_owner;
  renderer.set_cloth(gpu);
  vis::ViewSettings view = vis::scene_view(scene, gpu);
  const std::vector<std::uint8_t> rest = test::render_frame(renderer, gpu, view);
  ASSERT_TRUE(gpu.step(300).ok());
  cpu.load_state(gpu);
  const auto [same_size, worst, moved] = test::compare_with_cpu(renderer, gpu, cpu, view, rest);
  ASSERT_TRUE(same_size);
  std::printf(
      "GPU-drawn against CPU-drawn frame: largest channel difference %d; %ld channels "
      "differ from the rest frame\n",
      worst, moved);
  EXPECT_LE(worst, 2);
  EXPECT_GT(moved, 1000);  // the frame shows the moved cloth, not the rest state

  const auto a = test::probe_frame(renderer, cpu, view, 160, 120);
  renderer.set_cloth(gpu);
  const auto b = test::probe_frame(renderer, gpu, view, 160, 120);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->vertex, b->vertex);
  EXPECT_LT(glm::length(a->force - b->force), 1e-4f * std::max(1.0f, glm::length(a->force)));
  EXPECT_LT(glm::length(a->velocity - b->velocity), 1e-5f);
}

}  // namespace
}  // namespace clothlab
