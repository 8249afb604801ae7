// The dancing mannequin as the solver sees it: each of its primitives is a collider
// (sim/contact/collider.hpp) whose pose at a time comes from here. The solver poses colliders
// at every substep's start and end, and moving pins at every substep, so the whole body is
// evaluated once per distinct time and kept for a few recent times: sixteen colliders and a
// waistband of pins at one substep time cost one evaluation of the dance (about 6 us).
#pragma once

#include <array>
#include <cmath>
#include <mutex>

#include "sim/body/dance.hpp"

namespace clothlab {

class BodyMotion {
 public:
  static constexpr int kMaxParts = 24;

  // The dance placed in the world: turned `facing_degrees` about +y, then moved to `position`
  // (the dance's own frame stands at the origin facing +z). A mannequin of more than kMaxParts
  // primitives is a programmer error (CLOTHLAB_CHECK).
  BodyMotion(Dance dance, const Eigen::Vector3d& position, double facing_degrees);

  const Dance& dance() const { return dance_; }
  int part_count() const { return dance_.primitive_count(); }

  // World frame and velocity of primitive `part` at time t. Thread-safe.
  RigidState state(int part, double t) const;

  // The fastest speed of any point of any primitive between t0 and t1 (sampled every `dt` s,
  // points up to each primitive's extent from its centre): |v| + |w| r.
  double max_surface_speed(double t0, double t1, double dt = 0.005) const;
  // The smallest radius of a limb (capsule or sphere) or half extent of a box: the thinnest
  // feature a vertex could be pushed across.
  double thinnest_feature() const;

 private:
  struct Entry {
    double t = NAN;
    std::array<RigidState, kMaxParts> states;
  };
  const Entry& evaluate(double t) const;  // with mutex_ held

  Dance dance_;
  Eigen::Quaterniond facing_;
  Eigen::Vector3d position_;
  mutable std::mutex mutex_;
  mutable std::array<Entry, 4> cache_;
  mutable std::size_t next_ = 0;
};

}  // namespace clothlab
