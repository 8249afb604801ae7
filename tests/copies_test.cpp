// Copies of the cloth (the window's [ and ], sim/cloth/scene_copies.hpp): each copy of a drop
// onto a sphere moves exactly as the original, shifted; the window's session keeps the simulated
// time per frame whatever the number of copies; scenes that cannot be copied say why.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "apps/view/sim_session.hpp"
#include "sim/cloth/scene_copies.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

constexpr int kCopiesRes = 16;

// A horizontal 1 m sheet held at one corner above a ball, released at rest.
Scene copies_drop(IntegratorKind kind) {
  Scene s = testing::sheet(kCopiesRes, 1.0, 0.3, 300.0, kind, 1e-3);
  s.cloths[0].origin = {-0.5, 0.8, -0.5};
  s.cloths[0].v_axis = {0.0, 0.0, 1.0};
  s.cloths[0].pins = {{0, 0}};
  s.springs.damping = 0.05;
  s.solver.dt_auto = true;
  ColliderSpec ball;
  ball.center = {0.0, 0.4, 0.0};
  ball.radius = 0.25;
  ball.key = "colliders[0]";
  s.colliders.push_back(ball);
  ColliderSpec floor;
  floor.kind = ColliderKind::plane;
  floor.key = "colliders[1]";
  s.colliders.push_back(floor);
  return s;
}

TEST(Copies, LayOutOnASquareGridAndShareThePlanes) {
  const Scene one = copies_drop(IntegratorKind::symplectic_euler);
  const Scene five = with_copies(one, 5, 2.0);
  ASSERT_EQ(five.cloths.size(), 5u);
  ASSERT_EQ(five.colliders.size(), 2u + 4u);  // the floor once, a ball per copy
  // 5 copies: 3 columns; copy 4 is the second of row 1.
  EXPECT_EQ(copy_offset(4, 5, 2.0), (Vec3d{2.0, 0.0, -2.0}));
  EXPECT_EQ(five.cloths[4].origin, (Vec3d{-0.5 + 2.0, 0.8, -0.5 - 2.0}));
  EXPECT_EQ(five.colliders[5].center, (Vec3d{2.0, 0.4, -2.0}));
  EXPECT_EQ(five.cloths[4].pins, one.cloths[0].pins);
  EXPECT_EQ(with_copies(one, 1, 2.0).cloths.size(), 1u);
}

// Largest distance of copy k's vertices from the original's, shifted by copy k's offset.
double from_original(const Solver& single, const Solver& many, int k, int copies) {
  const int n = kCopiesRes * kCopiesRes;
  const Vec3d off = copy_offset(k, copies, 2.0);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec3d a = single.position(i), b = many.position(k * n + i);
    worst = std::max(worst, std::hypot(b[0] - off[0] - a[0], b[1] - a[1], b[2] - off[2] - a[2]));
  }
  return worst;
}

double centroid_y(const Solver& s, int first, int count) {
  double y = 0.0;
  for (int i = first; i < first + count; ++i) y += s.position(i)[1];
  return y / count;
}

// The drop with 4 copies against the original alone. The first copy sits where the original
// does and is bit-identical to it all the way; the others sit at other coordinates, so their
// round-off differs: within 1e-5 m as they fall (0.15 s), after which contact with friction
// amplifies round-off (stick or slip is a threshold) and they drape alike rather than identically.
TEST(Copies, EachCopyMovesAsTheOriginal) {
  for (const IntegratorKind kind : {IntegratorKind::symplectic_euler, IntegratorKind::verlet}) {
    const Scene one = copies_drop(kind);
    constexpr int kCopies = 4;
    const int n = kCopiesRes * kCopiesRes;
    auto single = make_solver(one);
    auto many = make_solver(with_copies(one, kCopies, 2.0));
    ASSERT_EQ(many->dt(), single->dt());
    const long fall = std::lround(0.15 / single->dt()), rest = std::lround(0.35 / single->dt());
    ASSERT_TRUE(single->step(fall).ok());
    ASSERT_TRUE(many->step(fall).ok());
    double worst = 0.0;
    for (int k = 0; k < kCopies; ++k)
      worst = std::max(worst, from_original(*single, *many, k, kCopies));
    std::printf("%s: 4 copies after 0.15 s, largest difference from the original %.2e m\n",
                to_string(kind), worst);
    EXPECT_LT(worst, 1e-5);
    ASSERT_TRUE(single->step(rest).ok());
    ASSERT_TRUE(many->step(rest).ok());
    EXPECT_EQ(from_original(*single, *many, 0, kCopies), 0.0);
    for (int k = 1; k < kCopies; ++k)
      EXPECT_NEAR(centroid_y(*many, k * n, n), centroid_y(*single, 0, n), 2e-3) << k;
    // The copies did fall onto their balls (a test of copies standing still would pass anyway).
    EXPECT_LT(centroid_y(*many, 3 * n, n), 0.6);
  }
}

