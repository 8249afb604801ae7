// The force field by source (Solver::update_force_field(ForceSource)): on a deformed, moving
// sheet in gusty wind the sources add up to the total, gravity is m_i g and drag -c v_i exactly,
// the wind source vanishes without wind, the springs vanish at rest, and a call allocates nothing.
// Both precisions, both spring kernels, springs with and without damping.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <new>
#include <sstream>
#include <vector>

#include "allocation_counter.hpp"
#include "sim/forces/force_source.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

constexpr int kSourceRes = 12;

// A sheet hanging from its two top corners in the x-y plane, blown along z by a gusty wind,
// with along-spring damping and linear drag; two solver threads.
Scene source_windy_sheet(bool damped, bool wind, Precision precision) {
  Scene s = testing::sheet(kSourceRes, 1.0, 0.5, 800.0, IntegratorKind::symplectic_euler, 1e-4);
  s.cloths[0].pins = {{0, 0}, {kSourceRes - 1, 0}};
  s.springs.damping = damped ? 0.07 : 0.0;
  s.forces.drag = 0.05;
  s.forces.wind = WindSpec{wind, {1.0, 0.0, 4.0}, 0.5, 3, 0.3, 1.2};
  s.solver.threads = 2;
  s.solver.precision = precision;
  return s;
}

template <class T>
Precision precision_of() {
  return sizeof(T) == sizeof(float) ? Precision::f32 : Precision::f64;
}

// The field of one source at the solver's current state.
std::vector<Vec3d> field(Solver& s, ForceSource source) {
  s.update_force_field(source);
  EXPECT_EQ(s.force_field_source(), source);
  std::vector<Vec3d> f(s.vertex_count());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = s.force(static_cast<int>(i));
  return f;
}

// Written to the XML report (--gtest_output=xml) for choosing tolerances.
void record(const char* key, double value) {
  std::ostringstream text;
  text << std::scientific << std::setprecision(3) << value;
  ::testing::Test::RecordProperty(key, text.str());
}

double largest_component(const std::vector<Vec3d>& f) {
  double m = 0.0;
  for (const Vec3d& v : f)
    for (double c : v) m = std::max(m, std::abs(c));
  return m;
}

// Steps the sheet 0.15 s so it is stretched, swinging and blown.
void run_a_while(Solver& s) {
  ASSERT_TRUE(s.step(1500).ok());
  double speed = 0.0;
  for (std::size_t i = 0; i < s.vertex_count(); ++i)
    for (double c : s.velocity(static_cast<int>(i))) speed = std::max(speed, std::abs(c));
  ASSERT_GT(speed, 0.01);  // it really moves
}

// springs + gravity + drag + wind == total to `tolerance` times the largest force component
// of any source (the springs' internal forces can exceed the total they sum to).
template <class T>
void expect_sources_sum_to_total(SpringKernel kernel, bool damped, double tolerance) {
  SCOPED_TRACE(::testing::Message() << "kernel " << int(kernel) << ", damped " << damped);
  const auto s_owner =
      testing::solver<T>(source_windy_sheet(damped, true, precision_of<T>()), kernel);
  Solver& s = *s_owner;
  run_a_while(s);
  std::array<std::vector<Vec3d>, kAllForceSources.size()> f;
  double largest = 0.0;
  for (std::size_t k = 0; k < kAllForceSources.size(); ++k) {
    f[k] = field(s, kAllForceSources[k]);
    largest = std::max(largest, largest_component(f[k]));
  }
  const auto& [total, springs, gravity, drag, wind] = f;
  // Every source contributes, so a missing or doubled one shows as a large error.
  ASSERT_GT(largest_component(springs), 1e-2 * largest);
  ASSERT_GT(largest_component(gravity), 1e-2 * largest);
  ASSERT_GT(largest_component(drag), 1e-4 * largest);
  ASSERT_GT(largest_component(wind), 1e-2 * largest);
  double worst = 0.0;
  for (std::size_t i = 0; i < s.vertex_count(); ++i) {
    for (int a = 0; a < 3; ++a) {
      const double sum = springs[i][a] + gravity[i][a] + drag[i][a] + wind[i][a];
      worst = std::max(worst, std::abs(sum - total[i][a]));
      ASSERT_NEAR(sum, total[i][a], tolerance * largest) << "vertex " << i << " axis " << a;
    }
  }
  record(damped ? "worst_relative_sum_error_damped" : "worst_relative_sum_error_undamped",
         worst / largest);
}

