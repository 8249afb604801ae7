// Triangle contact (sim/contact/triangle_contact.hpp) and the pieces it is built from: the
// closest-point functions and the box cut before them, the crossing test, the intersection count
// (against its definition, every edge against every triangle), the conservative CCD on its hard
// cases and against a dense sampling of random motions, the rigid fit of the Verlet list, and the
// stress scenes: no crossing edge/triangle pair in any frame with contact on (and thousands
// without), the same bytes on 1 and 2 threads, no energy gained.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>
#include <cstring>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "grid_mesh.hpp"
#include "load/scene_load.hpp"
#include "sim/contact/ccd.hpp"
#include "sim/contact/intersections.hpp"
#include "sim/contact/pair_spans.hpp"
#include "sim/contact/primitive_distance.hpp"
#include "sim/contact/rigid_fit.hpp"
#include "sim/contact/segment_crossing.hpp"
#include "sim/contact/triangle_contact.hpp"
#include "sim/fields/contact_gaps.hpp"
#include "sim/model/model.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/solver.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;
const std::string kScenes = std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/";

// ---- closest points -------------------------------------------------------------------------

// The closest point is no farther than any point of a fine barycentric sampling, and no nearer
// than the best of them by more than the sampling's spacing allows.
TEST(PrimitiveDistance, PointTriangleIsTheMinimumOverTheTriangle) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const V3 p(u(rng), u(rng), u(rng)), a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)),
        c(u(rng), u(rng), u(rng));
    const PointTriangleClosest r = closest_point_triangle(p, a, b, c);
    EXPECT_NEAR(r.w[0] + r.w[1] + r.w[2], 1.0, 1e-12);
    for (double w : r.w) EXPECT_GE(w, -1e-12);
    EXPECT_NEAR((p - (r.w[0] * a + r.w[1] * b + r.w[2] * c)).squaredNorm(), r.dist2, 1e-12);
    double best = INFINITY;
    constexpr int kN = 60;
    for (int i = 0; i <= kN; ++i)
      for (int j = 0; i + j <= kN; ++j) {
        const double s = double(i) / kN, t = double(j) / kN;
        best = std::min(best, (p - ((1 - s - t) * a + s * b + t * c)).norm());
      }
    EXPECT_LE(std::sqrt(r.dist2), best + 1e-12);
    EXPECT_GE(std::sqrt(r.dist2), best - 0.05);
  }
}

TEST(PrimitiveDistance, DegenerateTrianglesAndSegments) {
  // A zero-area triangle (three points on a line) is its longest side.
  const PointTriangleClosest r =
      closest_point_triangle(V3(0.5, 1, 0), V3(0, 0, 0), V3(1, 0, 0), V3(2, 0, 0));
  EXPECT_NEAR(r.dist2, 1.0, 1e-12);
  // All three corners on one spot.
  EXPECT_NEAR(point_triangle_dist2(V3(0, 3, 4), V3::Zero(), V3::Zero(), V3::Zero()), 25.0, 1e-12);
  // Parallel segments 1 apart, overlapping: distance 1.
  EXPECT_NEAR(edge_edge_dist2(V3(0, 0, 0), V3(2, 0, 0), V3(1, 1, 0), V3(3, 1, 0)), 1.0, 1e-12);
  // Collinear and disjoint: the gap between the ends.
  EXPECT_NEAR(edge_edge_dist2(V3(0, 0, 0), V3(1, 0, 0), V3(3, 0, 0), V3(2, 0, 0)), 1.0, 1e-12);
  // A zero-length segment is a point.
  EXPECT_NEAR(edge_edge_dist2(V3(0, 2, 0), V3(0, 2, 0), V3(-1, 0, 0), V3(1, 0, 0)), 4.0, 1e-12);
  // Skew segments crossing at right angles, 0.5 apart.
  const EdgeEdgeClosest e =
      closest_edge_edge(V3(-1, 0, 0), V3(1, 0, 0), V3(0, -1, 0.5), V3(0, 1, 0.5));
  EXPECT_NEAR(e.dist2, 0.25, 1e-12);
  EXPECT_NEAR(e.s, 0.5, 1e-12);
  EXPECT_NEAR(e.t, 0.5, 1e-12);
}

// The closest points of two segments are no farther apart than any pair of a fine sampling of
// both, and no nearer than the best of them by more than its spacing allows; random segments
// clamp either parameter at either end.
TEST(PrimitiveDistance, EdgeEdgeIsTheMinimumOverBothSegments) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int clamped = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const V3 p0(u(rng), u(rng), u(rng)), p1(u(rng), u(rng), u(rng)), q0(u(rng), u(rng), u(rng)),
        q1(u(rng), u(rng), u(rng));
    const EdgeEdgeClosest r = closest_edge_edge(p0, p1, q0, q1);
    EXPECT_GE(r.s, 0.0);
    EXPECT_LE(r.s, 1.0);
    EXPECT_GE(r.t, 0.0);
    EXPECT_LE(r.t, 1.0);
    clamped += r.t == 0.0 || r.t == 1.0;
    EXPECT_NEAR((p0 + r.s * (p1 - p0) - (q0 + r.t * (q1 - q0))).squaredNorm(), r.dist2, 1e-12);
    double best = INFINITY;
    constexpr int kN = 80;
    for (int i = 0; i <= kN; ++i)
      for (int j = 0; j <= kN; ++j) {
        const double s = double(i) / kN, t = double(j) / kN;
        best = std::min(best, (p0 + s * (p1 - p0) - (q0 + t * (q1 - q0))).norm());
      }
    EXPECT_LE(std::sqrt(r.dist2), best + 1e-12);
    EXPECT_GE(std::sqrt(r.dist2), best - 0.05);
  }
  EXPECT_GT(clamped, 30);  // the clamped ends are exercised
}

