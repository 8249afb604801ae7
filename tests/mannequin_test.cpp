// The procedural mannequin (sim/body/): forward kinematics against hand-computed chains, the
// figure's height and footing, its left-right symmetry, and arms that hang clear of the torso
// in the rest A-pose.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "body_box_distance.hpp"
#include "sim/body/mannequin.hpp"
#include "sim/body/skeleton.hpp"

namespace clothlab {
namespace {

using Eigen::AngleAxisd;
using Eigen::Quaterniond;
using Eigen::Vector3d;

Quaterniond about(const Vector3d& axis, double radians) {
  return Quaterniond(AngleAxisd(radians, axis));
}

std::array<RigidState, 32> rest_frames(const Mannequin& m) {
  std::array<RigidState, 32> frames;
  primitive_frames(m, rest_pose(m.skeleton), frames);
  return frames;
}

int index_of(const Mannequin& m, const std::string& name) {
  for (int i = 0; i < static_cast<int>(m.primitives.size()); ++i)
    if (m.primitives[i].name == name) return i;
  return -1;
}

TEST(Skeleton, ChainOfQuarterTurnsPlacesTheTipByHand) {
  // Root at (0,0,5) turned 90 deg about +y; three joints one metre apart with quarter turns
  // about z and x. By hand: Ry90 x = -z, Rz90 x = y, Rx90 z = -y, Rz90 (-y) = x.
  Skeleton s;
  s.add("root", -1, Vector3d(0, 1, 0));
  s.add("a", 0, Vector3d(1, 0, 0), about(Vector3d::UnitZ(), std::numbers::pi / 2));
  s.add("b", 1, Vector3d(1, 0, 0));
  SkeletonPose pose = rest_pose(s);
  pose.root_translation = Vector3d(0, 0, 5);
  pose.root_rotation = about(Vector3d::UnitY(), std::numbers::pi / 2);
  pose.local[2] = about(Vector3d::UnitX(), std::numbers::pi / 2);
  std::array<JointFrame, kMaxJoints> world;
  forward_kinematics(s, pose, world);
  EXPECT_LT((world[0].position - Vector3d(0, 1, 5)).norm(), 1e-12);
  EXPECT_LT((world[1].position - Vector3d(0, 1, 4)).norm(), 1e-12);
  EXPECT_LT((world[2].position - Vector3d(0, 2, 4)).norm(), 1e-12);
  // A tip one metre along joint b's +z: Ry90 Rz90 Rx90 z = Ry90 Rz90 (-y) = Ry90 x = -z.
  const Vector3d tip = world[2].rotation * Vector3d(0, 0, 1) + world[2].position;
  EXPECT_LT((tip - Vector3d(0, 2, 3)).norm(), 1e-12);
}

TEST(Skeleton, RejectsAParentThatComesLater) {
  Skeleton s;
  s.add("root", -1, Vector3d::Zero());
  EXPECT_THROW(s.add("x", 3, Vector3d::Zero()), std::invalid_argument);
}

TEST(Mannequin, BentElbowPutsTheWristWhereHandMathsSays) {
  const Mannequin m = make_mannequin();
  SkeletonPose pose = rest_pose(m.skeleton);
  const int elbow = m.skeleton.find("left_elbow");
  ASSERT_GE(elbow, 0);
  pose.local[elbow] = about(Vector3d::UnitX(), -std::numbers::pi / 2);  // forearm straight forward
  std::array<JointFrame, kMaxJoints> world;
  forward_kinematics(m.skeleton, pose, world);
  const JointFrame& shoulder = world[m.skeleton.find("left_shoulder")];
  // Upper arm 0.30 m down the A-pose direction (25 deg out), forearm 0.26 m along +z.
  const double out = 25 * std::numbers::pi / 180;
  const Vector3d expected =
      shoulder.position + Vector3d(0.30 * std::sin(out), -0.30 * std::cos(out), 0.26);
  EXPECT_LT((world[m.skeleton.find("left_wrist")].position - expected).norm(), 1e-12);
  EXPECT_NEAR(shoulder.position.x(), 0.20, 1e-12);
}

TEST(Mannequin, Is175TallWithSolesOnTheFloor) {
  const Mannequin m = make_mannequin();
  const auto frames = rest_frames(m);
  Eigen::AlignedBox3d box;
  for (std::size_t i = 0; i < m.primitives.size(); ++i)
    box.extend(primitive_bounds(m.primitives[i], frames[i]));
  EXPECT_NEAR(box.max().y(), 1.75, 0.02);
  EXPECT_NEAR(box.min().y(), 0.0, 0.01);
  for (const char* foot : {"left_foot", "right_foot"}) {
    const int i = index_of(m, foot);
    ASSERT_GE(i, 0);
    EXPECT_NEAR(primitive_bounds(m.primitives[i], frames[i]).min().y(), 0.0, 0.01) << foot;
  }
  // Facing +z: toes in front of the heels.
  const int foot = index_of(m, "left_foot");
  EXPECT_GT(frames[foot].position.z(), 0.02);
}

TEST(Mannequin, Has15To19PrimitivesOnValidJoints) {
  const Mannequin m = make_mannequin();
  const int n = static_cast<int>(m.primitives.size());
  EXPECT_GE(n, 15);
  EXPECT_LE(n, 19);
  for (const BodyPrimitive& p : m.primitives) {
    EXPECT_GE(p.joint, 0);
    EXPECT_LT(p.joint, m.skeleton.size());
  }
  const BodyPrimitive& head = m.primitives[index_of(m, "head")];
  EXPECT_EQ(head.shape, BodyShape::sphere);
  EXPECT_DOUBLE_EQ(head.radius, 0.11);
  const BodyPrimitive& forearm = m.primitives[index_of(m, "left_forearm")];
  EXPECT_EQ(forearm.shape, BodyShape::capsule);
  EXPECT_DOUBLE_EQ(2 * forearm.half_length, 0.26);
}

TEST(Mannequin, RestPoseIsMirrorSymmetric) {
  const Mannequin m = make_mannequin();
  const auto frames = rest_frames(m);
  int pairs = 0;
  for (std::size_t i = 0; i < m.primitives.size(); ++i) {
    const std::string& name = m.primitives[i].name;
    int other = static_cast<int>(i);  // central primitives mirror onto themselves
    if (name.starts_with("left_")) other = index_of(m, "right_" + name.substr(5));
    if (name.starts_with("right_")) other = index_of(m, "left_" + name.substr(6));
    ASSERT_GE(other, 0) << name;
    pairs += other != static_cast<int>(i);
    const RigidState mirrored = mirror_x(frames[i]);
    EXPECT_LT((mirrored.position - frames[other].position).norm(), 1e-9) << name;
    EXPECT_LT(
        (mirrored.rotation.toRotationMatrix() - frames[other].rotation.toRotationMatrix()).norm(),
        1e-9)
        << name;
  }
  EXPECT_EQ(pairs, 12);  // arms and legs: three primitives each, counted from both sides
}

TEST(Mannequin, ArmsHangClearOfTheTorsoInTheAPose) {
  const Mannequin m = make_mannequin();
  const auto frames = rest_frames(m);
  double clearance = INFINITY;
  for (const char* torso : {"chest", "pelvis"}) {
    const int b = index_of(m, torso);
    for (std::size_t i = 0; i < m.primitives.size(); ++i) {
      const BodyPrimitive& p = m.primitives[i];
      if (!p.name.ends_with("arm") && !p.name.ends_with("hand")) continue;
      // Points on the primitive's axis; the upper arm's top sphere (local +y end) sits on the
      // shoulder joint, allowed to overlap the chest, so stop one radius short of it.
      const bool upper = p.name.ends_with("upper_arm");
      const double top = upper ? 1 - p.radius / p.half_length : 1;
      for (double s = -1; s <= top; s += 0.01) {
        const Vector3d x =
            frames[i].rotation * Vector3d(0, s * p.half_length, 0) + frames[i].position;
        const double d = testing::box_distance(m.primitives[b], frames[b], x) - p.radius;
        if (upper && std::string(torso) == "chest") {
          EXPECT_GT(d, -0.003) << p.name << " in the chest at s = " << s;
        } else {
          clearance = std::min(clearance, d);
        }
      }
    }
  }
  // Forearms and hands leave room for a skirt or cape beside the body.
  EXPECT_GT(clearance, 0.05);
}

TEST(Mannequin, LegsStandApartWithoutTouching) {
  const Mannequin m = make_mannequin();
  const auto frames = rest_frames(m);
  const int l = index_of(m, "left_thigh"), r = index_of(m, "right_thigh");
  // Closest approach of the two thigh axes (they splay apart, so at the top).
  const Vector3d top_l =
      frames[l].rotation * Vector3d(0, m.primitives[l].half_length, 0) + frames[l].position;
  const Vector3d top_r =
      frames[r].rotation * Vector3d(0, m.primitives[r].half_length, 0) + frames[r].position;
  EXPECT_GT((top_l - top_r).norm() - 2 * m.primitives[l].radius, 0.02);
  const int fl = index_of(m, "left_foot"), fr = index_of(m, "right_foot");
  EXPECT_GT(frames[fl].position.x() - frames[fr].position.x(), 0.25);
}

}  // namespace
}  // namespace clothlab
