// A forward-kinematics skeleton (docs/contact.md section 3): joints in a tree, each with its rest
// offset from its parent and a rotation in its parent's frame. The world frame of joint j is
// parent_world * T(offset_j) * R(local_j); the root's parent is the figure's placement on the
// floor, T(root_translation) * R(root_rotation). The solver poses the skeleton at every substep,
// so forward_kinematics() writes into the caller's array and never allocates.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <span>
#include <string>
#include <vector>

namespace clothlab {

// Upper bound on joints, so that poses and scratch frames live in fixed-size arrays.
inline constexpr int kMaxJoints = 32;

struct Joint {
  std::string name;
  int parent = -1;                                   // index of an earlier joint; -1 for the root
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // joint origin in the parent frame, m
  Eigen::Quaterniond rest_rotation = Eigen::Quaterniond::Identity();  // in the parent frame
};

// Joints in order, parents before children (so one forward pass poses the tree).
struct Skeleton {
  std::vector<Joint> joints;

  int size() const { return static_cast<int>(joints.size()); }
  // Appends a joint and returns its index; throws std::invalid_argument where the parent is not
  // an earlier joint or the skeleton is full.
  int add(std::string name, int parent, const Eigen::Vector3d& offset,
          const Eigen::Quaterniond& rest_rotation = Eigen::Quaterniond::Identity());
  // Index of the joint of that name, or -1.
  int find(const std::string& name) const;
};

// The variables of a pose: where the figure stands and each joint's rotation in its parent's
// frame (only the first skeleton.size() entries are used).
struct SkeletonPose {
  Eigen::Vector3d root_translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond root_rotation = Eigen::Quaterniond::Identity();
  std::array<Eigen::Quaterniond, kMaxJoints> local;
};

// A rigid frame: world = rotation * local + position.
struct JointFrame {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

// The pose with every joint at its rest rotation, standing at the origin.
SkeletonPose rest_pose(const Skeleton& skeleton);

// World frame of every joint (world.size() >= skeleton.size()). Cost: one quaternion product and
// one rotation per joint; no allocation.
void forward_kinematics(const Skeleton& skeleton, const SkeletonPose& pose,
                        std::span<JointFrame> world);

}  // namespace clothlab
