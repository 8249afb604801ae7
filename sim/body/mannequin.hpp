// A procedural 1.75 m mannequin (docs/contact.md section 3): spheres, boxes and capsules attached
// to the joints of a forward-kinematics skeleton, standing on y = 0 and facing +z, its left hand on
// +x. At rest the arms hang in an A-pose (25 degrees out from the body) so that a skirt or a cape
// hangs clear of them, and the legs stand slightly apart. Sizes from docs/contact.md section 3.
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <string>
#include <vector>

#include "sim/body/skeleton.hpp"

namespace clothlab {

enum class BodyShape { sphere, box, capsule };

struct BodyPrimitive {
  std::string name;  // "pelvis", "left_forearm", ...
  int joint = 0;     // the joint it moves with
  BodyShape shape = BodyShape::sphere;
  double radius = 0;                                       // sphere, capsule, m
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();  // box, m
  // Capsule: half the distance between its two sphere centres, axis along the local +y, m.
  double half_length = 0;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // primitive centre in the joint frame
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // primitive frame in the joint's
};

// A primitive's world frame at a time: world = rotation * local + position.
struct RigidState {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // of `position`, m/s
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, world axes
};

struct Mannequin {
  Skeleton skeleton;
  std::vector<BodyPrimitive> primitives;
  double height = 1.75;  // m, top of the head above the soles in the rest pose
};

// The figure described above; its rest pose is rest_pose(m.skeleton).
Mannequin make_mannequin();

// A primitive's world frame (velocities left zero) given its joint's world frame.
RigidState primitive_frame(const BodyPrimitive& p, const JointFrame& joint);

// World frame of every primitive for a pose (out.size() >= primitives.size()); no allocation.
void primitive_frames(const Mannequin& m, const SkeletonPose& pose, std::span<RigidState> out);

// World axis-aligned box around a primitive placed at `frame`.
Eigen::AlignedBox3d primitive_bounds(const BodyPrimitive& p, const RigidState& frame);

// Mirror image of a frame in the plane x = 0 (the figure's plane of symmetry): x -> -x for the
// position, M R M with M = diag(-1, 1, 1) for the rotation.
RigidState mirror_x(const RigidState& s);

}  // namespace clothlab