// The gap between the boxes around a pair's two sides (the collection's cut before the exact
// distance) never exceeds their distance, and is the distance where the boxes sit side by side.
TEST(PairSpans, BoxGapNeverExceedsTheDistance) {
  const V3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
  // A point beside the triangle along x: gap and distance both 2.
  EXPECT_DOUBLE_EQ(box_gap2(false, {V3(3, 0, 0), o, x, y}), 4.0);
  // A point off the triangle's hypotenuse: the boxes' gap (1, 1, 0) is nearer than the
  // triangle, at 3 / sqrt(2).
  EXPECT_DOUBLE_EQ(box_gap2(false, {V3(2, 2, 0), o, x, y}), 2.0);
  EXPECT_NEAR(point_triangle_dist2(V3(2, 2, 0), o, x, y), 4.5, 1e-12);
  // Boxes that meet: no gap.
  EXPECT_EQ(box_gap2(true, {V3(0, 0, 1), V3(1, 1, 1), V3(1, 0, 1), V3(0, 1, 1)}), 0.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int cut = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<V3, 4> v;
    for (V3& p : v) p = V3(u(rng), u(rng), u(rng));
    v[0] += V3(1.5, 0, 0);  // the first side apart, so that some boxes do not meet
    const bool edge_edge = trial % 2 == 1;
    if (edge_edge) v[1] += V3(1.5, 0, 0);
    const double gap2 = box_gap2(edge_edge, v);
    const double dist2 = edge_edge ? edge_edge_dist2(v[0], v[1], v[2], v[3])
                                   : point_triangle_dist2(v[0], v[1], v[2], v[3]);
    EXPECT_LE(gap2, dist2 * (1.0 + 1e-12)) << trial;
    cut += gap2 > 0.0;
  }
  EXPECT_GT(cut, 200);
}

// ---- the crossing test and the count ---------------------------------------------------------

TEST(SegmentCrossing, ConstructedCases) {
  const V3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(segment_crosses_triangle(V3(0.2, 0.2, -1), V3(0.2, 0.2, 1), a, b, c));
  EXPECT_TRUE(segment_crosses_triangle(V3(0.2, 0.2, 1), V3(0.3, 0.1, -1), a, b, c));
  // Outside the triangle, ending on its plane, touching an edge or a corner: no crossing.
  EXPECT_FALSE(segment_crosses_triangle(V3(0.8, 0.8, -1), V3(0.8, 0.8, 1), a, b, c));
  EXPECT_FALSE(segment_crosses_triangle(V3(0.2, 0.2, 0), V3(0.2, 0.2, 1), a, b, c));
  EXPECT_FALSE(segment_crosses_triangle(V3(0.5, 0, -1), V3(0.5, 0, 1), a, b, c));
  EXPECT_FALSE(segment_crosses_triangle(V3(0, 0, -1), V3(0, 0, 1), a, b, c));
  // In the plane (coplanar), even across the triangle: touching, not crossing.
  EXPECT_FALSE(segment_crosses_triangle(V3(-1, 0.2, 0), V3(2, 0.2, 0), a, b, c));
  // A degenerate triangle has no inside.
  EXPECT_FALSE(segment_crosses_triangle(V3(0.5, 0, -1), V3(0.5, 0, 1), a, b, V3(2, 0, 0)));
}

using Sheet = GridMesh;
Sheet grid(int n, double y) {
  return grid_mesh(n, n, [y](int i, int j) { return V3(0.1 * i, y, 0.1 * j); });
}
long tree_count(const Sheet& s) {
  IntersectionCounter counter(s.triangles, s.x);
  return counter.count(s.x);
}

TEST(IntersectionCount, ConstructedSheets) {
  const Sheet one = grid(8, 0.0);
  EXPECT_EQ(tree_count(one), 0);
  // Two parallel sheets 1 mm apart, and two on the same plane (touching everywhere): none.
  for (const double y : {0.001, 0.0}) {
    Sheet two = one;
    add_grid(two, 8, 8, 1, [y](int i, int j) { return V3(0.1 * i, y, 0.1 * j); });
    EXPECT_EQ(tree_count(two), 0);
  }
  // A vertical sheet through the middle of a horizontal one: each of the vertical sheet's 7
  // columns of vertical edges crosses it once, and so does each diagonal of the row of squares
  // the plane cuts (7), and the horizontal sheet's edges pass through nothing of it but its
  // triangles: counted by the definition, and equal to it.
  Sheet cross = one;
  add_grid(cross, 8, 8, 1, [](int i, int j) { return V3(0.05 + 0.1 * i, -0.3 + 0.1 * j, 0.37); });
  const long expected = count_crossings_brute_force(cross.triangles, cross.x);
  EXPECT_GT(expected, 14);
  EXPECT_EQ(tree_count(cross), expected);
}

