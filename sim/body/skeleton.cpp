#include "sim/body/skeleton.hpp"

#include <stdexcept>

#include "sim/core/check.hpp"

namespace clothlab {

int Skeleton::add(std::string name, int parent, const Eigen::Vector3d& offset,
                  const Eigen::Quaterniond& rest_rotation) {
  CLOTHLAB_CHECK_LT(size(), kMaxJoints);  // the fixed pose arrays hold kMaxJoints
  if (parent < -1 || parent >= size())
    throw std::invalid_argument("skeleton: joint '" + name + "' has no earlier parent");
  joints.push_back(Joint{std::move(name), parent, offset, rest_rotation.normalized()});
  return size() - 1;
}

int Skeleton::find(const std::string& name) const {
  for (int j = 0; j < size(); ++j)
    if (joints[j].name == name) return j;
  return -1;
}

SkeletonPose rest_pose(const Skeleton& skeleton) {
  SkeletonPose pose;
  pose.local.fill(Eigen::Quaterniond::Identity());
  for (int j = 0; j < skeleton.size(); ++j) pose.local[j] = skeleton.joints[j].rest_rotation;
  return pose;
}

void forward_kinematics(const Skeleton& skeleton, const SkeletonPose& pose,
                        std::span<JointFrame> world) {
  CLOTHLAB_CHECK_GE(world.size(), skeleton.joints.size());
  const JointFrame root{pose.root_rotation, pose.root_translation};
  for (int j = 0; j < skeleton.size(); ++j) {
    const Joint& joint = skeleton.joints[j];
    const JointFrame& parent = joint.parent < 0 ? root : world[joint.parent];
    // parent * T(offset) * R(local): the offset is carried by the parent's rotation only.
    world[j].position = parent.position + parent.rotation * joint.offset;
    world[j].rotation = (parent.rotation * pose.local[j]).normalized();
  }
}

}  // namespace clothlab
