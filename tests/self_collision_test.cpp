// Cloth self-collision (sim/contact/self_collision.hpp): a strip dropped onto the floor piles up
// in folds whose layers keep the thickness apart, a small sheet dropped into a hammock stays on
// top of it; both runs checked at every step, and both shown to fail with self-collision off (the
// layers meet, the sheet falls through). The same result for 1 and 2 threads, bit for bit, and
// nothing built when the option is off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/contact/self_collision.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;
constexpr double kThickness = 0.008;  // m; at least 0.71 of the 1 cm grid spacing used below

ColliderSpec floor_plane() {
  ColliderSpec c;
  c.kind = ColliderKind::plane;
  c.point = {0.0, 0.0, 0.0};
  c.normal = {0.0, 1.0, 0.0};
  c.key = "colliders[0]";
  return c;
}

void use_self_collision(Scene& s, bool on) {
  s.solver.self_collision = on;
  s.solver.self_thickness = kThickness;
  // 10 substeps of 0.1 ms: the stiff 1 cm springs need the small substep, the pairs are found
  // once per 1 ms step.
  s.solver.integrator = IntegratorKind::symplectic_euler;
  s.solver.dt = 1e-3;
  s.solver.substeps = 10;
  s.springs.stiffness = 100.0;
  s.springs.damping = 0.005;
  s.forces.drag = 1e-5;
}

// An 8 x 64 strip (1 cm spacing, 7 cm x 63 cm), hanging almost vertically with its lower end
// 7 cm above the floor, released at rest: the lower end lands first and the rest piles onto it
// in folds.
Scene falling_strip(bool self) {
  Scene s = testing::sheet(8, 0.07, 0.05, 100.0, IntegratorKind::symplectic_euler, 1e-3);
  ClothSpec& c = s.cloths[0];
  c.size = {0.07, 0.63};
  c.resolution = {8, 64};
  c.origin = {-0.035, 0.70, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, -1.0, 0.2};  // leaning a little, so the folds fall to one side
  s.colliders = {floor_plane()};
  use_self_collision(s, self);
  return s;
}

// A 24 x 24 hammock (23 cm, held at its four corners, at y = 0) and a 16 x 16 sheet (15 cm)
// 4 cm above its middle, both 1 cm spacing, released at rest: the sheet falls into the hammock.
Scene hammock(bool self) {
  Scene s;
  ClothSpec lower;
  lower.size = {0.23, 0.23};
  lower.resolution = {24, 24};
  lower.origin = {-0.115, 0.0, -0.115};
  lower.u_axis = {1.0, 0.0, 0.0};
  lower.v_axis = {0.0, 0.0, 1.0};
  lower.mass = 0.06;
  lower.pins = {{0, 0}, {23, 0}, {0, 23}, {23, 23}};
  lower.key = "cloth[0]";
  ClothSpec upper = lower;
  upper.size = {0.15, 0.15};
  upper.resolution = {16, 16};
  upper.origin = {-0.075, 0.04, -0.075};
  upper.mass = 0.03;
  upper.pins.clear();
  upper.key = "cloth[1]";
  s.cloths = {lower, upper};
  s.multi_cloth = true;
  use_self_collision(s, self);
  s.springs.stiffness = 300.0;  // a taut hammock: it sags about 5 cm under the sheet
  return s;
}

std::vector<V3> positions(const SolverState& s) {
  std::vector<V3> x(s.vertex_count());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3d p = s.position(int(i));
    x[i] = {p[0], p[1], p[2]};
  }
  return x;
}