// A sheet crumpled at random into a small box crosses itself thousands of times; the tree's
// count equals the definition's, and a renumbering of the vertices changes neither.
TEST(IntersectionCount, CrumpledSheetMatchesTheDefinition) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 0.3);
  const Sheet s = grid_mesh(16, 16, [&](int, int) { return V3(u(rng), u(rng), u(rng)); });
  const long expected = count_crossings_brute_force(s.triangles, s.x);
  EXPECT_GT(expected, 1000);
  EXPECT_EQ(tree_count(s), expected);
  // Reversed vertex numbering.
  Sheet r = s;
  const int n = int(s.x.size());
  for (int v = 0; v < n; ++v) r.x[std::size_t(v)] = s.x[std::size_t(n - 1 - v)];
  for (auto& t : r.triangles)
    for (int& v : t) v = n - 1 - v;
  EXPECT_EQ(tree_count(r), expected);
}

// ---- continuous collision detection ---------------------------------------------------------

double ccd(PrimitivePair kind, std::array<V3, 4> x0, std::array<V3, 4> x1, double eta = 0.0) {
  CcdOptions o;
  o.eta = eta;
  return additive_ccd(kind, x0, x1, o);
}
constexpr auto kPT = PrimitivePair::point_triangle;
constexpr auto kEE = PrimitivePair::edge_edge;

TEST(Ccd, HardCases) {
  const V3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Straight through the middle at t = 0.5: reported no later than that, and not much earlier.
  double t = ccd(kPT, {V3(0.2, 0.2, 1), a, b, c}, {V3(0.2, 0.2, -1), a, b, c});
  EXPECT_GE(t, 0.4);
  EXPECT_LE(t, 0.5);
  // Passing beside the triangle, 0.1 from its corner: no contact.
  EXPECT_LT(ccd(kPT, {V3(1.1, 0, 1), a, b, c}, {V3(1.1, 0, -1), a, b, c}), 0.0);
  // Touching exactly at the end of the step: contact.
  t = ccd(kPT, {V3(0.2, 0.2, 1), a, b, c}, {V3(0.2, 0.2, 0), a, b, c});
  EXPECT_GE(t, 0.0);
  EXPECT_LE(t, 1.0);
  // Coplanar: a point sliding in the triangle's plane into its edge.
  EXPECT_GE(ccd(kPT, {V3(0.5, -0.5, 0), a, b, c}, {V3(0.5, 0.5, 0), a, b, c}), 0.0);
  // Coplanar and staying outside: no contact.
  EXPECT_LT(ccd(kPT, {V3(2, -0.5, 0), a, b, c}, {V3(2, 0.5, 0), a, b, c}), 0.0);
  // Parallel edges closing to each other (the cubic's degenerate case) and passing.
  const V3 p0(0, 0, 0), p1(1, 0, 0);
  EXPECT_GE(ccd(kEE, {p0, p1, V3(0, 0, 1), V3(1, 0, 1)}, {p0, p1, V3(0, 0, -1), V3(1, 0, -1)}),
            0.0);
  // Parallel and staying 0.1 apart while sliding along: none.
  EXPECT_LT(
      ccd(kEE, {p0, p1, V3(0, 0.1, 0), V3(1, 0.1, 0)}, {p0, p1, V3(5, 0.1, 0), V3(6, 0.1, 0)}),
      0.0);
  // Moving together (a rigid translation): distances never change, never contact.
  const V3 d(0, 0, -3);
  EXPECT_LT(ccd(kPT, {V3(0.2, 0.2, 0.01), a, b, c}, {V3(0.2, 0.2, 0.01) + d, a + d, b + d, c + d}),
            0.0);
  // A root within round-off of 0: starting 1e-12 above the face and moving down.
  t = ccd(kPT, {V3(0.2, 0.2, 1e-12), a, b, c}, {V3(0.2, 0.2, -1), a, b, c});
  EXPECT_GE(t, 0.0);
  EXPECT_LE(t, 1e-9);
  // Within round-off of 1: touching at t = 1 - 1e-12.
  EXPECT_GE(ccd(kPT, {V3(0.2, 0.2, 1), a, b, c}, {V3(0.2, 0.2, -1e-12), a, b, c}), 0.0);
  // With a separation eta: a pass 1 mm above the face counts within 2 mm. Within 0.5 mm it
  // counts too while the stop is a tenth of the 1 m gap it started with, not with a 0.1 mm
  // tolerance (which the fail-safe sets).
  const std::array<V3, 4> over0{V3(-1, 0.2, 0.001), a, b, c}, over1{V3(2, 0.2, 0.001), a, b, c};
  EXPECT_GE(ccd(kPT, over0, over1, 0.002), 0.0);
  EXPECT_GE(ccd(kPT, over0, over1, 0.0005), 0.0);
  // (A 20 cm pass: 3 m at this gap would take more advances than the cap, and count.)
  const std::array<V3, 4> short0{V3(0.05, 0.2, 0.001), a, b, c},
      short1{V3(0.25, 0.2, 0.001), a, b, c};
  CcdOptions tight;
  tight.eta = 0.0005;
  tight.tolerance = 0.0001;
  EXPECT_LT(additive_ccd(kPT, short0, short1, tight), 0.0);
  tight.eta = 0.00095;
  EXPECT_GE(additive_ccd(kPT, short0, short1, tight), 0.0);
}