TEST(ForceSource, SourcesSumToTheTotalInDouble) {
  for (SpringKernel k : {SpringKernel::row_sweep, SpringKernel::neighbour_list})
    for (bool damped : {true, false}) expect_sources_sum_to_total<double>(k, damped, 1e-13);
}

TEST(ForceSource, SourcesSumToTheTotalInFloat) {
  for (SpringKernel k : {SpringKernel::row_sweep, SpringKernel::neighbour_list})
    for (bool damped : {true, false}) expect_sources_sum_to_total<float>(k, damped, 1e-5);
}

// Gravity is m_i g and drag -c v_i, bit for bit, on every vertex, the pinned ones included.
template <class T>
void expect_exact_body_forces(SpringKernel kernel) {
  SCOPED_TRACE(::testing::Message() << "kernel " << int(kernel));
  const auto s_owner =
      testing::solver<T>(source_windy_sheet(true, true, precision_of<T>()), kernel);
  Solver& s = *s_owner;
  run_a_while(s);
  // The model's values in its precision T (sim/model/model.cpp casts the scene's).
  const ForceSpec& forces = source_windy_sheet(true, true, precision_of<T>()).forces;
  const T drag_c = static_cast<T>(forces.drag);
  const std::vector<Vec3d> gravity = field(s, ForceSource::gravity);
  const std::vector<Vec3d> drag = field(s, ForceSource::drag);
  std::vector<int> pinned;
  for (int i = 0; i < static_cast<int>(s.vertex_count()); ++i) {
    if (s.pinned(i)) pinned.push_back(i);
    const T mass = static_cast<T>(s.mass(i));
    for (int a = 0; a < 3; ++a) {
      const auto ua = static_cast<std::size_t>(a);
      const T g = mass * static_cast<T>(forces.gravity[ua]);
      const T d = -(drag_c * static_cast<T>(s.velocity(i)[ua]));
      const auto vi = static_cast<std::size_t>(i);
      ASSERT_EQ(gravity[vi][ua], double(g)) << "vertex " << i << " axis " << a;
      ASSERT_EQ(drag[vi][ua], double(d)) << "vertex " << i << " axis " << a;
    }
  }
  ASSERT_EQ(pinned.size(), 2u);
  // The pinned vertices too (inside the loop above; spelt out as they matter most).
  for (int p : pinned) {
    const auto i = static_cast<std::size_t>(p);
    EXPECT_EQ(gravity[i][1], double(static_cast<T>(s.mass(p)) * static_cast<T>(forces.gravity[1])));
    EXPECT_LT(gravity[i][1], 0.0);
  }
}

TEST(ForceSource, GravityAndDragAreExact) {
  for (SpringKernel k : {SpringKernel::row_sweep, SpringKernel::neighbour_list}) {
    expect_exact_body_forces<double>(k);
    expect_exact_body_forces<float>(k);
  }
}

template <class T>
void expect_no_wind_without_wind(SpringKernel kernel) {
  const auto s_owner =
      testing::solver<T>(source_windy_sheet(true, false, precision_of<T>()), kernel);
  Solver& s = *s_owner;
  run_a_while(s);
  for (const Vec3d& w : field(s, ForceSource::wind))
    for (double c : w) ASSERT_EQ(c, 0.0);
  // And the total is then the other three alone.
  const std::vector<Vec3d> total = field(s, ForceSource::total);
  const std::vector<Vec3d> springs = field(s, ForceSource::springs);
  const std::vector<Vec3d> gravity = field(s, ForceSource::gravity);
  const std::vector<Vec3d> drag = field(s, ForceSource::drag);
  const double largest = std::max(largest_component(total), largest_component(springs));
  const double tolerance = sizeof(T) == sizeof(float) ? 1e-5 : 1e-13;
  for (std::size_t i = 0; i < total.size(); ++i)
    for (int a = 0; a < 3; ++a)
      ASSERT_NEAR(springs[i][a] + gravity[i][a] + drag[i][a], total[i][a], tolerance * largest);
}

