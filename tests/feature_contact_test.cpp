// A collider's sharp features as contact points against the cloth's triangles
// (sim/contact/feature_contacts.hpp, issue 20): the features a box and an OBJ box give, the
// shipped crate and chair drops with no corner inside the cloth's thickness, and the same drop
// for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "load/scene_load.hpp"
#include "sim/contact/collider.hpp"
#include "sim/contact/feature_contacts.hpp"
#include "sim/contact/sharp_features.hpp"
#include "sim/mesh/closest_point.hpp"
#include "sim/model/model.hpp"
#include "sim/solver.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;

V3 vec(const Vec3d& v) {
  return {v[0], v[1], v[2]};
}

// The distance from world point p to the cloth's surface (its nearest triangle).
double distance_to_cloth(const Solver& s, const V3& p) {
  double best = INFINITY;
  for (const std::array<int, 3>& t : s.triangles()) {
    const TrianglePoint c =
        closest_on_triangle(p, vec(s.position(t[0])), vec(s.position(t[1])), vec(s.position(t[2])));
    best = std::min(best, (c.point - p).norm());
  }
  return best;
}

// The smallest distance from the cloth of `corners` (in the first collider's own frame) over
// `seconds`, looked at every 1/240 s.
double closest_approach(Solver& s, const Collider& collider, const std::vector<V3>& corners,
                        double seconds) {
  double closest = INFINITY;
  const int frames = static_cast<int>(std::lround(seconds * 240.0));
  for (int f = 0; f < frames; ++f) {
    EXPECT_TRUE(s.advance(1.0 / 240.0).ok());
    const ColliderPose pose = collider.pose(s.time());
    for (const V3& c : corners) closest = std::min(closest, distance_to_cloth(s, pose.to_world(c)));
  }
  return closest;
}

// A box's features: its eight corners on the rounded surface along the corner's diagonal, and
// points along every edge no further apart than the spacing, all on the surface (distance 0)
// with unit outward directions.
TEST(SharpFeatures, BoxCornersAndEdgesLieOnItsRoundedSurface) {
  ColliderSpec box;
  box.kind = ColliderKind::box;
  box.half_extents = {0.3, 0.25, 0.2};
  box.rounding = 0.02;
  const SharpFeatures f = sharp_features(box, 0.05);
  const Collider collider(box);
  // Edges: 4 along x of 0.56 m (12 gaps of <= 0.05 m: 11 points), 4 along y of 0.46 (10 gaps: 9
  // points), 4 along z of 0.36 (8 gaps: 7 points).
  ASSERT_EQ(f.points.size(), 8u + 4u * (11 + 9 + 7));
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    EXPECT_NEAR(collider.local_distance(f.points[i]).phi, 0.0, 1e-12) << i;
    EXPECT_NEAR(f.outward[i].norm(), 1.0, 1e-12);
  }
  const V3 corner = V3(0.28, 0.23, 0.18) + 0.02 * V3(1, 1, 1).normalized();
  EXPECT_LT((f.points[7] - corner).norm(), 1e-12);
}

// An OBJ cube (six quads, each fanned into two triangles): its eight vertices and its twelve
// creases are features; the quads' diagonals, across flat faces, are not.
TEST(SharpFeatures, MeshCreasesButNotFlatDiagonals) {
  TriangleMesh cube;
  for (int k = 0; k < 8; ++k)
    cube.positions.emplace_back(k & 1 ? 0.5 : -0.5, k & 2 ? 0.5 : -0.5, k & 4 ? 0.5 : -0.5);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    cube.triangles.push_back({q[0], q[1], q[2]});
    cube.triangles.push_back({q[0], q[2], q[3]});
  }
  ColliderSpec spec;
  spec.kind = ColliderKind::mesh;
  spec.mesh = std::make_shared<const TriangleMesh>(cube);
  const SharpFeatures f = sharp_features(spec, 0.3);  // each 1 m edge: 4 gaps, 3 points
  ASSERT_EQ(f.points.size(), 8u + 12u * 3u);
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    // On an edge of the cube: two coordinates at +-0.5.
    int on_faces = 0;
    for (int d = 0; d < 3; ++d) on_faces += std::abs(std::abs(f.points[i][d]) - 0.5) < 1e-12;
    EXPECT_GE(on_faces, 2) << "feature " << i << " lies inside a face";
    // Outward: along the point's own direction from the centre, for corners and edges alike.
    V3 expected = V3::Zero();
    for (int d = 0; d < 3; ++d)
      if (std::abs(std::abs(f.points[i][d]) - 0.5) < 1e-12) expected[d] = f.points[i][d];
    EXPECT_LT((f.outward[i] - expected.normalized()).norm(), 1e-9) << i;
  }
}