// Random straight motions of a point and a triangle and of two edges: every one whose distance,
// sampled at 2000 times, falls to zero (or below eta) is reported, and the reported time is no
// later than the first such sample.
TEST(Ccd, NeverMissesASampledContact) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int met = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const PrimitivePair kind = trial % 2 ? kEE : kPT;
    std::array<V3, 4> x0, x1;
    for (int k = 0; k < 4; ++k) {
      x0[std::size_t(k)] = V3(u(rng), u(rng), u(rng));
      x1[std::size_t(k)] = x0[std::size_t(k)] + 0.8 * V3(u(rng), u(rng), u(rng));
    }
    constexpr double kEta = 0.02;
    if (pair_dist2(kind, x0) <= kEta * kEta) continue;
    double first = -1.0;
    for (int i = 0; i <= 2000 && first < 0.0; ++i) {
      const double s = i / 2000.0;
      std::array<V3, 4> x;
      for (int k = 0; k < 4; ++k)
        x[std::size_t(k)] = (1 - s) * x0[std::size_t(k)] + s * x1[std::size_t(k)];
      if (pair_dist2(kind, x) <= kEta * kEta) first = s;
    }
    const double t = ccd(kind, x0, x1, kEta);
    if (first >= 0.0) {
      ++met;
      EXPECT_GE(t, 0.0) << "trial " << trial;
      EXPECT_LE(t, first + 1e-12) << "trial " << trial;
    }
  }
  EXPECT_GT(met, 200);
}

// ---- the rigid fit of the pairs' Verlet list ------------------------------------------------

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  const Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized().toRotationMatrix();
}

// Points moved by a known rigid motion (and 1e-9 of noise) give back its rotation; a mirror image
// still gives a rotation (determinant +1), never a reflection.
TEST(RigidFit, KabschRecoversTheRotation) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix3d Q = random_rotation(rng);
    const V3 shift(u(rng), u(rng), u(rng));
    std::vector<V3> a(50), b(50);
    V3 ma = V3::Zero(), mb = V3::Zero();
    for (std::size_t i = 0; i < a.size(); ++i) {
      a[i] = V3(u(rng), u(rng), 0.2 * u(rng));
      b[i] = Q * a[i] + shift + 1e-9 * V3(u(rng), u(rng), u(rng));
      ma += a[i] / 50.0;
      mb += b[i] / 50.0;
    }
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero(), M = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < a.size(); ++i) {
      H += (a[i] - ma) * (b[i] - mb).transpose();
      M += (a[i] - ma) *
           (V3(-b[i].x(), b[i].y(), b[i].z()) - V3(-mb.x(), mb.y(), mb.z())).transpose();
    }
    EXPECT_LT((kabsch_rotation(H) - Q).norm(), 1e-7);
    EXPECT_NEAR(kabsch_rotation(M).determinant(), 1.0, 1e-12);
  }
  EXPECT_EQ(kabsch_rotation(Eigen::Matrix3d::Zero()).determinant(), 1.0);
}

// The straight motion between two rotations shrinks no vector below the bound, and the bound is
// reached (at s = 1/2, across the axis).
TEST(RigidFit, InterpolatedRotationShrinkIsATightLowerBound) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Matrix3d A = random_rotation(rng);
    Eigen::Matrix3d B = random_rotation(rng);
    if (trial % 2) B = A * Eigen::AngleAxisd(0.01 * trial, V3::UnitX()).toRotationMatrix();
    const double bound = interpolated_rotation_shrink(A, B);
    double least = INFINITY;
    for (int k = 0; k <= 100; ++k) {
      const double t = k / 100.0;
      const Eigen::Matrix3d M = (1.0 - t) * A + t * B;
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M.transpose() * M,
                                                              Eigen::EigenvaluesOnly);
      least = std::min(least, std::sqrt(es.eigenvalues().minCoeff()));
    }
    EXPECT_LE(bound, least);
    EXPECT_GT(bound, least - 1e-8);
  }
}

// ---- the stress scenes ------------------------------------------------------------------------

Scene shipped(const std::string& name, const std::vector<std::string>& sets = {}) {
  return read_scene_file(kScenes + name, sets);
}

// The largest crossing count over the frames of `seconds` at 60 Hz.
long worst_frame(Solver& s, double seconds) {
  long worst = 0;
  for (int frame = 0; frame < int(std::lround(seconds * 60)); ++frame) {
    EXPECT_TRUE(s.advance(1.0 / 60).ok());
    worst = std::max(worst, s.intersections());
  }
  return worst;
}

// The closest vertex-triangle pair of different cloths, or of one cloth farther apart at rest
// than `thickness` (the pairs contact keeps apart), by brute force.
double closest_vertex_triangle(const Solver& s, double thickness) {
  std::vector<V3> x, rest;
  for (std::size_t i = 0; i < s.vertex_count(); ++i) {
    const Vec3d p = s.position(int(i)), r = s.rest_position(int(i));
    x.emplace_back(p[0], p[1], p[2]);
    rest.emplace_back(r[0], r[1], r[2]);
  }
  double best = INFINITY;
  for (const auto& t : s.triangles())
    for (std::size_t v = 0; v < x.size(); ++v) {
      if (t[0] == int(v) || t[1] == int(v) || t[2] == int(v)) continue;
      const auto at = [&](const std::vector<V3>& y) {
        return point_triangle_dist2(y[v], y[std::size_t(t[0])], y[std::size_t(t[1])],
                                    y[std::size_t(t[2])]);
      };
      if (at(rest) < thickness * thickness) continue;
      best = std::min(best, std::sqrt(at(x)));
    }
  return best;
}