TEST(ForceSource, WindIsZeroWithTheWindOff) {
  for (SpringKernel k : {SpringKernel::row_sweep, SpringKernel::neighbour_list}) {
    expect_no_wind_without_wind<double>(k);
    expect_no_wind_without_wind<float>(k);
  }
}

// At the built state (rest lengths, no motion) the springs pull on nothing: only round-off in
// |x_j - x_i| - L, far below the smallest real load (one vertex's weight).
template <class T>
void expect_springs_vanish_at_rest(SpringKernel kernel, double tolerance) {
  const auto s_owner =
      testing::solver<T>(source_windy_sheet(true, true, precision_of<T>()), kernel);
  Solver& s = *s_owner;
  const std::vector<Vec3d> gravity = field(s, ForceSource::gravity);
  const double weight = largest_component(gravity);
  ASSERT_GT(weight, 0.0);
  const std::vector<Vec3d> springs = field(s, ForceSource::springs);
  record(sizeof(T) == sizeof(float) ? "rest_springs_over_weight_float"
                                    : "rest_springs_over_weight_double",
         largest_component(springs) / weight);
  for (const Vec3d& f : springs)
    for (double c : f) ASSERT_NEAR(c, 0.0, tolerance * weight);
  // Stretched by the swing, the same springs carry several times that weight.
  run_a_while(s);
  EXPECT_GT(largest_component(field(s, ForceSource::springs)), weight);
}

TEST(ForceSource, SpringsVanishAtRest) {
  for (SpringKernel k : {SpringKernel::row_sweep, SpringKernel::neighbour_list}) {
    expect_springs_vanish_at_rest<double>(k, 1e-9);
    expect_springs_vanish_at_rest<float>(k, 2e-2);
  }
}

TEST(ForceSource, ReportsTheLastSourceThroughTheSolverInterface) {
  const std::unique_ptr<Solver> s = make_solver(source_windy_sheet(true, true, Precision::f32));
  EXPECT_EQ(s->force_field_source(), ForceSource::total);  // before any update
  ASSERT_TRUE(s->step(100).ok());
  s->update_force_field(ForceSource::drag);
  EXPECT_EQ(s->force_field_source(), ForceSource::drag);
  const Vec3d drag = s->force(50);
  s->update_force_field();  // the default is the total
  EXPECT_EQ(s->force_field_source(), ForceSource::total);
  EXPECT_NE(s->force(50)[1], drag[1]);
  for (ForceSource source : kAllForceSources) {
    s->update_force_field(source);
    EXPECT_EQ(s->force_field_source(), source);
  }
}

template <class T>
void expect_source_allocates_nothing() {
  const auto s_owner = testing::solver<T>(source_windy_sheet(true, true, precision_of<T>()));
  Solver& s = *s_owner;
  run_a_while(s);
  for (ForceSource source : kAllForceSources) s.update_force_field(source);  // warm-up
  const long before = g_allocations.load();
  for (int k = 0; k < 3; ++k)
    for (ForceSource source : kAllForceSources) s.update_force_field(source);
  EXPECT_EQ(g_allocations.load() - before, 0);
}

TEST(ForceSource, UpdatingAllocatesNothing) {
  expect_source_allocates_nothing<float>();
  expect_source_allocates_nothing<double>();
}

TEST(ForceSource, NamesRoundTrip) {
  const std::array<std::string_view, 5> names = {"total", "springs", "gravity", "drag", "wind"};
  for (std::size_t k = 0; k < kAllForceSources.size(); ++k) {
    EXPECT_EQ(force_source_name(kAllForceSources[k]), names[k]);
    EXPECT_EQ(parse_force_source(names[k]), kAllForceSources[k]);
  }
  EXPECT_FALSE(parse_force_source("Total").has_value());
  EXPECT_FALSE(parse_force_source("").has_value());
  EXPECT_FALSE(parse_force_source("spring").has_value());
}

}  // namespace
}  // namespace clothlab
