// `clothlab tune` (tune/tune.hpp, docs/tuning.md): the reference's error bound, the table's
// errors against runs made without the tune code, the frontier and the recommendation on a
// constructed table, and the rows of cases that diverge, are stopped or do not apply.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "load/scene_load.hpp"
#include "sim/solver.hpp"
#include "tune/ladder.hpp"
#include "tune/result_file.hpp"
#include "tune/tolerance.hpp"
#include "tune/tune.hpp"
#include "tune_sheet.hpp"

namespace clothlab::tune {
namespace {

const char* const kSheet = testing::kTuneSheet;

SceneReader sheet_reader(std::vector<std::string> user = {}) {
  return [user](const std::vector<std::string>& extra) {
    std::vector<std::string> all = user;
    all.insert(all.end(), extra.begin(), extra.end());
    return read_scene_string(kSheet, "sheet.toml", all);
  };
}

TEST(Tune, SampleTimesAreDistinctWholeFrames) {
  const std::vector<double> t = sample_times(1.0, 4);
  ASSERT_EQ(t.size(), 4u);
  for (std::size_t k = 0; k < t.size(); ++k)
    EXPECT_NEAR(t[k] / kFrame, std::round(t[k] / kFrame), 1e-9);
  EXPECT_NEAR(t.back(), 1.0, 1e-12);
  EXPECT_EQ(sample_times(1.0 / 60.0, 4).size(), 1u);  // one frame: one time, not four of it
}

// The reference's bound (its distance from the run at twice its step) covers its distance from
// an RK4 run at a quarter of its step, and is as loose as RK4's order says, no more.
TEST(Tune, ReferenceBoundCoversItsDistanceFromAFinerRk4Run) {
  Options o;
  o.duration = 0.5;
  o.samples = 2;
  const Plan plan = plan_tune(sheet_reader(), o);
  const Scene coarse = sheet_reader()(plan.reference.setting.overrides);
  const int n = coarse.solver.substeps;
  const SampledRun fine = run_sampled(
      sheet_reader(plan.reference.setting.overrides)({"solver.substeps=" + std::to_string(4 * n)}),
      plan.times, 0.0);
  ASSERT_TRUE(fine.finished());
  for (std::size_t k = 0; k < plan.times.size(); ++k) {
    const Distance actual = distance(plan.reference.run.at[k], fine.at[k]);
    EXPECT_LE(actual.rms, plan.reference.self[k].rms) << "at " << plan.times[k] << " s";
    EXPECT_LE(actual.max, plan.reference.self[k].max) << "at " << plan.times[k] << " s";
    // RK4's fourth order: the runs at h, h/2 and h/8 differ by e (16 - 1) and e (1 - 1/64) for
    // an error e of the run at h/2, a ratio of 15.2 (measured 15.3 and 15.5).
    const double ratio = plan.reference.self[k].rms / actual.rms;
    EXPECT_GT(ratio, 8.0) << "at " << plan.times[k] << " s";
    EXPECT_LT(ratio, 25.0) << "at " << plan.times[k] << " s";
  }
}

// Positions of a scene at time t, stepped without any of the tune code.
std::vector<Vec3d> positions_at(const Scene& scene, double t) {
  auto solver = make_solver(scene);
  solver->step(std::lround(t / solver->dt()));
  std::vector<Vec3d> p(solver->vertex_count());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = solver->position(int(i));
  return p;
}

// Without a wall-time limit, so that no row depends on the clock.
TEST(Tune, TableErrorsEqualTwoRunsComparedDirectly) {
  Options o;
  o.duration = 0.25;
  o.samples = 2;
  const Plan plan = plan_tune(sheet_reader(), o);
  ASSERT_EQ(plan.ladder.size(), ladder(Spectrum{}).size());
  const Scene reference = sheet_reader()(plan.reference.setting.overrides);
  int compared = 0;
  for (const Setting& setting : plan.ladder) {
    if (setting.family == "implicit") continue;  // the cheap ones suffice
    const Row row = measure(sheet_reader(), o, setting, plan.reference.run, plan.times, 0.0);
    ASSERT_TRUE(row.ok()) << setting.label << ": " << row.status;
    const Scene candidate = sheet_reader()(setting.overrides);
    for (std::size_t k = 0; k < plan.times.size(); ++k) {
      const std::vector<Vec3d> a = positions_at(candidate, plan.times[k]);
      const std::vector<Vec3d> b = positions_at(reference, plan.times[k]);
      double sum = 0.0, most = 0.0;
      for (std::size_t i = 0; i < a.size(); ++i) {
        const double d2 = (a[i][0] - b[i][0]) * (a[i][0] - b[i][0]) +
                          (a[i][1] - b[i][1]) * (a[i][1] - b[i][1]) +
                          (a[i][2] - b[i][2]) * (a[i][2] - b[i][2]);
        sum += d2;
        most = std::max(most, std::sqrt(d2));
      }
      EXPECT_DOUBLE_EQ(row.error[k].rms, std::sqrt(sum / double(a.size()))) << setting.label;
      EXPECT_DOUBLE_EQ(row.error[k].max, most) << setting.label;
    }
    ++compared;
  }
  EXPECT_EQ(compared, 18);
}

Row made(const char* label, double cost, std::vector<double> rms, const char* status = "ok") {
  Row r;
  r.setting.label = label;
  r.cost = cost;
  for (double e : rms) r.error.push_back({e, 2.0 * e});
  r.status = status;
  return r;
}

TEST(Tune, RecommendationIsTheFrontiersCheapestWithinTheTolerance) {
  const std::vector<Row> rows = {
      made("a", 0.10, {0.050, 0.080}),          // cheapest, 80 mm at worst
      made("b", 0.20, {0.030, 0.010}),          // 30 mm at worst (its first time)
      made("c", 0.30, {0.040, 0.040}),          // beaten by b: off the frontier
      made("d", 0.05, {0.001}, "diverged: x"),  // unfinished: never chosen
      made("e", 0.50, {0.004, 0.005}),          // 5 mm
      made("f", 0.40, {0.020, 0.0201}),         // 20.1 mm, cheaper than e
  };
  const std::vector<std::size_t> front = frontier(rows);
  EXPECT_EQ(front, (std::vector<std::size_t>{0, 1, 5, 4}));
  EXPECT_EQ(cheapest_within(rows, 0.1), std::optional<std::size_t>(0));
  EXPECT_EQ(cheapest_within(rows, 0.06), std::optional<std::size_t>(1));
  EXPECT_EQ(cheapest_within(rows, 0.02), std::optional<std::size_t>(4));  // f's 20.1 mm is out
  EXPECT_EQ(cheapest_within(rows, 0.005), std::optional<std::size_t>(4));
  EXPECT_EQ(cheapest_within(rows, 0.001), std::nullopt);
  for (double tol : {0.1, 0.06, 0.03, 0.0201, 0.005}) {
    const auto best = cheapest_within(rows, tol);
    ASSERT_TRUE(best);
    EXPECT_NE(std::find(front.begin(), front.end(), *best), front.end()) << tol;
  }
}

TEST(Tune, DivergingStoppedAndInapplicableCasesAreRows) {
  Options o;
  const std::vector<double> times = sample_times(0.5, 2);
  const SceneReader read = sheet_reader({"springs.stiffness=1e5"});
  const SampledRun reference = run_sampled(
      read({"solver.integrator=rk4", "solver.precision=double", "solver.substeps=400"}), times, 0);
  ASSERT_TRUE(reference.finished());

  const Setting unstable{"explicit",
                         "se at one step a frame",
                         {"solver.integrator=symplectic_euler", "solver.substeps=1"}};
  const Row diverged = measure(read, o, unstable, reference, times, 0.0);
  EXPECT_EQ(diverged.status.rfind("diverged", 0), 0u) << diverged.status;
  EXPECT_TRUE(std::isinf(diverged.worst_rms()));

  const Setting slow{
      "explicit", "rk4 at 4000 substeps", {"solver.integrator=rk4", "solver.substeps=4000"}};
  const Row stopped = measure(read, o, slow, reference, times, 1e-3);
  EXPECT_EQ(stopped.status.rfind("stopped at t = ", 0), 0u) << stopped.status;
  EXPECT_LT(stopped.error.size(), times.size());

  const Setting invalid{
      "descent", "vbd at -1 iterations", {"solver.integrator=vbd", "solver.iterations=-1"}};
  const Row refused = measure(read, o, invalid, reference, times, 0.0);
  // The message names the --set line, as the command line's own does.
  EXPECT_EQ(refused.status.rfind("not applicable: --set solver.iterations=-1: ", 0), 0u)
      << refused.status;

  const std::vector<Row> rows = {diverged, stopped, refused};
  EXPECT_TRUE(frontier(rows).empty());
  EXPECT_EQ(cheapest_within(rows, 1e9), std::nullopt);
}

// `clothlab tune --scheduler` reads back the table the Python module wrote: every number to the
// bit (1/3, the smallest double, an infinite cost), the unfinished rows' missing times, every
// word; a file that is not one names itself.
TEST(Tune, ResultFileReadsBackExactly) {
  Result r;
  r.times = {1.0 / 60.0, 0.5, 1.0};
  r.reference.setting = {"reference", "rk4 (double), 48 substeps", {"solver.integrator=rk4"}};
  r.reference.self = {{1.0 / 3.0, 0.5}, {4.9e-324, 1e-300}, {1e-7, 2e-7}};
  r.reference.cost = 0.4563;
  r.reference.stop_after = 2.0 / 7.0;
  r.rows = {made("a \"quoted\" label", 0.1, {0.05, 0.08, 0.07}),
            made("d", std::numeric_limits<double>::infinity(), {0.001}, "diverged: x")};
  r.rows[0].energy_drift = -1.0 / 7.0;
  const std::string file = ::testing::TempDir() + "clothlab_tune_result.toml";
  write_result(file, r);
  const Result back = read_result(file);
  EXPECT_EQ(back.times, r.times);
  EXPECT_EQ(back.reference.setting.label, r.reference.setting.label);
  EXPECT_EQ(back.reference.setting.overrides, r.reference.setting.overrides);
  ASSERT_EQ(back.reference.self.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(back.reference.self[k].rms, r.reference.self[k].rms);
    EXPECT_EQ(back.reference.self[k].max, r.reference.self[k].max);
  }
  EXPECT_EQ(back.reference.cost, r.reference.cost);
  EXPECT_EQ(back.reference.stop_after, r.reference.stop_after);
  ASSERT_EQ(back.rows.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back.rows[i].setting.label, r.rows[i].setting.label);
    EXPECT_EQ(back.rows[i].status, r.rows[i].status);
    EXPECT_EQ(back.rows[i].cost, r.rows[i].cost);
    EXPECT_EQ(back.rows[i].energy_drift, r.rows[i].energy_drift);
    ASSERT_EQ(back.rows[i].error.size(), r.rows[i].error.size());
    for (std::size_t k = 0; k < r.rows[i].error.size(); ++k)
      EXPECT_EQ(back.rows[i].error[k].max, r.rows[i].error[k].max);
  }
  std::ofstream(file) << "times = []\n";
  try {
    read_result(file);
    ADD_FAILURE() << "read an empty table";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file + ": not a tune's result"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(file);
}

TEST(Tune, TomlQuotesTheWordsAndKeepsTheNumbers) {
  const Setting s{"constraints",
                  "xpbd",
                  {"solver.integrator=xpbd", "solver.substeps=auto", "solver.dt=0.0166"}};
  EXPECT_EQ(as_toml(s), "[solver]\nintegrator = \"xpbd\"\nsubsteps = \"auto\"\ndt = 0.0166\n");
  // Pasted in place of the scene's [solver] table, it reads as the same solver as the lines.
  const std::string sheet = kSheet;
  const Scene pasted =
      read_scene_string(sheet.substr(0, sheet.find("[solver]")) + as_toml(s), "s.toml", {});
  const Scene set =
      read_scene_string(sheet.substr(0, sheet.find("[solver]")), "s.toml", s.overrides);
  EXPECT_EQ(pasted.solver.integrator, IntegratorKind::xpbd);
  EXPECT_EQ(pasted.solver.substeps, 0);
  EXPECT_EQ(pasted.solver.dt, set.solver.dt);
  EXPECT_EQ(pasted.solver.integrator, set.solver.integrator);
}

}  // namespace
}  // namespace clothlab::tune

