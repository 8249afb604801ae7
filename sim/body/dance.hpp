// The mannequin dancing to beats (docs/contact.md section 3). The rest (A-)pose is held for
// settle_seconds, so garments can settle and seams close; then the dance blends in with a
// smoothstep weight until the first keyframe, which lands on the blend_beats-th beat after
// settle_seconds. From there one keyframe pose sits exactly on every beat (a 16-beat loop: hip
// sway, arm raises and swings, knee bends, a full turn of the body over 4 beats so a skirt
// flares, head nods), each one's deviation from the rest pose scaled by the beat's amplitude.
// Between beats the joints follow C1 quaternion curves with the beat times as (non-uniform)
// knots, the body's turn and its step a cubic Hermite; the figure is lifted or lowered so the
// soles stay on y = 0. Everything is computed at construction but the evaluation at a time,
// which allocates nothing: the solver poses the body at every substep.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <span>
#include <vector>

#include "sim/body/mannequin.hpp"
#include "sim/body/skeleton.hpp"

namespace clothlab {

struct DanceSpec {
  double settle_seconds = 1.5;    // rest pose held until then, s
  int blend_beats = 4;            // beats over which the dance blends in (at least 1)
  double amplitude = 1.0;         // scales every keyframe's deviation from the rest pose
  double max_joint_speed = 10.0;  // rad/s; the choreography keeps under it up to 140 BPM
};

// Beats every 60/bpm seconds from `first` up to `duration` (a constant tempo).
std::vector<double> constant_tempo_beats(double bpm, double duration, double first = 0.0);

class Dance {
 public:
  // beats: increasing times in seconds (a beat tracker's, or constant_tempo_beats()).
  // beat_amplitude: one value in [0, 1] per beat (e.g. the music's band energy), or empty for
  // all 1. Throws std::invalid_argument for beats that do not increase or a size mismatch.
  Dance(Mannequin mannequin, DanceSpec spec, std::vector<double> beats,
        std::vector<double> beat_amplitude = {});

  // World frame and velocity of every primitive at time t (out.size() >= primitive_count()).
  // Velocities are central differences of the pose over +-1e-6 s. Cost: three evaluations of
  // the pose and the skeleton, no allocation.
  void states(double t, std::span<RigidState> out) const;
  // The skeleton's pose at time t, root height included.
  void pose(double t, SkeletonPose& out) const;
  // World frame of every joint at time t (out.size() >= skeleton size).
  void joint_frames(double t, std::span<JointFrame> out) const;
  // World box around every primitive at time t.
  Eigen::AlignedBox3d body_bounds(double t) const;

  // The beat each keyframe is placed on, and that keyframe's pose.
  std::vector<double> keyframe_times() const { return key_times_; }
  const SkeletonPose& keyframe(int k) const { return keys_[k]; }
  // When the blend from the rest pose starts and ends (the first keyframe's beat).
  double blend_start() const { return spec_.settle_seconds; }
  double blend_end() const { return key_times_.empty() ? INFINITY : key_times_.front(); }

  int primitive_count() const { return static_cast<int>(mannequin_.primitives.size()); }
  const std::vector<BodyPrimitive>& primitives() const { return mannequin_.primitives; }
  const Mannequin& mannequin() const { return mannequin_; }
  const SkeletonPose& rest() const { return rest_; }

 private:
  // One joint's curve between two keyframes: q(s) = q_k exp(a B1(s)) exp(b B2(s)) exp(c B3(s)).
  struct JointSegment {
    Eigen::Vector3d a, b, c;
  };
  // The dance alone (no blend, no floor), held at its first and last keyframes outside them.
  void dance_pose(double t, SkeletonPose& out) const;
  // Blend with the rest pose and lift onto the floor; fills `world` with the joint frames.
  void evaluate(double t, SkeletonPose& pose, std::span<JointFrame> world) const;
  // Height of the soles (a soft minimum over the foot boxes' corners).
  double sole_height(std::span<const JointFrame> world) const;
  void build_keyframes(const std::vector<double>& beats, const std::vector<double>& amplitude);
  void build_curves();

  Mannequin mannequin_;
  DanceSpec spec_;
  SkeletonPose rest_;
  double rest_sole_ = 0;                     // sole_height of the rest pose
  std::vector<int> feet_;                    // primitives whose corners touch the floor
  std::vector<double> key_times_;            // s
  std::vector<SkeletonPose> keys_;           // root_translation.y includes the floor lift
  std::vector<double> key_yaw_;              // the body's turn about +y, rad, unwrapped
  std::vector<double> yaw_slope_;            // rad/s at each keyframe
  std::vector<Eigen::Vector3d> step_slope_;  // root translation's slope at each keyframe, m/s
  std::vector<JointSegment> segments_;       // (keys - 1) x joints
};

}  // namespace clothlab