// Which pairs self-collision ignores (the same rule as SelfCollision::skip_distance): two
// vertices of one cloth closer at rest than 1.5 thickness or the longest spring.
template <class T>
struct SkipRule {
  std::vector<int> cloth;
  std::vector<V3> rest;
  double skip = 0.0;
  explicit SkipRule(const Model<T>& m) {
    cloth.assign(m.n, 0);
    for (std::size_t c = 0; c < m.cloths.size(); ++c)
      for (int k = 0; k < m.cloths[c].nu * m.cloths[c].nv; ++k)
        cloth[std::size_t(m.cloths[c].offset + k)] = int(c);
    for (std::size_t i = 0; i < m.n; ++i)
      rest.emplace_back(m.rest_positions.x[i], m.rest_positions.y[i], m.rest_positions.z[i]);
    const SpringList<T> springs = spring_list(m);
    for (std::size_t k = 0; k < springs.size(); ++k)
      skip = std::max(skip, double(springs.rest_length[k]));
    skip = std::max(skip * (1.0 + 1e-6), 1.5 * kThickness);
  }
  bool skipped(std::size_t i, std::size_t j) const {
    return cloth[i] == cloth[j] && (rest[i] - rest[j]).norm() < skip;
  }
};

// The closest two vertices that are not skipped.
template <class T>
double closest_pair(const std::vector<V3>& x, const SkipRule<T>& rule) {
  // Sweep along x: only pairs closer than the best so far in x can be closer.
  std::vector<std::size_t> order(x.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return x[a].x() < x[b].x(); });
  double best = INFINITY;
  for (std::size_t a = 0; a < order.size(); ++a)
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const std::size_t i = order[a], j = order[b];
      if (x[j].x() - x[i].x() >= best) break;
      if (rule.skipped(i, j)) continue;
      best = std::min(best, (x[i] - x[j]).norm());
    }
  return best;
}

// The pile: over 0.8 s (landing at about 0.1 s and settling), the closest pair at every step.
template <class T>
double strip_closest(bool self, int* pile_steps = nullptr) {
  const Scene scene = falling_strip(self);
  const auto s_owner = testing::solver<T>(scene);
  Solver& s = *s_owner;
  const SkipRule<T> rule(build_model<T>(scene));
  double closest = INFINITY;
  for (int k = 0; k < 800; ++k) {
    EXPECT_TRUE(s.step(1).ok());
    closest = std::min(closest, closest_pair(positions(s), rule));
    if (self) {
      EXPECT_EQ(s.last_self_collision()->dropped, 0);
      if (pile_steps && s.last_self_collision()->pairs > 0) ++*pile_steps;
    }
  }
  return closest;
}

TEST(SelfCollision, FoldedStripKeepsItsLayersApart) {
  int pile_steps = 0;
  const double closest = strip_closest<float>(true, &pile_steps);
  EXPECT_GT(pile_steps, 300);  // the strip did fold onto itself
  EXPECT_GT(closest, 0.5 * kThickness);
}

// Without self-collision the folds fall onto each other: the same run is a meaningful test.
TEST(SelfCollision, FoldedStripInterpenetratesWithoutIt) {
  EXPECT_LT(strip_closest<float>(false), 0.25 * kThickness);
}

// The hammock: at every step no two vertices closer than half the thickness, and every vertex
// of the upper sheet above the hammock's vertex nearest to it in plan (its layer order).
struct HammockRun {
  double closest = INFINITY;  // m, over the run
  double lowest = INFINITY;   // m: the smallest height of an upper vertex over the hammock
};

template <class T>
HammockRun run_hammock(bool self, int threads, int steps) {
  Scene scene = hammock(self);
  scene.solver.threads = threads;
  const auto s_owner = testing::solver<T>(scene);
  Solver& s = *s_owner;
  const SkipRule<T> rule(build_model<T>(scene));
  const int lower_n = 24 * 24;
  HammockRun run;
  for (int k = 0; k < steps; ++k) {
    EXPECT_TRUE(s.step(1).ok());
    const std::vector<V3> x = positions(s);
    run.closest = std::min(run.closest, closest_pair(x, rule));
    for (std::size_t i = lower_n; i < x.size(); ++i) {
      double plan = INFINITY;
      double below = 0.0;
      for (std::size_t j = 0; j < std::size_t(lower_n); ++j) {
        const double d = std::hypot(x[i].x() - x[j].x(), x[i].z() - x[j].z());
        if (d < plan) plan = d, below = x[j].y();
      }
      run.lowest = std::min(run.lowest, x[i].y() - below);
    }
  }
  return run;
}