// The largest speed at the ends of the next `frames` frames among the first `count` vertices whose
// position satisfies `at`; no frame may end with a crossing.
template <class At>
double fastest_over_frames(Solver& s, int frames, int count, const At& at) {
  double most = 0.0;
  for (int frame = 0; frame < frames; ++frame) {
    EXPECT_TRUE(s.advance(1.0 / 60).ok());
    EXPECT_EQ(s.intersections(), 0);
    for (int i = 0; i < count; ++i) {
      const Vec3d v = s.velocity(i);
      if (at(s.position(i))) most = std::max(most, std::hypot(v[0], v[1], v[2]));
    }
  }
  return most;
}

// The 48 x 48 silk sheet lets go at 2 s and lands in folds: no crossing in any frame over 5 s,
// and the layers that touch (over a thousand candidate pairs, some pushed apart in the last
// substep) at least 0.9 of the 4 mm thickness apart at the end. Then, over 0.5 s more, with no
// crossing, the layer lying on the floor (within 2 mm of its shell) at rest at every frame's end:
// under 0.05 m/s, where the pushes of the layers above, driving it into the floor until the plane
// put it back a substep later, left it at up to 0.5 m/s (0.0025 m/s with the pushes held against
// the colliders).
TEST(ClothContact, PileHasNoCrossingInAnyFrame) {
  std::unique_ptr<Solver> s = make_solver(shipped("pile.toml"));
  EXPECT_EQ(worst_frame(*s, 5.0), 0);
  EXPECT_GT(s->last_cloth_contact()->candidates, 1000);
  EXPECT_GT(s->last_cloth_contact()->contacts, 0);
  EXPECT_GE(closest_vertex_triangle(*s, 0.004), 0.9 * 0.004);
  const auto on_floor = [](const Vec3d& p) { return p[1] < 0.007; };
  EXPECT_LT(fastest_over_frames(*s, 30, int(s->vertex_count()), on_floor), 0.05);
}

// The same scene without triangle contact: the pile passes through itself (a test that can fail).
TEST(ClothContact, PileCrossesItselfWithoutIt) {
  std::unique_ptr<Solver> s = make_solver(shipped("pile.toml", {"solver.cloth_contact=false"}));
  EXPECT_GT(worst_frame(*s, 5.0), 100);
}

// No crossing in any frame over 2 s, and, once the sheets rest on the ball (1.5-2 s), the lower
// sheet over the top of the ball at rest at every frame's end: under 0.1 m/s, where pushes of the
// upper sheet that drove it into the ball (the collider putting it back a substep later) left it
// at up to 0.9 m/s (0.013 m/s with the pushes held against the colliders).
TEST(ClothContact, StackOnBallHasNoCrossingInAnyFrame) {
  std::unique_ptr<Solver> s = make_solver(shipped("stack_on_ball.toml"));
  EXPECT_EQ(worst_frame(*s, 1.5), 0);
  // The lower sheet (its 41 x 41 vertices first) within 10 cm of the top of the ball in plan.
  const auto on_top = [](const Vec3d& p) { return p[0] * p[0] + p[2] * p[2] < 0.01; };
  EXPECT_LT(fastest_over_frames(*s, 30, 1681, on_top), 0.1);
  // Over the top of the ball the upper sheet lies on the lower one, at least 0.9 of the 4 mm
  // thickness above it (each sheet's vertex nearest the top in plan; 1.3 cm apart at most in
  // plan, where the ball's surface falls 0.2 mm).
  const auto top_height = [&](int first) {
    int best = first;
    for (int i = first; i < first + 1600; ++i) {
      const Vec3d p = s->position(i), q = s->position(best);
      if (p[0] * p[0] + p[2] * p[2] < q[0] * q[0] + q[2] * q[2]) best = i;
    }
    return s->position(best)[1];
  };
  EXPECT_GT(top_height(1600), top_height(0) + 0.9 * 0.004 - 0.0002);
}

// The fast drop onto the thin table: the sheet meets the 4 mm top at 6.7 m/s, 11 mm a substep,
// more than the top and its two 2 mm shells (8 mm). In no frame does an edge cross a triangle or
// a vertex lie inside the top, and no vertex well inside the top's plan (5 cm in from its rim,
// at a frame's start and end) changes sides of it: a vertex tested only at the substep's end
// would be pushed out of the far side. Over the top, the sheet lands at the shell.
TEST(ClothContact, FastDropLandsOnTheThinTable) {
  std::unique_ptr<Solver> s = make_solver(shipped("thin_table.toml"));
  constexpr double kTop = 0.752, kShell = 0.002;
  const auto inside_plan = [](const Vec3d& p) {
    return std::abs(p[0]) < 0.45 && std::abs(p[2]) < 0.30;
  };
  std::vector<Vec3d> before(s->vertex_count());
  for (std::size_t i = 0; i < before.size(); ++i) before[i] = s->position(int(i));
  double speed = 0.0;
  for (int frame = 0; frame < 90; ++frame) {
    ASSERT_TRUE(s->advance(1.0 / 60).ok());
    ASSERT_EQ(s->intersections(), 0) << "frame " << frame;
    for (std::size_t i = 0; i < before.size(); ++i) {
      const Vec3d p = s->position(int(i));
      ASSERT_FALSE(std::abs(p[0]) < 0.5 && std::abs(p[2]) < 0.35 && std::abs(p[1] - 0.75) < 0.002)
          << "vertex " << i << " inside the top in frame " << frame;
      if (inside_plan(p) && inside_plan(before[i])) {
        ASSERT_EQ(p[1] > kTop, before[i][1] > kTop) << "vertex " << i << " frame " << frame;
      }
      if (frame == 40) speed = std::max(speed, -s->velocity(int(i))[1]);
      before[i] = p;
    }
  }
  EXPECT_GT(speed, 6.0);  // at full speed in the frame before it lands
  const Vec3d centre = s->position(24 * 48 + 24);
  EXPECT_NEAR(centre[1], kTop + kShell, 2e-4);
}

