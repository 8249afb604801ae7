// The window's live reference (tune/live_reference.hpp, docs/tuning.md "The error in the
// window"): a run against itself is at distance zero, its distances equal those of runs made
// without it, its interpolation between steps is exact on a parabola, and a restart takes over the
// shown state, time and released pins.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "load/scene_load.hpp"
#include "sim/solver.hpp"
#include "tune/ladder.hpp"
#include "tune/live_reference.hpp"
#include "tune/tune.hpp"
#include "tune_sheet.hpp"

namespace clothlab::tune {
namespace {

const char* const kReferenceSheet = testing::kTuneSheet;

Scene sheet(std::vector<std::string> overrides = {}) {
  return read_scene_string(kReferenceSheet, "sheet.toml", overrides);
}

// Advances `shown` by whole frames to `frames`, handing each frame's state to the reference.
std::vector<LiveComparison> compare_with_reference(Solver& shown, LiveReference& ref, int frames) {
  std::vector<LiveComparison> out;
  for (int f = 0; f < frames; ++f) {
    EXPECT_TRUE(shown.advance(kFrame).ok());
    EXPECT_TRUE(ref.submit(shown));
    ref.wait();
    LiveComparison c;
    EXPECT_TRUE(ref.take(c));
    EXPECT_FALSE(ref.take(c)) << "one result per request";
    out.push_back(std::move(c));
  }
  return out;
}

TEST(LiveReference, ARunAgainstItselfIsAtDistanceZero) {
  const Scene scene = sheet();
  auto shown = make_solver(scene);
  LiveReference ref(scene);
  ref.restart(*shown);
  for (const LiveComparison& c : compare_with_reference(*shown, ref, 12)) {
    EXPECT_EQ(c.distance.rms, 0.0);
    EXPECT_EQ(c.distance.max, 0.0);
    ASSERT_EQ(c.per_vertex.size(), shown->vertex_count());
  }
  EXPECT_GT(ref.cost(), 0.0);
}

// The live distances at whole frames equal tune::distance between runs of the shown setting and
// of tune's coarser reference made by run_sampled, and the live reference is that reference.
TEST(LiveReference, DistancesEqualThoseOfSeparateRuns) {
  const Scene scene = sheet();
  const Scene reference = live_reference_scene(scene);
  EXPECT_EQ(reference.solver.integrator, IntegratorKind::rk4);
  EXPECT_EQ(reference.solver.precision, Precision::f64);
  EXPECT_EQ(reference.solver.threads, 1);
  auto shown = make_solver(scene);
  LiveReference ref(reference);
  ref.restart(*shown);
  const std::vector<LiveComparison> live = compare_with_reference(*shown, ref, 30);

  const std::vector<double> times{10 * kFrame, 20 * kFrame, 30 * kFrame};
  const SampledRun a = run_sampled(scene, times, 0.0);
  const SampledRun b = run_sampled(reference, times, 0.0);
  Options o;
  const Setting coarse =
      settings_for([](const std::vector<std::string>& extra) { return sheet(extra); }, o).coarse;
  const SampledRun tune_ref = run_sampled(sheet(coarse.overrides), times, 0.0);
  for (std::size_t k = 0; k < times.size(); ++k) {
    const LiveComparison& c = live[10 * (k + 1) - 1];
    EXPECT_NEAR(c.time, times[k], 1e-12);
    const Distance d = distance(a.at[k], b.at[k]);
    EXPECT_GT(d.rms, 1e-4) << "the settings differ";
    // The live reference starts from the shown run's state in float: 1e-8 m apart at most.
    EXPECT_NEAR(c.distance.rms, d.rms, 1e-7);
    EXPECT_NEAR(c.distance.max, d.max, 1e-7);
    // A step of its own instead of a substep of a frame: the same reference to round-off.
    EXPECT_LT(distance(b.at[k], tune_ref.at[k]).max, 1e-9);
  }
}

// A sheet without pins falls as one piece on the parabola x0 - g t^2 / 2, which RK4 follows to
// round-off; the reference read at a third and two thirds of its steps must be on it too (linear
// interpolation would be g h^2 / 8 = 85 um off at its step of 8.3 ms).
TEST(LiveReference, InterpolationBetweenStepsIsExactOnAParabola) {
  // Soft springs: at 1000 N/m RK4's limit is below these steps, and round-off would grow.
  const std::vector<std::string> free_fall{"cloth.pins=[]", "springs.stiffness=1.0",
                                           "solver.integrator=rk4", "solver.precision=double"};
  std::vector<std::string> ref_lines = free_fall, shown_lines = free_fall;
  ref_lines.push_back("solver.dt=" + std::to_string(kFrame / 2));
  shown_lines.push_back("solver.dt=" + std::to_string(kFrame / 6));
  auto shown = make_solver(sheet(shown_lines));
  LiveReference ref(sheet(ref_lines));
  ref.restart(*shown);
  for (int k = 1; k <= 20; ++k) {
    ASSERT_TRUE(shown->step(1).ok());
    ASSERT_TRUE(ref.submit(*shown));
    ref.wait();
    LiveComparison c;
    ASSERT_TRUE(ref.take(c));
    EXPECT_LT(c.distance.max, 1e-9) << "step " << k << " at " << c.time << " s";
  }
}

// A restart takes over the shown state at its time (distance zero there, though the reference's
// step does not divide that time) and lets go of the pins when the shown run has.
TEST(LiveReference, RestartTakesOverTheShownStateAndItsReleasedPins) {
  const Scene scene = sheet();
  auto shown = make_solver(sheet({"solver.integrator=symplectic_euler", "solver.dt=0.0003"}));
  LiveReference ref(live_reference_scene(scene));
  ASSERT_TRUE(shown->advance(0.3).ok());
  shown->release_pins();
  ref.restart(*shown);
  ASSERT_TRUE(ref.submit(*shown));
  ref.wait();
  LiveComparison c;
  ASSERT_TRUE(ref.take(c));
  EXPECT_EQ(c.distance.max, 0.0);
  EXPECT_NEAR(c.time, shown->time(), 1e-12);
  // Half a second of falling later: 1.2 m below where pins would have held the corners.
  ASSERT_TRUE(shown->advance(0.5).ok());
  ASSERT_TRUE(ref.submit(*shown));
  ref.wait();
  ASSERT_TRUE(ref.take(c));
  EXPECT_LT(c.distance.max, 0.05);
}

TEST(LiveReference, AReferenceThatDivergesSaysSoAndTakesNoMoreRequests) {
  auto shown = make_solver(sheet());
  LiveReference ref(sheet({"solver.integrator=rk4", "solver.dt=0.016666666666666666"}));
  ref.restart(*shown);
  for (int f = 0; f < 240 && ref.failure().empty(); ++f) {
    ASSERT_TRUE(shown->advance(kFrame).ok());
    ASSERT_TRUE(ref.submit(*shown));
    ref.wait();
  }
  EXPECT_NE(ref.failure().find("diverged"), std::string::npos);
  EXPECT_FALSE(ref.submit(*shown));
}

}  // namespace
}  // namespace clothlab::tune