// The session's simulated time per frame does not depend on the copies: the same frames of wall
// time give the same simulated time with 1, 4 and 16 copies.
TEST(Copies, SimulatedTimePerFrameIsTheSameForAnyCount) {
  double simulated[3] = {};
  const int counts[3] = {1, 4, 16};
  for (int c = 0; c < 3; ++c) {
    vis::SimSession session(copies_drop(IntegratorKind::symplectic_euler));
    ASSERT_EQ(session.set_copies(counts[c]), "");
    ASSERT_EQ(session.copies(), counts[c]);
    ASSERT_EQ(session.solver().vertex_count(), std::size_t(counts[c] * kCopiesRes * kCopiesRes));
    ASSERT_EQ(session.scene().cloths.size(), std::size_t(counts[c]));
    const FrameStepper stepper;
    for (int f = 0; f < 20; ++f) session.advance(stepper, 1.0 / 60.0);
    simulated[c] = session.solver().time();
  }
  EXPECT_NEAR(simulated[0], 20.0 / 60.0, 1e-3 + 1e-9);  // within one step of real time
  EXPECT_EQ(simulated[1], simulated[0]);
  EXPECT_EQ(simulated[2], simulated[0]);
}

TEST(Copies, SessionClampsAndRestarts) {
  vis::SimSession session(copies_drop(IntegratorKind::symplectic_euler));
  session.advance(FrameStepper(), 0.05);
  ASSERT_GT(session.solver().time(), 0.0);
  const long generation = session.generation();
  ASSERT_EQ(session.set_copies(2), "");
  EXPECT_EQ(session.solver().time(), 0.0);
  EXPECT_GT(session.generation(), generation);
  ASSERT_EQ(session.set_copies(1000), "");
  EXPECT_EQ(session.copies(), vis::SimSession::kMaxCopies);
  ASSERT_EQ(session.set_copies(0), "");
  EXPECT_EQ(session.copies(), 1);
  // Reset keeps the copies.
  ASSERT_EQ(session.set_copies(4), "");
  session.reset();
  EXPECT_EQ(session.solver().cloths().size(), 4u);
}

TEST(Copies, ScenesThatCannotBeCopiedSayWhy) {
  Scene s = copies_drop(IntegratorKind::symplectic_euler);
  s.mannequin.emplace();
  EXPECT_EQ(copies_unsupported_reason(s),
            "the mannequin is one body: a scene with a mannequin is not copied");
  EXPECT_THROW(with_copies(s, 2, 2.0), std::invalid_argument);
  EXPECT_EQ(with_copies(s, 1, 2.0).cloths.size(), 1u);
  Scene follow = copies_drop(IntegratorKind::symplectic_euler);
  follow.cloths[0].pins_follow = {0};
  EXPECT_NE(copies_unsupported_reason(follow).find("pins_follow"), std::string::npos);
}

// Copies past kParallelMinVertices (32 copies of 16x16 = 8192 vertices) hand the thread count to
// the measured trial: one thread first, then the parallel setting, and the faster is kept; a
// busy machine's slow parallel step keeps one thread. M is the user's choice and ends the trial;
// a small cloth never runs one.
TEST(Copies, ManyCopiesMeasureWhichThreadCountIsFaster) {
  Scene scene = copies_drop(IntegratorKind::symplectic_euler);
  scene.solver.threads = 0;  // automatic, as the shipped scenes
  vis::SimSession session(scene);
  EXPECT_EQ(session.thread_trial(), nullptr);
  EXPECT_FALSE(session.parallel());
  ASSERT_EQ(session.set_copies(32), "");
  ASSERT_GE(session.solver().vertex_count(), kParallelMinVertices);
  ASSERT_NE(session.thread_trial(), nullptr);
  EXPECT_FALSE(session.parallel());  // the trial starts on one thread
  double now = 0.0;
  for (int f = 0; f < 100 && session.thread_trial()->trying(); ++f, now += 1.0 / 60.0)
    session.measured_frame(10, session.parallel() ? 28e-3 : 1.4e-3, now);  // busy: 20x slower
  EXPECT_FALSE(session.thread_trial()->trying());
  EXPECT_FALSE(session.parallel());
  EXPECT_EQ(session.solver().threads(), 1);
  session.toggle_parallel();  // M
  EXPECT_EQ(session.thread_trial(), nullptr);
  EXPECT_TRUE(session.parallel());
  session.measured_frame(10, 1.0, now + 60.0);  // the user's choice stays
  EXPECT_TRUE(session.parallel());
}

// A small cloth with cloth contact runs the trial too: its pair work is worth threads (the stack
// on the ball in the window: 44 % of real time on one thread, 80 % on two). Where the parallel
// step measures faster it is kept.
TEST(Copies, ASmallClothWithContactMeasuresWhichThreadCountIsFaster) {
  Scene scene = copies_drop(IntegratorKind::symplectic_euler);
  scene.solver.threads = 0;
  scene.solver.cloth_contact = true;
  vis::SimSession session(scene);
  ASSERT_LT(session.solver().vertex_count(), kParallelMinVertices);
  ASSERT_NE(session.thread_trial(), nullptr);
  double now = 0.0;
  for (int f = 0; f < 100 && session.thread_trial()->trying(); ++f, now += 1.0 / 60.0)
    session.measured_frame(10, session.parallel() ? 12e-3 : 19e-3, now);
  EXPECT_TRUE(session.parallel());
}

}  // namespace
}  // namespace clothlab