TEST(ClothContact, OneAndTwoThreadsGiveTheSameBytes) {
  std::vector<Vec3d> x[2];
  for (int threads = 1; threads <= 2; ++threads) {
    std::unique_ptr<Solver> s =
        make_solver(shipped("pile.toml", {"solver.threads=" + std::to_string(threads)}));
    ASSERT_TRUE(s->advance(2.6).ok());  // landing in folds
    for (std::size_t i = 0; i < s->vertex_count(); ++i)
      x[threads - 1].push_back(s->position(int(i)));
  }
  EXPECT_EQ(x[0], x[1]);
}

// One substep of triangle contact on the pile landed in folds, with a swirling 3 mm motion that
// drives its layers into each other: renumbering the vertices (a shuffle) moves every vertex to
// the same place (to round-off: an edge's ends may swap) with the same velocity, pushes and
// returns included.
TEST(ClothContact, RenumberedVerticesGetTheSameResponse) {
  const Scene scene = shipped("pile.toml");
  std::unique_ptr<Solver> solver = make_solver(scene);
  ASSERT_TRUE(solver->advance(4.0).ok());
  const Model<double> m = build_model<double>(scene);
  State<double> start;
  start.pos.resize(m.n);
  start.vel.resize(m.n);
  for (std::size_t i = 0; i < m.n; ++i) {
    const Vec3d p = solver->position(int(i));
    start.pos.set(i, p[0], p[1], p[2]);
  }
  const auto moved = [](const Vec3d& p) {
    return Vec3d{p[0] + 0.003 * std::sin(40 * p[2]), p[1] - 0.003 * std::sin(40 * p[0]),
                 p[2] + 0.003 * std::cos(40 * p[0])};
  };
  std::vector<int> to(m.n);
  std::iota(to.begin(), to.end(), 0);
  std::shuffle(to.begin(), to.end(), std::mt19937(3));
  Model<double> r = m;
  for (std::size_t i = 0; i < m.n; ++i) {
    const auto j = std::size_t(to[i]);
    r.inv_mass[j] = m.inv_mass[i];
    for (int a = 0; a < 3; ++a) r.rest_positions.axis(a)[j] = m.rest_positions.axis(a)[i];
  }
  for (auto& t : r.triangles)
    for (int& v : t) v = to[std::size_t(v)];
  const auto respond = [&](const Model<double>& model, const std::vector<int>& map) {
    State<double> s;
    s.pos.resize(m.n);
    s.vel.resize(m.n);
    for (std::size_t i = 0; i < m.n; ++i)
      for (int a = 0; a < 3; ++a) s.pos.axis(a)[std::size_t(map[i])] = start.pos.axis(a)[i];
    TriangleContact<double> contact(model, scene.solver);
    contact.begin(s, 1);
    for (std::size_t i = 0; i < m.n; ++i) {
      const auto j = std::size_t(map[i]);
      if (model.inv_mass[j] == 0.0) continue;
      const Vec3d p = moved({s.pos.x[j], s.pos.y[j], s.pos.z[j]});
      s.pos.set(j, p[0], p[1], p[2]);
      s.vel.set(j, 0.0, -0.6, 0.0);
    }
    contact.respond(model, s, 1.0 / 600.0, 1);
    return std::pair{s, contact.last()};
  };
  std::vector<int> same(m.n);
  std::iota(same.begin(), same.end(), 0);
  const auto [a, sa] = respond(m, same);
  const auto [b, sb] = respond(r, to);
  std::printf("renumbered pile: %d/%d candidates, %d/%d pushes, %d returned, %d/%d recollected\n",
              sa.candidates, sb.candidates, sa.contacts, sb.contacts, sa.rolled_back,
              int(sa.recollected), int(sb.recollected));
  EXPECT_GT(sa.contacts, 100);
  EXPECT_EQ(sa.contacts, sb.contacts);
  EXPECT_EQ(sa.rolled_back, sb.rolled_back);
  double worst = 0.0;
  for (std::size_t i = 0; i < m.n; ++i)
    for (int c = 0; c < 3; ++c) {
      const auto j = std::size_t(to[i]);
      worst = std::max(worst, std::abs(a.pos.axis(c)[i] - b.pos.axis(c)[j]));
      worst = std::max(worst, 1.0 / 600.0 * std::abs(a.vel.axis(c)[i] - b.vel.axis(c)[j]));
    }
  EXPECT_LT(worst, 1e-12);
}

