#include "sim/contact/collider.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/body/body_motion.hpp"
#include "sim/core/vec3_math.hpp"

namespace clothlab {
namespace {

Eigen::Vector3d vec(const Vec3d& v) {
  return {v[0], v[1], v[2]};
}

// The rotation taking +y to unit d (the shortest arc; half a turn about x when d is -y).
Eigen::Quaterniond rotate_y_to(const Eigen::Vector3d& d) {
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitY().cross(d);
  const double s = axis.norm(), c = d.y();
  if (s < 1e-12)
    return c > 0.0
               ? Eigen::Quaterniond::Identity()
               : Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()));
  return Eigen::Quaterniond(Eigen::AngleAxisd(std::atan2(s, c), axis / s));
}

// Angular velocity (world axes) that turns qa into qb in dt seconds.
Eigen::Vector3d angular_velocity_between(const Eigen::Quaterniond& qa, const Eigen::Quaterniond& qb,
                                         double dt) {
  const Eigen::AngleAxisd turn(qb * qa.conjugate());
  double angle = turn.angle();
  if (angle > std::numbers::pi) angle -= 2.0 * std::numbers::pi;  // the short way round
  return turn.axis() * (angle / dt);
}

}  // namespace

Eigen::Quaterniond rotation_from_degrees(const Vec3d& degrees) {
  const double k = std::numbers::pi / 180.0;
  return Eigen::AngleAxisd(degrees[2] * k, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(degrees[1] * k, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(degrees[0] * k, Eigen::Vector3d::UnitX());
}

Collider pose_only_collider(const ColliderSpec& spec) {
  Collider c(spec, false);
  c.spec_.mesh.reset();
  return c;
}

Collider::Collider(const ColliderSpec& spec, bool build_grid) : spec_(spec) {
  switch (spec.kind) {
    case ColliderKind::plane:
      centre0_ = vec(spec.point);
      rotation0_ = rotate_y_to(vec(normalised(spec.normal)));
      break;
    case ColliderKind::sphere:
      centre0_ = vec(spec.center);
      break;
    case ColliderKind::box:
      centre0_ = vec(spec.center);
      rotation0_ = rotation_from_degrees(spec.rotation);
      break;
    case ColliderKind::mesh:
      // The OBJ's own coordinates are the local frame, placed at `center` with `rotation`.
      centre0_ = vec(spec.center);
      rotation0_ = rotation_from_degrees(spec.rotation);
      if (spec.mesh && build_grid)
        sdf_ = std::make_shared<const SdfGrid>(*spec.mesh, spec.sdf_resolution);
      if (spec.mesh && !spec.mesh->positions.empty()) {
        mesh_lo_ = mesh_hi_ = spec.mesh->positions.front();
        for (const Eigen::Vector3d& p : spec.mesh->positions) {
          mesh_lo_ = mesh_lo_.cwiseMin(p);
          mesh_hi_ = mesh_hi_.cwiseMax(p);
        }
      }
      break;
    case ColliderKind::capsule: {
      const Eigen::Vector3d a = vec(spec.a), b = vec(spec.b);
      centre0_ = 0.5 * (a + b);
      half_length_ = 0.5 * (b - a).norm();
      rotation0_ = rotate_y_to((b - a).normalized());
      break;
    }
  }
}

ColliderPose Collider::pose(double t) const {
  ColliderPose p = pose_at(t);
  p.turned = !p.rotation.isIdentity(0.0);
  return p;
}

ColliderPose Collider::pose_at(double t) const {
  ColliderPose p;
  if (spec_.body) {  // a part of the dancing body: its frame is the shape's own
    const RigidState s = spec_.body->state(spec_.body_part, t);
    p.rotation = s.rotation.toRotationMatrix();
    p.centre = s.position;
    p.velocity = s.velocity;
    p.angular_velocity = s.angular_velocity;
    return p;
  }
  const ColliderMotion& m = spec_.motion;
  if (m.keys.empty()) {
    // Constant velocities: the centre moves along v, the body turns about it at w (world axes).
    const Eigen::Vector3d w = vec(m.angular_velocity);
    const double speed = w.norm();
    Eigen::Quaterniond q = rotation0_;
    if (speed > 0.0) q = Eigen::Quaterniond(Eigen::AngleAxisd(speed * t, w / speed)) * rotation0_;
    p.rotation = q.toRotationMatrix();
    p.centre = centre0_ + vec(m.velocity) * t;
    p.velocity = vec(m.velocity);
    p.angular_velocity = w;
    return p;
  }
  // Keyframes: offsets interpolated linearly, rotations by slerp, held outside the keys; the
  // velocities are those of the segment t lies in (zero outside).
  const auto& keys = m.keys;
  auto key_rotation = [&](const ColliderKey& k) { return rotation_from_degrees(k.rotation); };
  if (t <= keys.front().time || keys.size() == 1) {
    const ColliderKey& k = t <= keys.front().time ? keys.front() : keys.back();
    p.rotation = (key_rotation(k) * rotation0_).toRotationMatrix();
    p.centre = centre0_ + vec(k.offset);
    return p;
  }
  if (t >= keys.back().time) {
    p.rotation = (key_rotation(keys.back()) * rotation0_).toRotationMatrix();
    p.centre = centre0_ + vec(keys.back().offset);
    return p;
  }
  std::size_t i = 1;
  while (keys[i].time < t) ++i;
  const ColliderKey &k0 = keys[i - 1], &k1 = keys[i];
  const double span = k1.time - k0.time, s = (t - k0.time) / span;
  const Eigen::Quaterniond q0 = key_rotation(k0), q1 = key_rotation(k1);
  p.rotation = (q0.slerp(s, q1) * rotation0_).toRotationMatrix();
  p.centre = centre0_ + (1.0 - s) * vec(k0.offset) + s * vec(k1.offset);
  p.velocity = (vec(k1.offset) - vec(k0.offset)) / span;
  p.angular_velocity = angular_velocity_between(q0, q1, span);
  return p;
}

LocalDistance Collider::local_distance(const Eigen::Vector3d& p) const {
  LocalDistance d;
  switch (spec_.kind) {
    case ColliderKind::plane:
      d.phi = p.y();
      d.normal = Eigen::Vector3d::UnitY();
      break;
    case ColliderKind::sphere: {
      const double r = p.norm();
      d.phi = r - spec_.radius;
      d.normal = r > 1e-12 ? Eigen::Vector3d(p / r) : Eigen::Vector3d::UnitY();
      break;
    }
    case ColliderKind::box: {
      // Rounded box (Quilez's sdRoundBox): q = |p| - (h - r); outside, the distance to the
      // shrunk box; inside, the largest (least negative) face distance; minus the rounding r.
      const double r = spec_.rounding;
      const Eigen::Vector3d h = vec(spec_.half_extents).array() - r;
      const Eigen::Vector3d q = p.cwiseAbs() - h;
      const Eigen::Vector3d outside = q.cwiseMax(0.0);
      const double out = outside.norm();
      Eigen::Vector3d::Index axis = 0;
      const double inside = std::min(q.maxCoeff(&axis), 0.0);
      d.phi = out + inside - r;
      const Eigen::Vector3d sign = p.unaryExpr([](double x) { return x < 0.0 ? -1.0 : 1.0; });
      if (out > 0.0) {
        d.normal = outside.cwiseProduct(sign) / out;
      } else {
        d.normal = Eigen::Vector3d::Zero();
        d.normal[axis] = sign[axis];
      }
      break;
    }
    case ColliderKind::mesh:
      if (sdf_)
        d.phi = sdf_->distance(p, &d.normal);
      else
        d.phi = INFINITY;  // no mesh read: nothing to collide with
      break;
    case ColliderKind::capsule: {
      // Distance to the axis segment (local y from -L to L), minus the radius.
      const Eigen::Vector3d closest(0.0, std::clamp(p.y(), -half_length_, half_length_), 0.0);
      const Eigen::Vector3d off = p - closest;
      const double r = off.norm();
      d.phi = r - spec_.radius;
      d.normal = r > 1e-12 ? Eigen::Vector3d(off / r) : Eigen::Vector3d::UnitX();
      break;
    }
  }
  return d;
}

bool Collider::reaches(const Bounds& box, const ColliderPose& pose, double margin) const {
  if (spec_.kind != ColliderKind::plane) return bounds(pose, margin).overlaps(box);
  // The signed distance of the box's corner deepest along -n: centre distance minus the box's
  // half extent projected on |n|.
  const Eigen::Vector3d n = pose.rotation.col(1);
  const Eigen::Vector3d centre = 0.5 * (box.lo + box.hi), half = 0.5 * (box.hi - box.lo);
  return n.dot(centre - pose.centre) - half.dot(n.cwiseAbs()) <= margin;
}

Bounds Collider::bounds(const ColliderPose& pose, double margin) const {
  Bounds b;
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();  // half size of the world box
  switch (spec_.kind) {
    case ColliderKind::plane:
      return b;  // unbounded
    case ColliderKind::sphere:
      extent.setConstant(spec_.radius);
      break;
    case ColliderKind::box:
      extent = pose.rotation.cwiseAbs() * vec(spec_.half_extents);
      break;
    case ColliderKind::capsule:
      extent = (pose.rotation.col(1) * half_length_).cwiseAbs().array() + spec_.radius;
      break;
    case ColliderKind::mesh: {
      if (!sdf_ && mesh_lo_ == mesh_hi_)
        return Bounds{Eigen::Vector3d::Constant(INFINITY), Eigen::Vector3d::Constant(-INFINITY)};
      // The grid's box (the mesh plus its margin; for a collider kept for its poses alone, the
      // mesh's box), turned: its corners' extent about the centre.
      const Eigen::Vector3d box_lo = sdf_ ? sdf_->lo() : mesh_lo_,
                            box_hi = sdf_ ? sdf_->hi() : mesh_hi_;
      const Eigen::Vector3d mid = 0.5 * (box_lo + box_hi), half = 0.5 * (box_hi - box_lo);
      extent = pose.rotation.cwiseAbs() * half;
      b.lo = pose.to_world(mid) - extent - Eigen::Vector3d::Constant(margin);
      b.hi = pose.to_world(mid) + extent + Eigen::Vector3d::Constant(margin);
      return b;
    }
  }
  b.lo = pose.centre - extent - Eigen::Vector3d::Constant(margin);
  b.hi = pose.centre + extent + Eigen::Vector3d::Constant(margin);
  return b;
}

}  // namespace clothlab