namespace clothlab::tune {
namespace {

TuneSummary constructed_summary() {
  TuneSummary s;
  s.reference_error = 1e-4;
  s.reference = {"reference", "rk4 (double), 40 substeps", {"solver.integrator=rk4"}};
  Row a = made("cheap", 0.1, {0.05});
  a.setting.overrides = {"solver.integrator=xpbd", "solver.substeps=5"};
  Row b = made("dear", 0.3, {0.004});
  b.setting.overrides = {"solver.integrator=symplectic_euler", "solver.substeps=40"};
  Row c = made("diverged", 0.01, {}, "diverged: at t = 0.1 s");
  s.rows = {a, b, c};
  return s;
}

TEST(Tolerance, PicksTheCheapestWithinAndRefusesBelowTheReference) {
  const TuneSummary s = constructed_summary();
  EXPECT_EQ(pick(s, 0.1).setting.label, "cheap");
  EXPECT_EQ(pick(s, 0.02).setting.label, "dear");
  EXPECT_DOUBLE_EQ(pick(s, 0.02).worst_rms, 0.004);
  const TolerancePick none = pick(s, 0.001);  // nothing within: the reference's own setting
  EXPECT_TRUE(none.reference);
  EXPECT_EQ(none.setting.overrides, s.reference.overrides);
  try {
    (void)pick(s, 1e-5);
    ADD_FAILURE() << "a tolerance below the reference's error was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0.01 mm is below the reference's own error to 1 s on "
                                         "this scene (0.1 mm)"),
              std::string::npos)
        << e.what();
  }
}

