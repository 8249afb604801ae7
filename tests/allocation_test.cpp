// The step loop allocates nothing: global operator new is counted across many steps of every
// integrator, with every force (springs with damping, drag, gusty wind) on and two threads, and
// with self-collision and triangle contact on.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "allocation_counter.hpp"
#include "load/scene_load.hpp"
#include "sim/mesh/triangle_mesh.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

template <class T>
void expect_no_allocation(IntegratorKind kind) {
  Scene scene = testing::sheet(24, 1.0, 0.5, 400.0, kind, 2e-4);
  scene.cloths[0].pins = {{0, 0}, {23, 0}};
  scene.springs.damping = 0.02;
  scene.forces.drag = 0.001;
  scene.forces.wind = {true, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
  scene.solver.threads = 2;
  const auto s = testing::solver<T>(scene);
  ASSERT_TRUE(s->step(3).ok());  // warm-up: starts the OpenMP thread pool
  const long before = g_allocations.load();
  ASSERT_TRUE(s->step(200).ok());
  ASSERT_TRUE(s->advance(0.01).ok());
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in the step loop";
}

class StepLoop : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(StepLoop, AllocatesNothingInFloat) {
  expect_no_allocation<float>(GetParam());
}
TEST_P(StepLoop, AllocatesNothingInDouble) {
  expect_no_allocation<double>(GetParam());
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, StepLoop, ::testing::ValuesIn(kAllIntegrators),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

// The implicit methods with the multigrid preconditioner: its hierarchy is refreshed every
// Newton iteration and cycled every PCG iteration without allocating (a 40 x 40 sheet: three
// coarse levels and the dense coarsest solve).
TEST(StepLoop, MultigridImplicitStepsAllocateNothing) {
  for (IntegratorKind kind : {IntegratorKind::implicit_euler, IntegratorKind::bdf2}) {
    Scene scene = testing::sheet(40, 1.0, 0.2, 1000.0, kind, 1.0 / 60.0);
    scene.cloths[0].pins = {{0, 0}, {39, 0}};
    scene.springs.damping = 0.05;
    scene.solver.linear_solver = LinearSolver::multigrid;
    scene.solver.threads = 2;
    const auto s = testing::solver<float>(scene);
    ASSERT_TRUE(s->step(2).ok());
    const long before = g_allocations.load();
    ASSERT_TRUE(s->step(10).ok());
    EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in the step loop";
  }
}

// xpbd's grid path with tethers and coarse stretch levels (a 64 x 64 sheet gets one level;
// its own weight stretches it by 0.2 %).
TEST(StepLoop, XpbdWithTethersAndCoarseLevelsAllocatesNothing) {
  Scene scene = testing::sheet(64, 1.0, 0.2, 1000.0, IntegratorKind::xpbd, 1.0 / 60.0);
  scene.cloths[0].pins = {{0, 0}, {63, 0}};
  scene.solver.threads = 2;
  const auto s = testing::solver<float>(scene);
  ASSERT_TRUE(s->step(2).ok());
  const long before = g_allocations.load();
  ASSERT_TRUE(s->step(20).ok());
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in the step loop";
}

// Self-collision (sim/contact/self_collision.hpp) allocates its hash and pair buffers when the
// solver is built: a free sheet falling 2 cm in front of a hanging one, pairs found every step.
template <class T>
void expect_no_allocation_with_self_collision() {
  Scene scene = testing::sheet(24, 1.0, 0.5, 400.0, IntegratorKind::symplectic_euler, 2e-4);
  scene.cloths[0].pins = {{0, 0}, {23, 0}};
  scene.cloths[0].key = "cloth[0]";
  ClothSpec front = scene.cloths[0];
  front.origin[2] += 0.02;
  front.pins.clear();
  front.key = "cloth[1]";
  scene.cloths.push_back(front);
  scene.multi_cloth = true;
  scene.springs.damping = 0.02;
  scene.solver.substeps = 2;
  scene.solver.self_collision = true;
  scene.solver.self_thickness = 0.03;
  scene.solver.threads = 2;
  const auto s = testing::solver<T>(scene);
  ASSERT_TRUE(s->step(3).ok());
  const long before = g_allocations.load();
  ASSERT_TRUE(s->step(200).ok());
  ASSERT_TRUE(s->advance(0.01).ok());
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in the step loop";
  EXPECT_GT(s->last_self_collision()->pairs, 0);
}

TEST(StepLoop, SelfCollisionAllocatesNothingInFloat) {
  expect_no_allocation_with_self_collision<float>();
}
TEST(StepLoop, SelfCollisionAllocatesNothingInDouble) {
  expect_no_allocation_with_self_collision<double>();
}

// Triangle contact on the landed pile (scenes/pile.toml, 2 threads): its pair lists grow only
// when a tangle outgrows the largest they have held, so once the sheet lies in its folds a
// second of steps allocates nothing.
TEST(StepLoop, ClothContactAllocatesNothingOnceLanded) {
  const Scene scene =
      read_scene_file(std::string(CLOTHLAB_SOURCE_DIR "/scenes/pile.toml"), {"solver.threads=2"});
  const auto s = make_solver(scene);
  ASSERT_TRUE(s->advance(4.0).ok());
  const long before = g_allocations.load();
  ASSERT_TRUE(s->advance(1.0).ok());
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in the step loop";
  EXPECT_GT(s->last_cloth_contact()->candidates, 1000);
}

// A mesh cloth (the shipped round cloth, scaled to 0.24 m) falling across a thin rod: the
// neighbour-list kernel, area masses and the mesh's edge contacts, all sized when built.
TEST(StepLoop, MeshClothOnARodAllocatesNothing) {
  Scene scene;
  ClothSpec c;
  c.shape = "mesh";
  c.mesh = std::make_shared<const TriangleMesh>(
      load_obj(std::string(CLOTHLAB_SOURCE_DIR "/assets/meshes/round_cloth.obj"), 0.3));
  c.resolution = {static_cast<int>(c.mesh->positions.size()), 1};
  c.origin = {0.0, 0.02, 0.0};
  c.mass = 0.1;
  c.key = "cloth";
  scene.cloths.push_back(c);
  scene.springs.stiffness = 300.0;
  scene.solver.dt = 2e-4;
  scene.solver.threads = 2;
  ColliderSpec rod;
  rod.kind = ColliderKind::capsule;
  rod.a = {-0.5, 0.0, 0.0};
  rod.b = {0.5, 0.0, 0.0};
  rod.radius = 0.004;  // thinner than the cloth's edges: edge midpoints are contacts too
  rod.key = "colliders[0]";
  scene.colliders = {rod};
  const auto s = testing::solver<double>(scene);
  ASSERT_TRUE(s->step(3).ok());
  const long before = g_allocations.load();
  ASSERT_TRUE(s->step(400).ok());
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in the step loop";
  EXPECT_GT(s->last_contacts().contacts, 0);
}

// The sharp-feature contacts (sim/contact/feature_contacts.hpp) mark, search and push with
// storage sized when the solver is built: scenes/drop_box.toml's sheet lying on the crate's
// corners and edges allocates nothing over 400 steps on two threads.
TEST(StepLoop, ClothOnACrateAllocatesNothing) {
  Scene scene = read_scene_file(std::string(CLOTHLAB_SOURCE_DIR "/scenes/drop_box.toml"));
  scene.cloths[0].release_at = 0.0;
  scene.cloths[0].pins.clear();
  scene.solver.threads = 2;
  const auto s = make_solver(scene);
  ASSERT_TRUE(s->advance(0.5).ok());  // fallen onto the crate
  const long before = g_allocations.load();
  ASSERT_TRUE(s->step(400).ok());
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations in the step loop";
  EXPECT_GT(s->last_contacts().contacts, 0);
}

TEST(StepLoop, CounterSeesAllocations) {
  // The counter works: building a solver does allocate.
  const long before = g_allocations.load();
  const auto s =
      testing::solver<float>(testing::sheet(4, 1.0, 0.1, 100.0, IntegratorKind::verlet, 1e-4));
  EXPECT_GT(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace clothlab