TEST(SelfCollision, SheetStaysOnTopOfTheHammock) {
  const HammockRun run = run_hammock<float>(true, 1, 600);
  EXPECT_GT(run.closest, 0.5 * kThickness);
  EXPECT_GT(run.lowest, 0.0) << "an upper vertex went below the hammock";
}

TEST(SelfCollision, SheetFallsThroughTheHammockWithoutIt) {
  const HammockRun run = run_hammock<float>(false, 1, 600);
  EXPECT_LT(run.closest, 0.25 * kThickness);
  EXPECT_LT(run.lowest, -0.05);  // fell clean through
}

// The pairs are written per block and the response is serial in their order, so 1 and 2 threads
// give the same run, bit for bit (the hammock has two blocks of vertices).
template <class T>
void expect_thread_independent() {
  std::vector<std::vector<Vec3d>> runs;
  for (int threads : {1, 2}) {
    Scene scene = hammock(true);
    scene.solver.threads = threads;
    const auto s_owner = testing::solver<T>(scene);
    Solver& s = *s_owner;
    EXPECT_TRUE(s.step(250).ok());
    EXPECT_GT(s.last_self_collision()->pairs, 0);
    std::vector<Vec3d> all = testing::positions_of(s);
    const std::vector<Vec3d> vel = testing::velocities_of(s);
    all.insert(all.end(), vel.begin(), vel.end());
    runs.push_back(all);
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  EXPECT_TRUE(runs[0] == runs[1]) << "1 and 2 threads differ";
}

TEST(SelfCollision, SameResultForAnyThreadCountFloat) {
  expect_thread_independent<float>();
}
TEST(SelfCollision, SameResultForAnyThreadCountDouble) {
  expect_thread_independent<double>();
}

// Pairs: each once (a < b), none skipped, none twice, all closer than the query radius.
TEST(SelfCollision, PairListHasEachNearPairOnce) {
  const Scene scene = hammock(true);
  const auto s_owner = testing::solver<double>(scene);
  Solver& s = *s_owner;
  ASSERT_TRUE(s.step(200).ok());  // the sheet lies in the hammock
  // The self-collision pass alone, on the model and the state the solver reached.
  const Model<double> model = build_model<double>(scene);
  State<double> state;
  state.pos.resize(model.n);
  state.vel.resize(model.n);
  const std::vector<Vec3d> pos = testing::positions_of(s), vel = testing::velocities_of(s);
  for (std::size_t i = 0; i < model.n; ++i) {
    state.pos.set(i, pos[i][0], pos[i][1], pos[i][2]);
    state.vel.set(i, vel[i][0], vel[i][1], vel[i][2]);
  }
  SelfCollision<double> sc(model, scene.solver);
  sc.find_pairs(model, state, s.dt(), 2);
  const SkipRule<double> rule(model);
  const std::vector<V3> x = positions(s);
  std::vector<std::pair<int, int>> found;
  sc.for_each_pair([&](const SelfCollision<double>::Pair& p) { found.emplace_back(p.a, p.b); });
  // Brute force: every pair closer than the radius and not skipped.
  std::vector<std::pair<int, int>> expected;
  const double r = sc.last().query_radius;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j)
      if ((x[i] - x[j]).norm() < r && !rule.skipped(i, j) &&
          !(s.pinned(int(i)) && s.pinned(int(j))))
        expected.emplace_back(int(i), int(j));
  std::sort(found.begin(), found.end());
  EXPECT_GT(expected.size(), 50u);
  EXPECT_EQ(found, expected);
  EXPECT_EQ(sc.skip_distance(), rule.skip);
}

TEST(SelfCollision, OffBuildsNothing) {
  const auto s_owner = testing::solver<float>(hammock(false));
  Solver& s = *s_owner;
  EXPECT_FALSE(s.last_self_collision());
}

}  // namespace
}  // namespace clothlab