TEST(Tolerance, CacheEntryReadsBackAndIsUsedWithoutTuning) {
  const std::string dir = ::testing::TempDir() + "clothlab_tolerance_cache";
  const std::string file = dir + "/entry.toml";
  std::filesystem::remove_all(dir);
  const TuneSummary s = constructed_summary();
  write_summary(file, s);
  const std::optional<TuneSummary> back = read_summary(file);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->reference_error, s.reference_error);
  ASSERT_EQ(back->rows.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back->rows[i].setting.overrides, s.rows[i].setting.overrides);
    EXPECT_EQ(back->rows[i].worst_rms(), s.rows[i].worst_rms());
    EXPECT_EQ(back->rows[i].cost, s.rows[i].cost);
    EXPECT_EQ(back->rows[i].status, s.rows[i].status);
  }
  // A reader that fails shows that no tune runs while the entry is there.
  const SceneReader never = [](const std::vector<std::string>&) -> Scene {
    throw std::runtime_error("tuned although cached");
  };
  const TolerancePick p = resolve_tolerance(never, file, 0.02, nullptr);
  EXPECT_TRUE(p.cached);
  EXPECT_EQ(p.setting.label, "dear");
  std::ofstream(file) << "not toml [";  // a damaged entry is tuned again
  EXPECT_THROW(resolve_tolerance(never, file, 0.02, nullptr), std::runtime_error);
  std::filesystem::remove_all(dir);
}

TEST(Tolerance, CacheKeyLeavesOutTheToleranceAndNothingElse) {
  const std::string a = "[solver]\ntolerance = 0.02\ncg_tolerance = 1e-3\n";
  const std::string b = "[solver]\ntolerance = 0.005\ncg_tolerance = 1e-3\n";
  const std::string c = "[solver]\ntolerance = 0.02\ncg_tolerance = 1e-4\n";
  EXPECT_EQ(cache_file(a, {}), cache_file(b, {}));
  EXPECT_NE(cache_file(a, {}), cache_file(c, {}));
  EXPECT_EQ(cache_file(a, {"solver.tolerance=0.01"}), cache_file(a, {}));
  EXPECT_NE(cache_file(a, {"springs.stiffness=10"}), cache_file(a, {}));
}

}  // namespace
}  // namespace clothlab::tune
