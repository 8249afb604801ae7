// A collider at run time: its shape as a signed distance in its own frame, and its rigid pose
// at any time (docs/contact.md section 1). One interface for every shape: phi(p) (negative inside),
// its gradient as the outward normal, and the surface velocity v_c = v + w x (x - c) that the
// contact response works relative to.
#pragma once

#include <cassert>

#include <Eigen/Geometry>
#include <memory>

#include "sim/mesh/sdf_grid.hpp"
#include "sim/scene/collider_spec.hpp"

namespace clothlab {

// The collider's frame at a time: world = rotation * local + centre, and its rigid velocity.
struct ColliderPose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // of the centre, m/s
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, world axes

  // Whether rotation is other than the identity: an unturned frame skips the products, which
  // with the identity give the same numbers. Whoever sets rotation sets it (Collider::pose);
  // debug builds check.
  bool turned = false;

  Eigen::Vector3d to_local(const Eigen::Vector3d& x) const {
    assert(turned || rotation.isIdentity(0.0));
    return turned ? Eigen::Vector3d(rotation.transpose() * (x - centre))
                  : Eigen::Vector3d(x - centre);
  }
  Eigen::Vector3d to_world(const Eigen::Vector3d& p) const { return rotate(p) + centre; }
  // A local direction in world axes.
  Eigen::Vector3d rotate(const Eigen::Vector3d& d) const {
    assert(turned || rotation.isIdentity(0.0));
    return turned ? Eigen::Vector3d(rotation * d) : d;
  }
  // Velocity of the collider's material at world point x.
  Eigen::Vector3d surface_velocity(const Eigen::Vector3d& x) const {
    return velocity + angular_velocity.cross(x - centre);
  }
};

// Signed distance and outward unit normal, in the collider's own frame.
struct LocalDistance {
  double phi = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
};

// Axis-aligned world bounds; a plane's are unbounded.
struct Bounds {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(-INFINITY);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(INFINITY);
  bool overlaps(const Bounds& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
};

// One collider over a substep: its poses at the start and the end, and the box round both
// grown by its thickness.
struct ColliderSweep {
  ColliderPose start, end;
  Bounds box;        // the shape and its shell over the substep
  Bounds reach_box;  // the same out to where the response holds vertices it leaves alone
};

class Collider {
 public:
  explicit Collider(const ColliderSpec& spec) : Collider(spec, true) {}

  const ColliderSpec& spec() const { return spec_; }
  double thickness() const { return spec_.thickness; }
  bool moving() const { return spec_.moves(); }

  // Pose at time t (s): the built pose moved by the motion.
  ColliderPose pose(double t) const;
  // Distance from the surface of local point p (negative inside) and the outward normal there.
  LocalDistance local_distance(const Eigen::Vector3d& p) const;
  // World bounds of the shape at `pose`, grown by `margin` on every side.
  Bounds bounds(const ColliderPose& pose, double margin) const;
  // Whether any point of `box` may lie within `margin` of the shape at `pose` (conservative: a
  // box test for bounded shapes; for a plane, the box's lowest corner against it, so a cloth
  // high above the floor costs no per-vertex work).
  bool reaches(const Bounds& box, const ColliderPose& pose, double margin) const;

 private:
  friend Collider pose_only_collider(const ColliderSpec& spec);
  // build_grid = false: a mesh collider keeps only its box (pose_only_collider).
  Collider(const ColliderSpec& spec, bool build_grid);
  // pose() before it marks whether the frame is turned.
  ColliderPose pose_at(double t) const;

  ColliderSpec spec_;
  // The built frame: plane: point and the rotation taking +y to the normal; sphere and box:
  // centre and rotation; capsule: the midpoint of a-b and the rotation taking +y to b - a.
  Eigen::Quaterniond rotation0_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d centre0_ = Eigen::Vector3d::Zero();
  double half_length_ = 0.0;            // capsule: half of |b - a|
  std::shared_ptr<const SdfGrid> sdf_;  // mesh: its signed distance, shared by copies
  Eigen::Vector3d mesh_lo_ = Eigen::Vector3d::Zero(), mesh_hi_ = Eigen::Vector3d::Zero();  // mesh
};

// A collider for its poses alone (drawing, framing, moving pins): a mesh collider's distance grid
// is not built again; the collision response holds the one that is.
Collider pose_only_collider(const ColliderSpec& spec);

// Rotation of Euler angles in degrees about x, then y, then z (R = Rz Ry Rx), as MeshSpec uses.
Eigen::Quaterniond rotation_from_degrees(const Vec3d& degrees);

}  // namespace clothlab
