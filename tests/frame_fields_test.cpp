// The frame's field snapshot (sim/fields/frame_fields.hpp): the springs' strain against its
// closed form, exactly the requested fields, equal to the solver's own, and no allocation on a
// frame that keeps its request.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "sim/fields/frame_fields.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/scalar_field.hpp"

namespace clothlab {
namespace {

std::unique_ptr<Solver> stretched_sheet(double factor, Vec3d shift) {
  std::unique_ptr<Solver> solver = make_solver(testing::grid_sheet(8, 6));
  std::vector<Vec3d> x(solver->vertex_count()), v(solver->vertex_count(), Vec3d{0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3d r = solver->rest_position(static_cast<int>(i));
    for (int k = 0; k < 3; ++k) x[i][k] = factor * r[k] + shift[k];
  }
  solver->set_state(x, v);
  return solver;
}

// The window's error view hands in each vertex's distance from its reference: the "error" colour
// shows it in mm; a distance of another length (another cloth, or none yet) shows as zero, and
// every frame starts without one.
TEST(FrameFields, TheReferenceDistanceIsHandedInAndShownInMillimetres) {
  std::unique_ptr<Solver> solver = stretched_sheet(1.0, {0.0, 0.0, 0.0});
  const std::size_t n = solver->vertex_count();
  FieldSnapshot snapshot;
  snapshot.take(*solver, {});
  std::vector<float> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = 1e-4f * float(i);
  snapshot.set_reference_distance(d);
  std::vector<float> mm;
  vis::scalar_values(snapshot.fields(), vis::ScalarField::error, ForceSource::total, mm);
  ASSERT_EQ(mm.size(), n);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(mm[i], 0.1 * double(i), 1e-5);
  snapshot.set_reference_distance(std::vector<float>(n + 1, 1.0f));
  vis::scalar_values(snapshot.fields(), vis::ScalarField::error, ForceSource::total, mm);
  for (float v : mm) EXPECT_EQ(v, 0.0f);
  EXPECT_TRUE(snapshot.take(*solver, {}).reference_distance.empty());
  EXPECT_THROW(
      vis::scalar_values(snapshot.fields(), vis::ScalarField::error, ForceSource::total, mm),
      std::logic_error);
}

// A uniform stretch by s strains every spring, and so every vertex's mean, by s - 1; a
// translation strains nothing.
TEST(FrameFields, UniformStretchStrainsEverySpringAlike) {
  for (const double s : {1.0, 1.25, 0.8}) {
    std::unique_ptr<Solver> solver = stretched_sheet(s, {0.3, -2.0, 0.7});
    FieldSnapshot snapshot;
    FieldRequest request;
    request.spring_strain = request.vertex_strain = true;
    const FrameFields& f = snapshot.take(*solver, request);
    ASSERT_EQ(f.spring_strain.size(), solver->spring_count());
    ASSERT_EQ(f.vertex_strain.size(), solver->vertex_count());
    for (float e : f.spring_strain) EXPECT_NEAR(e, s - 1.0, 2e-6) << "stretch " << s;
    for (float e : f.vertex_strain) EXPECT_NEAR(e, s - 1.0, 2e-6) << "stretch " << s;
  }
}

// One spring stretched: its strain is (l - l0) / l0, its two vertices share it among their springs.
TEST(FrameFields, OneStretchedSpringShowsAtItsEnds) {
  std::unique_ptr<Solver> solver =
      make_solver(testing::single_spring(0.1, 50.0, 0.5, IntegratorKind::verlet, 1e-3));
  std::vector<Vec3d> x = {solver->rest_position(0), solver->rest_position(1)};
  x[1][1] -= 0.1;  // 0.5 m -> 0.6 m
  solver->set_state(x, {Vec3d{0.0, 0.0, 0.0}, Vec3d{0.0, 0.0, 0.0}});
  FieldSnapshot snapshot;
  FieldRequest request;
  request.vertex_strain = true;
  const FrameFields& f = snapshot.take(*solver, request);
  EXPECT_TRUE(f.spring_strain.empty());  // asked for the vertices' mean alone
  ASSERT_EQ(f.vertex_strain.size(), 2u);
  EXPECT_NEAR(f.vertex_strain[0], 0.2, 1e-6);
  EXPECT_NEAR(f.vertex_strain[1], 0.2, 1e-6);
}

// The snapshot holds what was asked (positions and normals always on the CPU), equal to the
// solver's own values, and nothing else.
TEST(FrameFields, HoldsExactlyTheRequestedFields) {
  std::unique_ptr<Solver> solver = make_solver(testing::grid_sheet(8, 6));
  ASSERT_TRUE(solver->advance(0.05).ok());
  FieldSnapshot snapshot;
  FieldRequest request;
  request.add_force(ForceSource::gravity);
  request.add_force(ForceSource::springs);
  const FrameFields& f = snapshot.take(*solver, request);
  const std::size_t n = solver->vertex_count();
  EXPECT_EQ(f.vertices, n);
  EXPECT_DOUBLE_EQ(f.time, solver->time());
  ASSERT_EQ(f.positions.size(), 3 * n);
  ASSERT_EQ(f.normals.size(), 3 * n);
  EXPECT_TRUE(f.velocities.empty());
  EXPECT_FALSE(f.has_force(ForceSource::total));
  EXPECT_FALSE(f.has_force(ForceSource::wind));
  ASSERT_TRUE(f.has_force(ForceSource::gravity));
  ASSERT_TRUE(f.has_force(ForceSource::springs));
  EXPECT_TRUE(f.spring_strain.empty() && f.vertex_strain.empty());
  solver->update_force_field(ForceSource::springs);
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3d p = solver->position(int(v)), fs = solver->force(int(v));
    for (int k = 0; k < 3; ++k) {
      EXPECT_FLOAT_EQ(f.positions[3 * v + k], float(p[k]));
      EXPECT_FLOAT_EQ(f.force(ForceSource::springs)[3 * v + k], float(fs[k]));
    }
    // Gravity is m g on every vertex (the mass is shared evenly on this sheet).
    EXPECT_NEAR(f.force(ForceSource::gravity)[3 * v + 1], -9.81 * solver->mass(int(v)), 1e-6);
    const float* nv = &f.normals[3 * v];
    EXPECT_NEAR(std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]), 1.0, 1e-5);
  }
}

// A frame that keeps its request reuses every buffer; dropping a field keeps its memory.
TEST(FrameFields, AFrameThatKeepsItsRequestReusesItsBuffers) {
  std::unique_ptr<Solver> solver = make_solver(testing::grid_sheet(8, 6));
  FieldSnapshot snapshot;
  FieldRequest request;
  request.velocities = request.spring_strain = true;
  request.add_force(ForceSource::total);
  const FrameFields& first = snapshot.take(*solver, request);
  const float* buffers[] = {first.positions.data(), first.normals.data(), first.velocities.data(),
                            first.force(ForceSource::total).data(), first.spring_strain.data()};
  ASSERT_TRUE(solver->advance(0.01).ok());
  const FrameFields& second = snapshot.take(*solver, request);
  const float* again[] = {second.positions.data(), second.normals.data(), second.velocities.data(),
                          second.force(ForceSource::total).data(), second.spring_strain.data()};
  for (int b = 0; b < 5; ++b) EXPECT_EQ(buffers[b], again[b]) << "buffer " << b;
  const std::size_t capacity = second.velocities.capacity();
  snapshot.take(*solver, FieldRequest{});
  EXPECT_TRUE(snapshot.fields().velocities.empty());
  EXPECT_EQ(snapshot.fields().velocities.capacity(), capacity);
}

}  // namespace
}  // namespace clothlab