// scenes/drop_box.toml: the sheet let go at 0.3 s falls onto the crate, folds over its edges and
// slides off. Through all of it no corner of the crate comes nearer the cloth than 0.9 of the
// collider's thickness (5 mm). Before the crate's corners were contact points they came within
// 0.3 mm of the cloth's surface and showed through it as light specks.
TEST(FeatureContacts, NoCrateCornerInsideTheClothsThickness) {
  Scene scene = read_scene_file(std::string(CLOTHLAB_SOURCE_DIR "/scenes/drop_box.toml"));
  scene.cloths[0].release_at = 0.3;
  const ColliderSpec& box = scene.colliders[0];
  ASSERT_EQ(box.kind, ColliderKind::box);
  std::vector<V3> corners;
  for (int k = 0; k < 8; ++k) {
    const V3 s(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0);
    const V3 inner = vec(box.half_extents) - V3::Constant(box.rounding);
    corners.push_back(s.cwiseProduct(inner) + box.rounding * s.normalized());
  }
  auto solver = make_solver(scene);
  const double closest = closest_approach(*solver, pose_only_collider(box), corners, 3.0);
  EXPECT_GE(closest, 0.9 * box.thickness);
}

// scenes/chair.toml: the sheet falls onto the chair read from its OBJ. None of the chair's mesh
// vertices (the corners of its seat, backrest and legs) comes nearer the cloth than half the
// collider's 6 mm thickness over 2 s of fall and drape (before: 0.16 mm, at the impact).
TEST(FeatureContacts, NoChairCornerInsideTheClothsThickness) {
  Scene scene = read_scene_file(std::string(CLOTHLAB_SOURCE_DIR "/scenes/chair.toml"));
  const ColliderSpec& chair = scene.colliders[0];
  ASSERT_EQ(chair.kind, ColliderKind::mesh);
  const std::vector<V3> corners(chair.mesh->positions.begin(), chair.mesh->positions.end());
  auto solver = make_solver(scene);
  const double closest = closest_approach(*solver, pose_only_collider(chair), corners, 2.0);
  EXPECT_GE(closest, 0.5 * chair.thickness);
}

// A collider at least one cloth edge thick needs no features (its vertex contacts keep every
// point of a triangle off it) and gets none: a fuzzed chair 2 m thick, where every feature was
// within the thickness of every triangle, took 0.36 s a step. One just thinner than the edge
// keeps its features.
TEST(FeatureContacts, NoneForAColliderAtLeastOneEdgeThick) {
  Scene scene = read_scene_file(std::string(CLOTHLAB_SOURCE_DIR "/scenes/drop_box.toml"));
  const Model<double> model = build_model<double>(scene);
  const double edge = 0.05;
  scene.colliders[0].thickness = edge;
  EXPECT_TRUE(FeatureContacts<double>({Collider(scene.colliders[0])}, model, edge).empty());
  scene.colliders[0].thickness = 0.99 * edge;
  EXPECT_FALSE(FeatureContacts<double>({Collider(scene.colliders[0])}, model, edge).empty());
}

// The feature contacts run serially over the triangles after per-block marking, so the crate drop
// gives the same result on 1 and 2 threads, bit for bit.
TEST(FeatureContacts, SameResultForAnyThreadCount) {
  Scene scene = read_scene_file(std::string(CLOTHLAB_SOURCE_DIR "/scenes/drop_box.toml"));
  scene.cloths[0].release_at = 0.0;
  scene.cloths[0].origin = {-0.3, 1.1, -0.6};  // centred over the crate
  scene.cloths[0].resolution = {40, 40};       // several blocks of vertices
  scene.cloths[0].pins.clear();
  scene.solver.threads = 1;
  std::unique_ptr<Solver> one = make_solver(scene);
  scene.solver.threads = 2;
  std::unique_ptr<Solver> two = make_solver(scene);
  ASSERT_TRUE(one->advance(0.6).ok());
  ASSERT_TRUE(two->advance(0.6).ok());
  EXPECT_GT(one->position(20 + 20 * 40)[1], 0.5) << "the sheet lies on the crate";
  for (std::size_t i = 0; i < one->vertex_count(); ++i)
    ASSERT_EQ(one->position(int(i)), two->position(int(i))) << "vertex " << i;
}

}  // namespace
}  // namespace clothlab