// A pass of triangle contact spans several substeps while no vertex moves, relative to the mean
// velocity of all, more than half the 4 mm thickness over it, and at most 1/150 s: the stack
// falling as one spans 4 of xpbd's 1/600 s substeps (3 when only 3 are left in the step); one
// vertex 0.5 m/s faster than the rest allows 2 (0.83 mm a substep), 1 m/s only 1.
TEST(ClothContact, PassesSpanSubstepsWhileNothingMovesFastRelativeToTheRest) {
  const Scene scene = shipped("stack_on_ball.toml");
  const Model<double> m = build_model<double>(scene);
  TriangleContact<double> contact(m, scene.solver);
  State<double> s;
  s.pos = m.rest_positions;
  s.vel.resize(m.n);
  const auto falling = [&](double extra) {
    for (std::size_t i = 0; i < m.n; ++i) s.vel.set(i, 0.2, -3.0 - (i == 7 ? extra : 0.0), 0.0);
  };
  constexpr double h = 1.0 / 600.0;
  for (int threads = 1; threads <= 2; ++threads) {
    falling(0.0);
    EXPECT_EQ(contact.pass_span(s, h, 10, threads), 4);
    EXPECT_EQ(contact.pass_span(s, h, 3, threads), 3);
    falling(0.5);
    EXPECT_EQ(contact.pass_span(s, h, 10, threads), 2);
    falling(1.0);
    EXPECT_EQ(contact.pass_span(s, h, 10, threads), 1);
  }
}

// A large sheet that swings without ever touching itself moves exactly as it does without
// contact: no push, no rollback. (Its swing strays a centimetre from the mean motion in one
// substep, which once grew the skin until the pairs overflowed and the sheet was stopped dead; a
// rigid fit takes the swing away.)
TEST(ClothContact, SwingingSheetMovesAsWithoutContact) {
  std::vector<Vec3d> x[2];
  for (int on = 0; on <= 1; ++on) {
    std::unique_ptr<Solver> s = make_solver(shipped(
        "large_sheet.toml", {"cloth.resolution=[200, 200]", "cloth.pins=[[0, 0], [199, 0]]",
                             std::string("solver.cloth_contact=") + (on ? "true" : "false")}));
    ASSERT_TRUE(s->advance(1.0).ok());
    for (std::size_t i = 0; i < s->vertex_count(); ++i) x[on].push_back(s->position(int(i)));
    if (on) {
      EXPECT_EQ(s->last_cloth_contact()->rolled_back, 0);
      EXPECT_FALSE(s->last_cloth_contact()->overflow);
    }
  }
  EXPECT_EQ(x[0], x[1]);
}

// Two sheets without gravity or drag fly into each other face to face; contact is inelastic and
// frictional, so the total energy never rises above where it started.
TEST(ClothContact, NeverAddsEnergy) {
  Scene scene = shipped("stack_on_ball.toml", {"forces.gravity=[0, 0, 0]", "forces.drag=0"});
  scene.colliders.clear();
  std::unique_ptr<Solver> s = make_solver(scene);
  std::vector<Vec3d> x, v;
  for (std::size_t i = 0; i < s->vertex_count(); ++i) {
    x.push_back(s->position(int(i)));
    v.push_back({0.0, i < 1600 ? 1.0 : -1.0, 0.0});
  }
  s->set_state(x, v);
  const double e0 = s->energy().total();
  double highest = e0;
  for (int frame = 0; frame < 30; ++frame) {
    ASSERT_TRUE(s->advance(1.0 / 60).ok());
    highest = std::max(highest, s->energy().total());
    EXPECT_EQ(s->intersections(), 0);
  }
  EXPECT_LE(highest, e0 * (1.0 + 1e-6));
  EXPECT_GT(s->last_cloth_contact()->candidates, 0);
}

// ---- the contact view's gaps (sim/fields/contact_gaps.hpp) ------------------------------------

std::vector<float> floats_of(const std::vector<V3>& x) {
  std::vector<float> xyz;
  for (const V3& p : x)
    for (int k = 0; k < 3; ++k) xyz.push_back(float(p[k]));
  return xyz;
}

// Two 9 x 9 sheets built 3 mm apart (two cloths are never neighbours): every vertex's gap is 3 mm
// (float positions: to 1e-6 m); 2 cm apart, every gap is the range (1 cm): each sheet alone shows
// none, its neighbours being near at rest.
TEST(ContactGaps, LayersShowTheirDistanceAndNeighboursNone) {
  const Scene scene = read_scene_string(R"(
[[cloth]]
size = [0.5, 0.5]
resolution = [9, 9]
origin = [0, 1, 0]
u_axis = [1, 0, 0]
v_axis = [0, 0, 1]
pins = [[0, 0]]
[[cloth]]
size = [0.5, 0.5]
resolution = [9, 9]
origin = [0, 1.003, 0]
u_axis = [1, 0, 0]
v_axis = [0, 0, 1]
pins = [[0, 0]]
)",
                                        "two sheets");
  std::unique_ptr<Solver> s = make_solver(scene);
  ContactGaps gaps(*s);
  std::vector<V3> x(s->vertex_count());
  for (std::size_t v = 0; v < x.size(); ++v) {
    const Vec3d p = s->rest_position(int(v));
    x[v] = {p[0], p[1], p[2]};
  }
  std::vector<float> out;
  gaps.per_vertex(floats_of(x), 0.01, 1, out);
  for (float g : out) EXPECT_NEAR(g, 0.003, 1e-6);
  for (std::size_t v = 81; v < x.size(); ++v) x[v].y() = 1.02;
  gaps.per_vertex(floats_of(x), 0.01, 1, out);
  for (float g : out) EXPECT_EQ(g, 0.01f);
}

