// The collider meshes the viewer draws have the shapes the solver collides with: every vertex of
// the capsule and the rounded box lies on the collider's own surface (sim's signed distance is 0
// there), the normals are the distance's gradient, and the enclosed volumes match the closed
// forms (the facets cut the curved parts only slightly).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/contact/collider.hpp"
#include "vis/meshes/mesh.hpp"
#include "vis/meshes/shapes.hpp"

namespace clothlab {
namespace {

void expect_on_surface(const vis::Mesh& mesh, const ColliderSpec& spec) {
  const Collider collider(spec);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
    const LocalDistance d = collider.local_distance({p.x, p.y, p.z});
    ASSERT_NEAR(d.phi, 0.0, 1e-5) << "vertex " << v;
    EXPECT_GT(d.normal.dot(Eigen::Vector3d(n.x, n.y, n.z)), 0.999) << "vertex " << v;
  }
}

TEST(ColliderMeshTest, CapsuleLiesOnTheCapsuleCollider) {
  ColliderSpec spec;
  spec.kind = ColliderKind::capsule;
  spec.radius = 0.2;
  spec.a = {0.0, -0.35, 0.0};
  spec.b = {0.0, 0.35, 0.0};  // along local y already: the collider's frame is the world's
  const vis::Mesh mesh = vis::make_capsule(0.2f, 0.35f, 48, 12);
  expect_on_surface(mesh, spec);
  const double r = 0.2, h = 0.35;
  const double volume =
      std::numbers::pi * r * r * 2.0 * h + 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_NEAR(vis::signed_volume(mesh) / volume, 1.0, 0.01);  // positive: outward-facing
  EXPECT_EQ(mesh.tangents.size(), mesh.vertex_count());
}

TEST(ColliderMeshTest, RoundedBoxLiesOnTheRoundedBoxCollider) {
  ColliderSpec spec;
  spec.kind = ColliderKind::box;
  spec.center = {0.0, 0.0, 0.0};
  spec.half_extents = {0.5, 0.3, 0.2};
  spec.rounding = 0.08;
  const vis::Mesh mesh = vis::make_rounded_box({0.5f, 0.3f, 0.2f}, 0.08f, 6);
  expect_on_surface(mesh, spec);
  // The inner box grown by r: abc + 2r(ab + bc + ca) + pi r^2 (a + b + c) + 4/3 pi r^3.
  const double r = 0.08, a = 2 * (0.5 - r), b = 2 * (0.3 - r), c = 2 * (0.2 - r);
  const double volume = a * b * c + 2 * r * (a * b + b * c + c * a) +
                        std::numbers::pi * r * r * (a + b + c) +
                        4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_NEAR(vis::signed_volume(mesh) / volume, 1.0, 0.005);
  // No rounding: the plain box.
  EXPECT_EQ(vis::make_rounded_box({0.5f, 0.3f, 0.2f}, 0.0f, 6).vertex_count(), 24u);
}

TEST(ColliderMeshTest, RejectsBadSizes) {
  EXPECT_THROW(vis::make_capsule(0.0f, 1.0f, 8, 2), std::invalid_argument);
  EXPECT_THROW(vis::make_capsule(1.0f, 1.0f, 2, 2), std::invalid_argument);
  EXPECT_THROW(vis::make_rounded_box({1, 0, 1}, 0.1f, 4), std::invalid_argument);
}

}  // namespace
}  // namespace clothlab
