// Normal-cone culling for cloth contact (sim/contact/flat_patches.hpp, patch_topology.hpp): which
// nodes of the tree are disks, a flat or gently bent sheet skipped as one patch, and the three
// ways a patch can touch itself that the test must catch: a fold (normals beyond the cone), a
// strip wound over itself (normals fine, the rim crosses in projection) and a turn within one
// substep (the ends fine, the motion between them collapses every triangle).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "grid_mesh.hpp"
#include "load/scene_load.hpp"
#include "sim/contact/flat_patches.hpp"
#include "sim/contact/intersections.hpp"
#include "sim/solver.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;

using Mesh = GridMesh;

Vec3Array<double> soa(const std::vector<V3>& x) {
  Vec3Array<double> a;
  a.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) a.set(i, x[i].x(), x[i].y(), x[i].z());
  return a;
}

struct Culling {
  TriangleBvh bvh;
  SurfaceFeatures features;
  FlatPatches<double> flat;
  Culling(const Mesh& m, const std::vector<V3>& rest)
      : bvh(triangle_centroids(m.triangles, rest), m.groups),
        features(surface_features(m.triangles, rest.size())),
        flat(bvh, features, soa(rest), 1e-5) {}
  void choose(const std::vector<V3>& x0, const std::vector<V3>& x1) {
    flat.choose(bvh, features, soa(x0), soa(x1), 2);
  }
};

V3 flat_plane(int i, int j) {
  return V3(0.05 * i, 0.0, 0.05 * j);
}

TEST(PatchTopology, GridNodesAreDisksAndEachClothHasItsOwnSubtree) {
  Mesh one;
  add_grid(one, 12, 12, 0, flat_plane);
  const TriangleBvh bvh(triangle_centroids(one.triangles, one.x));
  const PatchTopology t =
      patch_topology(bvh, surface_features(one.triangles, one.x.size()), one.x.size());
  ASSERT_TRUE(t.disk[0]);
  EXPECT_EQ(t.rim_begin[1] - t.rim_begin[0], 4 * 11);  // the grid's border
  // Two sheets one above the other: the root is two disks, split between the cloths first.
  Mesh two = one;
  add_grid(two, 12, 12, 1, [](int i, int j) { return V3(flat_plane(i, j) + V3(0, 0.01, 0)); });
  const TriangleBvh by_cloth(triangle_centroids(two.triangles, two.x), two.groups);
  const PatchTopology u =
      patch_topology(by_cloth, surface_features(two.triangles, two.x.size()), two.x.size());
  EXPECT_FALSE(u.disk[0]);
  EXPECT_TRUE(u.disk[std::size_t(by_cloth.left(0))]);
  EXPECT_TRUE(u.disk[std::size_t(by_cloth.right(0))]);
  // Without the groups the median splits cut across both sheets: the root's children are not
  // disks (each holds pieces of both).
  const TriangleBvh mixed(triangle_centroids(two.triangles, two.x));
  const PatchTopology w =
      patch_topology(mixed, surface_features(two.triangles, two.x.size()), two.x.size());
  EXPECT_FALSE(w.disk[std::size_t(mixed.left(0))]);
}

// A flat sheet moving as one, and the same sheet bent into a gentle arc (45 degrees end to end),
// are one patch; the sheet folded over onto itself is not, but patches of each half are (at least
// a third of the sheet: the tree's median splits do not follow the fold).
TEST(FlatPatches, FlatAndGentlyBentSheetsAreOnePatchAFoldIsNot) {
  Mesh m;
  add_grid(m, 16, 16, 0, flat_plane);
  Culling c(m, m.x);
  std::vector<V3> moved = m.x;
  for (V3& p : moved) p += V3(0.01, -0.02, 0.003);
  c.choose(m.x, moved);
  EXPECT_TRUE(c.flat.covers_all());
  EXPECT_EQ(c.flat.triangles_covered(), m.triangles.size());
  std::vector<V3> arc = m.x;
  const double radius = 0.75 / (std::numbers::pi / 4);
  for (V3& p : arc) {
    const double a = p.x() / radius;
    p = V3(radius * std::sin(a), radius * (1 - std::cos(a)), p.z());
  }
  c.choose(arc, arc);
  EXPECT_TRUE(c.flat.covers_all());
  // Folded along x = 0.375: the right half turned over onto the left, 1 cm above it.
  std::vector<V3> folded = m.x;
  for (V3& p : folded)
    if (p.x() > 0.375) p = V3(0.75 - p.x(), 0.01, p.z());
  c.choose(folded, folded);
  EXPECT_FALSE(c.flat.covers_all());
  EXPECT_GE(c.flat.patch_count(), 2u);
  EXPECT_GT(c.flat.triangles_covered(), m.triangles.size() / 3);
}

// A strip lying flat (every normal straight up) wound round 1.3 times, rising 1 cm a turn: its
// own rim crosses in plan, so it is not a patch; wound 0.8 times it is.
TEST(FlatPatches, AStripWoundOverItselfIsCaughtByItsRim) {
  const auto wound = [](double turns) {
    Mesh m;
    add_grid(m, 80, 2, 0, [turns](int i, int j) {
      const double a = 2 * std::numbers::pi * turns * i / 79.0, r = 0.2 + 0.03 * j;
      return V3(r * std::cos(a), 0.01 * a / (2 * std::numbers::pi), r * std::sin(a));
    });
    return m;
  };
  for (const double turns : {0.8, 1.3}) {
    const Mesh m = wound(turns);
    Culling c(m, m.x);
    c.choose(m.x, m.x);
    // Every triangle faces straight up or down alike (the cone test passes).
    EXPECT_EQ(c.flat.covers_all(), turns < 1.0) << turns << " turns";
  }
}

