#include "sim/body/body_motion.hpp"

#include <algorithm>
#include <stdexcept>

#include "sim/core/check.hpp"

namespace clothlab {

BodyMotion::BodyMotion(Dance dance, const Eigen::Vector3d& position, double facing_degrees)
    : dance_(std::move(dance)),
      facing_(Eigen::AngleAxisd(facing_degrees * M_PI / 180.0, Eigen::Vector3d::UnitY())),
      position_(position) {
  CLOTHLAB_CHECK_LE(dance_.primitive_count(), kMaxParts);  // the pose cache holds kMaxParts
}

const BodyMotion::Entry& BodyMotion::evaluate(double t) const {
  for (const Entry& e : cache_)
    if (e.t == t) return e;
  Entry& e = cache_[next_];
  next_ = (next_ + 1) % cache_.size();
  dance_.states(t, std::span<RigidState>(e.states.data(), std::size_t(part_count())));
  for (int i = 0; i < part_count(); ++i) {
    RigidState& s = e.states[std::size_t(i)];
    s.rotation = facing_ * s.rotation;
    s.position = facing_ * s.position + position_;
    s.velocity = facing_ * s.velocity;
    s.angular_velocity = facing_ * s.angular_velocity;
  }
  e.t = t;
  return e;
}

RigidState BodyMotion::state(int part, double t) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return evaluate(t).states[std::size_t(part)];
}

double BodyMotion::max_surface_speed(double t0, double t1, double dt) const {
  double fastest = 0.0;
  std::array<RigidState, kMaxParts> s;
  for (double t = t0; t <= t1; t += dt) {
    dance_.states(t, std::span<RigidState>(s.data(), std::size_t(part_count())));
    for (int i = 0; i < part_count(); ++i) {
      const BodyPrimitive& p = dance_.primitives()[std::size_t(i)];
      const double reach =
          p.shape == BodyShape::box ? p.half_extents.norm() : p.radius + p.half_length;
      fastest = std::max(fastest, s[std::size_t(i)].velocity.norm() +
                                      s[std::size_t(i)].angular_velocity.norm() * reach);
    }
  }
  return fastest;
}

double BodyMotion::thinnest_feature() const {
  double thinnest = INFINITY;
  for (const BodyPrimitive& p : dance_.primitives())
    thinnest = std::min(thinnest, p.shape == BodyShape::box ? p.half_extents.minCoeff() : p.radius);
  return thinnest;
}

}  // namespace clothlab
