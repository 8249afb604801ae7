#include "sim/body/mannequin.hpp"

#include <cmath>
#include <numbers>

namespace clothlab {
namespace {

using Eigen::AngleAxisd;
using Eigen::Quaterniond;
using Eigen::Vector3d;

constexpr double kDeg = std::numbers::pi / 180.0;

// Proportions of a 1.75 m adult (docs/contact.md section 3 for the primitive sizes).
constexpr double kHeight = 1.75;
constexpr double kArmOut = 25 * kDeg;  // A-pose: arms 25 degrees from the body
constexpr double kLegOut = 3 * kDeg;   // legs slightly apart
constexpr double kUpperArm = 0.30, kForearm = 0.26, kThigh = 0.43, kShin = 0.43;
constexpr double kAnkleHeight = 0.07;  // ankle joint above the sole
constexpr double kHipBelowPelvis = 0.06;
constexpr double kPelvisHalf[3] = {0.17, 0.10, 0.11};
constexpr double kChestHalf[3] = {0.17, 0.21, 0.11};
constexpr double kShoulderX = 0.20, kShoulderBelowChestTop = 0.04;
constexpr double kHipX = 0.10;
constexpr double kHeadRadius = 0.11;

Quaterniond about_z(double angle) {
  return Quaterniond(AngleAxisd(angle, Vector3d::UnitZ()));
}

BodyPrimitive sphere(std::string name, int joint, double r, Vector3d offset) {
  BodyPrimitive p{std::move(name), joint, BodyShape::sphere};
  p.radius = r;
  p.offset = offset;
  return p;
}

BodyPrimitive box(std::string name, int joint, Vector3d half, Vector3d offset) {
  BodyPrimitive p{std::move(name), joint, BodyShape::box};
  p.half_extents = half;
  p.offset = offset;
  return p;
}

// A capsule along the joint's -y from the joint to the next one, `length` away (sphere centres
// on the two joints, so neighbouring limbs overlap only at their joint).
BodyPrimitive limb(std::string name, int joint, double r, double length) {
  BodyPrimitive p{std::move(name), joint, BodyShape::capsule};
  p.radius = r;
  p.half_length = 0.5 * length;
  p.offset = Vector3d(0, -0.5 * length, 0);
  return p;
}

// One arm or leg chain; side = +1 for the left (+x), -1 for the right.
void add_arm(Mannequin& m, int chest, double chest_top, double side) {
  Skeleton& s = m.skeleton;
  const std::string n = side > 0 ? "left_" : "right_";
  const int shoulder = s.add(n + "shoulder", chest,
                             Vector3d(side * kShoulderX, chest_top - kShoulderBelowChestTop, 0),
                             about_z(side * kArmOut));
  const int elbow = s.add(n + "elbow", shoulder, Vector3d(0, -kUpperArm, 0));
  const int wrist = s.add(n + "wrist", elbow, Vector3d(0, -kForearm, 0));
  m.primitives.push_back(limb(n + "upper_arm", shoulder, 0.045, kUpperArm));
  m.primitives.push_back(limb(n + "forearm", elbow, 0.04, kForearm));
  m.primitives.push_back(sphere(n + "hand", wrist, 0.05, Vector3d(0, -0.06, 0)));
}

void add_leg(Mannequin& m, int pelvis, double side) {
  Skeleton& s = m.skeleton;
  const std::string n = side > 0 ? "left_" : "right_";
  const int hip = s.add(n + "hip", pelvis, Vector3d(side * kHipX, -kHipBelowPelvis, 0),
                        about_z(side * kLegOut));
  const int knee = s.add(n + "knee", hip, Vector3d(0, -kThigh, 0));
  // The ankle turns back by the leg's splay so the sole lies flat on the floor.
  const int ankle = s.add(n + "ankle", knee, Vector3d(0, -kShin, 0), about_z(-side * kLegOut));
  m.primitives.push_back(limb(n + "thigh", hip, 0.075, kThigh));
  m.primitives.push_back(limb(n + "shin", knee, 0.055, kShin));
  // Sole at the ankle height below the joint; toes reach forward (+z) of the ankle.
  m.primitives.push_back(box(n + "foot", ankle, Vector3d(0.05, 0.5 * kAnkleHeight, 0.12),
                             Vector3d(0, -0.5 * kAnkleHeight, 0.06)));
}

}  // namespace

Mannequin make_mannequin() {
  Mannequin m;
  m.height = kHeight;
  Skeleton& s = m.skeleton;
  const double hip_y = kAnkleHeight + (kThigh + kShin) * std::cos(kLegOut);
  const double pelvis_y = hip_y + kHipBelowPelvis;
  const int pelvis = s.add("pelvis", -1, Vector3d(0, pelvis_y, 0));
  const int chest = s.add("chest", pelvis, Vector3d(0, kPelvisHalf[1], 0));
  const double chest_top = 2 * kChestHalf[1];  // in the chest joint's frame
  const int neck = s.add("neck", chest, Vector3d(0, chest_top, 0));
  const double neck_y = pelvis_y + kPelvisHalf[1] + chest_top;

  m.primitives.push_back(box("pelvis", pelvis,
                             Vector3d(kPelvisHalf[0], kPelvisHalf[1], kPelvisHalf[2]),
                             Vector3d::Zero()));
  m.primitives.push_back(box("chest", chest, Vector3d(kChestHalf[0], kChestHalf[1], kChestHalf[2]),
                             Vector3d(0, kChestHalf[1], 0)));
  BodyPrimitive neck_capsule = limb("neck", neck, 0.05, 0.04);
  neck_capsule.offset = Vector3d(0, 0.045, 0);  // up from the chest's top face
  m.primitives.push_back(neck_capsule);
  // The head turns with the neck (a nod pivots at the chest's top) and tops out at the height.
  m.primitives.push_back(
      sphere("head", neck, kHeadRadius, Vector3d(0, kHeight - kHeadRadius - neck_y, 0)));
  add_arm(m, chest, chest_top, +1);
  add_arm(m, chest, chest_top, -1);
  add_leg(m, pelvis, +1);
  add_leg(m, pelvis, -1);
  return m;
}

RigidState primitive_frame(const BodyPrimitive& p, const JointFrame& joint) {
  RigidState s;
  s.rotation = (joint.rotation * p.rotation).normalized();
  s.position = joint.position + joint.rotation * p.offset;
  return s;
}

void primitive_frames(const Mannequin& m, const SkeletonPose& pose, std::span<RigidState> out) {
  std::array<JointFrame, kMaxJoints> world;
  forward_kinematics(m.skeleton, pose, world);
  for (std::size_t i = 0; i < m.primitives.size(); ++i)
    out[i] = primitive_frame(m.primitives[i], world[m.primitives[i].joint]);
}

Eigen::AlignedBox3d primitive_bounds(const BodyPrimitive& p, const RigidState& frame) {
  Vector3d half = Vector3d::Zero();
  switch (p.shape) {
    case BodyShape::sphere:
      half = Vector3d::Constant(p.radius);
      break;
    case BodyShape::box:  // extent of a rotated box along each axis: |R| h
      half = frame.rotation.toRotationMatrix().cwiseAbs() * p.half_extents;
      break;
    case BodyShape::capsule:
      half = (frame.rotation * Vector3d(0, p.half_length, 0)).cwiseAbs() +
             Vector3d::Constant(p.radius);
      break;
  }
  return Eigen::AlignedBox3d(frame.position - half, frame.position + half);
}

RigidState mirror_x(const RigidState& s) {
  const Eigen::Matrix3d mirror = Eigen::Vector3d(-1, 1, 1).asDiagonal();
  RigidState r = s;
  r.position.x() = -s.position.x();
  r.rotation = Quaterniond(Eigen::Matrix3d(mirror * s.rotation.toRotationMatrix() * mirror));
  // Velocities mirror like positions; angular velocity is a pseudo-vector: (w, -w_y, -w_z).
  r.velocity.x() = -s.velocity.x();
  r.angular_velocity =
      Vector3d(s.angular_velocity.x(), -s.angular_velocity.y(), -s.angular_velocity.z());
  return r;
}

}  // namespace clothlab