// A 20 x 20 sheet folded in half, the upper half waving through the lower one (0.5 m, a 26 mm
// grid; the wave 1 cm high, 0.2 m long, jittered by up to 1 mm): each vertex's gap is the least
// distance over the vertex-triangle and edge-edge pairs it belongs to whose owner triangles lay
// at least the range apart at rest (the definition, by brute force over every pair), and NaN on
// exactly the vertices of crossing edges and triangles; the same bytes on 1 and 2 threads.
TEST(ContactGaps, MatchTheirDefinitionOnAFoldedSheet) {
  std::unique_ptr<Solver> s = make_solver(read_scene_string(R"(
[cloth]
size = [0.5, 0.5]
resolution = [20, 20]
origin = [0, 0, 0]
u_axis = [1, 0, 0]
v_axis = [0, 0, 1]
pins = [[0, 0]]
)",
                                                            "one sheet"));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.001, 0.001);
  constexpr double kSpacing = 0.5 / 19, kPi = 3.14159265358979;
  std::vector<V3> x(s->vertex_count()), rest(s->vertex_count());
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) {
      const std::size_t v = std::size_t(j * 20 + i);
      const double z = j * kSpacing;
      const V3 p = i < 10 ? V3(i * kSpacing, 0.0, z)
                          : V3((19.3 - i) * kSpacing, 0.01 * std::sin(2 * kPi * z / 0.2), z);
      x[v] = (p + V3(0.0, jitter(rng), 0.0)).cast<float>().cast<double>();  // the view's floats
      const Vec3d r = s->rest_position(int(v));
      rest[v] = {r[0], r[1], r[2]};
    }
  constexpr double kRange = 0.02;
  const SurfaceFeatures f = surface_features(s->triangles(), x.size());
  const auto box = [&](int t) {
    const auto& tri = f.triangles[std::size_t(t)];
    Box3 b{rest[std::size_t(tri[0])], rest[std::size_t(tri[0])]};
    for (int v : tri)
      b = {b.lo.cwiseMin(rest[std::size_t(v)]), b.hi.cwiseMax(rest[std::size_t(v)])};
    return b;
  };
  const auto apart_at_rest = [&](int ta, int tb) {
    const Box3 a = box(ta), b = box(tb);
    return (a.lo - b.hi).cwiseMax(b.lo - a.hi).cwiseMax(0.0).norm() >= kRange;
  };
  std::vector<double> expect(x.size(), kRange);
  const auto take = [&](double d2, std::initializer_list<int> vertices) {
    for (int v : vertices) expect[std::size_t(v)] = std::min(expect[std::size_t(v)], std::sqrt(d2));
  };
  std::vector<int> vertex_owner(x.size()), edge_owner(f.edges.size());
  for (std::size_t t = 0; t < f.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      if (f.owned_vertices[t] & (1u << k)) vertex_owner[std::size_t(f.triangles[t][k])] = int(t);
      if (f.owned_edges[t] & (1u << k)) edge_owner[std::size_t(f.triangle_edges[t][k])] = int(t);
    }
  for (std::size_t v = 0; v < x.size(); ++v)
    for (std::size_t t = 0; t < f.triangles.size(); ++t) {
      const auto& tri = f.triangles[t];
      if (shares_vertex(tri, int(v)) || !apart_at_rest(vertex_owner[v], int(t))) continue;
      take(point_triangle_dist2(x[v], x[std::size_t(tri[0])], x[std::size_t(tri[1])],
                                x[std::size_t(tri[2])]),
           {int(v), tri[0], tri[1], tri[2]});
    }
  for (std::size_t e = 0; e < f.edges.size(); ++e)
    for (std::size_t g = e + 1; g < f.edges.size(); ++g) {
      const auto &a = f.edges[e], &b = f.edges[g];
      if (shares_vertex(a, b) || !apart_at_rest(edge_owner[e], edge_owner[g])) continue;
      take(edge_edge_dist2(x[std::size_t(a[0])], x[std::size_t(a[1])], x[std::size_t(b[0])],
                           x[std::size_t(b[1])]),
           {a[0], a[1], b[0], b[1]});
    }
  std::vector<bool> crossed(x.size(), false);
  for (const auto& e : f.edges)
    for (const auto& t : f.triangles)
      if (!shares_vertex(e, t) &&
          segment_crosses_triangle(x[std::size_t(e[0])], x[std::size_t(e[1])], x[std::size_t(t[0])],
                                   x[std::size_t(t[1])], x[std::size_t(t[2])]))
        for (int v : {e[0], e[1], t[0], t[1], t[2]}) crossed[std::size_t(v)] = true;

  ContactGaps gaps(*s);
  std::vector<float> one, two;
  gaps.per_vertex(floats_of(x), kRange, 1, one);
  gaps.per_vertex(floats_of(x), kRange, 2, two);
  ASSERT_EQ(one.size(), x.size());
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)), 0);
  int near = 0, nan = 0;
  for (std::size_t v = 0; v < x.size(); ++v) {
    if (crossed[v]) {
      EXPECT_TRUE(std::isnan(one[v])) << "vertex " << v;
      ++nan;
      continue;
    }
    EXPECT_NEAR(one[v], expect[v], 1e-6) << "vertex " << v;
    if (expect[v] < kRange) ++near;
  }
  EXPECT_GT(near, 20);
  EXPECT_GT(nan, 10);
}

}  // namespace
}  // namespace clothlab