// The sheet turned half round about its normal within one substep: flat at both ends, but the
// straight-line motion between them passes every triangle through a point (the middle Bernstein
// coefficient of its normal points the other way), so nothing is a patch.
TEST(FlatPatches, AHalfTurnWithinOneSubstepIsNotFlat) {
  Mesh m;
  add_grid(m, 16, 16, 0, flat_plane);
  Culling c(m, m.x);
  std::vector<V3> turned = m.x;
  const V3 centre(0.375, 0.0, 0.375);
  for (V3& p : turned) p = centre - (p - centre);
  c.choose(m.x, turned);
  EXPECT_EQ(c.flat.patch_count(), 0u);
  // A chosen patch is kept while it stays flat, and not once it turns.
  c.choose(m.x, m.x);
  ASSERT_TRUE(c.flat.covers_all());
  EXPECT_TRUE(c.flat.still_flat(c.features, soa(m.x), soa(m.x), 2));
  EXPECT_FALSE(c.flat.still_flat(c.features, soa(m.x), soa(turned), 2));
}

// A 64 x 64 sheet falling flat with triangle contact on: one patch, no candidate pair at all.
TEST(FlatPatches, AFallingFlatSheetHasNoCandidatePairs) {
  const std::string toml = R"(
[[cloth]]
size = [1.0, 1.0]
resolution = [64, 64]
[solver]
integrator = "xpbd"
dt = 0.0166667
cloth_contact = true
self_thickness = 0.004
)";
  std::unique_ptr<Solver> s = make_solver(read_scene_string(toml, "flat.toml"));
  ASSERT_TRUE(s->advance(0.2).ok());
  const ClothContactStats c = *s->last_cloth_contact();
  EXPECT_EQ(c.candidates, 0);
  EXPECT_EQ(c.flat_patches, 1);
  EXPECT_EQ(c.flat_triangles, 2 * 63 * 63);
}

// The broad phase's pieces for threads (TriangleBvh::tasks): two sheets 1 cm apart, both waved,
// report every pair of overlapping triangles the whole traversal does, each once, also with the
// pair of cloths cut into many pieces; a node culled within itself and a pair of nodes culled
// between them report none of their pairs from any piece.
TEST(TriangleBvh, PiecesReportEveryPairOnceAndCullsHoldInEveryPiece) {
  const auto waved = [](double lift) {
    return [lift](int i, int j) {
      return V3(0.05 * i, lift + 0.02 * std::sin(0.9 * i) * std::cos(0.7 * j), 0.05 * j);
    };
  };
  Mesh m;
  add_grid(m, 16, 16, 0, waved(0.0));
  add_grid(m, 16, 16, 1, waved(0.01));
  TriangleBvh bvh(triangle_centroids(m.triangles, m.x), m.groups);
  fill_triangle_boxes(m.triangles, m.x, 0.01, bvh.leaf_boxes());
  bvh.refit();
  using Pairs = std::vector<std::pair<int, int>>;
  const auto ordered = [](int a, int b) { return std::pair(std::min(a, b), std::max(a, b)); };
  Pairs whole;
  bvh.self_pairs([&](int a, int b) { return whole.push_back(ordered(a, b)), true; });
  std::sort(whole.begin(), whole.end());
  const int cloth_a = bvh.left(0), cloth_b = bvh.right(0);
  const auto under = [&](int n, int top) {
    return bvh.triangles_begin(n) >= bvh.triangles_begin(top) &&
           bvh.triangles_end(n) <= bvh.triangles_end(top);
  };
  const int b_left = bvh.left(cloth_b), b_right = bvh.right(cloth_b);
  struct Cull {
    std::function<bool(int)> self_fn;
    std::function<bool(int, int)> pair_fn;
    bool self(int n) const { return self_fn(n); }
    bool pair(int a, int b) const { return pair_fn(a, b); }
  };
  const Cull none{[](int) { return false; }, [](int, int) { return false; }};
  // Cloth a within itself, and the two halves of cloth b against each other.
  const Cull some{[&](int n) { return n == cloth_a; },
                  [&](int a, int b) {
                    return (under(a, b_left) && under(b, b_right)) ||
                           (under(a, b_right) && under(b, b_left));
                  }};
  const std::vector<TriangleBvh::Task> tasks = bvh.tasks(5);
  EXPECT_GT(std::count_if(tasks.begin(), tasks.end(),
                          [](const TriangleBvh::Task& t) { return t.within == 0; }),
            64);  // the cloths against each other: 4^4 pieces
  const auto run = [&](const Cull& cull) {
    Pairs out;
    for (const TriangleBvh::Task& t : tasks)
      bvh.run(t, cull, [&](int a, int b) { return out.push_back(ordered(a, b)), true; });
    std::sort(out.begin(), out.end());
    return out;
  };
  ASSERT_GT(whole.size(), 1000u);
  EXPECT_EQ(run(none), whole);  // sorted: any pair twice would show
  Pairs expected;
  const auto in = [&](int t, int top) {
    return std::find(bvh.triangles_begin(top), bvh.triangles_end(top), t) != bvh.triangles_end(top);
  };
  for (const auto& [a, b] : whole)
    if (!(in(a, cloth_a) && in(b, cloth_a)) && !(in(a, b_left) && in(b, b_right)) &&
        !(in(a, b_right) && in(b, b_left)))
      expected.push_back({a, b});
  ASSERT_LT(expected.size() + 1000, whole.size());  // the culls remove many pairs
  EXPECT_EQ(run(some), expected);
}

}  // namespace
}  // namespace clothlab
