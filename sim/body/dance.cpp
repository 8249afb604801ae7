#include "sim/body/dance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace clothlab {
namespace {

using Eigen::AngleAxisd;
using Eigen::Quaterniond;
using Eigen::Vector3d;

constexpr double kVelocityStep = 1e-6;  // s, half-width of the central difference
constexpr double kSoleSoftness = 1e-3;  // m, length scale of the soft minimum over sole corners

// Exponential map of a rotation vector (angle * axis) to a unit quaternion; exactly the identity
// for the zero vector, so a curve evaluated at its knot gives the keyframe bit for bit.
Quaterniond exp_map(const Vector3d& v) {
  const double angle = v.norm();
  if (angle < 1e-12) return Quaterniond(1, 0.5 * v.x(), 0.5 * v.y(), 0.5 * v.z()).normalized();
  return Quaterniond(AngleAxisd(angle, v / angle));
}

// Inverse of exp_map on the shorter of q and -q: a rotation vector of angle <= pi.
Vector3d log_map(const Quaterniond& q) {
  const double s = q.w() < 0 ? -1.0 : 1.0;
  const Vector3d v = s * q.vec();
  const double sin_half = v.norm();
  if (sin_half < 1e-12) return 2.0 * v;
  return 2.0 * std::atan2(sin_half, s * q.w()) / sin_half * v;
}

// Weights of the cumulative cubic Bezier basis (Kim, Kim & Shin 1995, "A general construction
// scheme for unit quaternion curves with simple high order derivatives", eq. 11):
// B1 = 1 - (1-s)^3, B2 = 3s^2 - 2s^3, B3 = s^3. Their slopes are (3, 0, 0) at s = 0 and
// (0, 0, 3) at s = 1, so the curve's angular velocity at each end is 3a/T and 3c/T.
std::array<double, 3> cumulative_bezier(double s) {
  const double r = 1 - s;
  return {1 - r * r * r, s * s * (3 - 2 * s), s * s * s};
}

// Slope at a knot from its two neighbouring chords, weighted by the other side's interval (the
// non-uniform Catmull-Rom tangent: the derivative of the parabola through the three points).
template <class T>
T knot_slope(const T& left_chord, double dl, const T& right_chord, double dr) {
  return (dr * left_chord / dl + dl * right_chord / dr) / (dl + dr);
}

// Cubic Hermite interpolation between (p0, m0) and (p1, m1) over an interval of length dt.
template <class T>
T hermite(const T& p0, const T& m0, const T& p1, const T& m1, double s, double dt) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * dt * m0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * dt * m1;
}

// One beat of the choreography, angles in degrees, as deviations from the rest pose. Steps
// between neighbouring beats stay under about 50 degrees: at 140 BPM (0.43 s a beat) and with
// the Catmull-Rom overshoot that keeps joints near 3 rad/s, well under the 10 rad/s of
// docs/contact.md section 3.
struct Move {
  double hip_sway;          // pelvis roll about +z; the hips roll back so the legs stay upright
  double chest_sway;        // chest roll about +z
  double chest_twist;       // chest about +y
  double nod;               // neck about +x (head forward)
  double raise_l, raise_r;  // arm abduction beyond the A-pose
  double swing_l, swing_r;  // arm forward (+) or back (-)
  double elbow_l, elbow_r;  // forearm bend forward
  double knee;              // squat: hips -k, knees +2k, ankles -k about x (soles stay flat)
  double turn;              // fraction of this loop's full turn about +y done by this beat
  double step;              // root shift along the body's +x, m
};

// The 16-beat loop. The turn (beats 8-12) happens with the arms out, so a skirt flares freely.
constexpr std::array<Move, 16> kLoop = {{
    {8, -6, 0, 10, 0, 0, 20, -20, 30, 30, 0, 0, 0.03},
    {-8, 6, 0, 0, 0, 0, -20, 20, 30, 30, 15, 0, -0.03},
    {8, -6, 10, 10, 40, 0, 0, 0, 60, 20, 0, 0, 0.03},
    {-8, 6, -10, 0, 0, 40, 0, 0, 20, 60, 15, 0, -0.03},
    {0, 0, 0, 10, 60, 60, 0, 0, 20, 20, 25, 0, 0},
    {0, 0, 0, 0, 100, 100, 0, 0, 10, 10, 0, 0, 0},
    {0, 0, 0, 10, 60, 60, 0, 0, 20, 20, 25, 0, 0},
    {6, -4, 0, 0, 30, 30, 30, 30, 40, 40, 0, 0, 0.02},
    {0, 0, 0, 0, 50, 50, 0, 0, 20, 20, 0, 0, 0},
    {0, 0, 0, 0, 55, 55, 0, 0, 15, 15, 0, 0.25, 0},
    {0, 0, 0, 0, 55, 55, 0, 0, 15, 15, 0, 0.5, 0},
    {0, 0, 0, 0, 55, 55, 0, 0, 15, 15, 0, 0.75, 0},
    {0, 0, 0, -5, 50, 50, 0, 0, 20, 20, 10, 1, 0},
    {-8, 6, 0, 10, 20, 0, 30, -20, 40, 20, 0, 1, -0.03},
    {8, -6, 0, 0, 0, 20, -20, 30, 20, 40, 15, 1, 0.03},
    {0, 0, 0, 10, 10, 10, 0, 0, 30, 30, 0, 1, 0},
}};
constexpr int kTurnBeat = 8;  // the loop's beat the turn starts from

Quaterniond about(const Vector3d& axis, double degrees) {
  return Quaterniond(AngleAxisd(degrees * (std::numbers::pi / 180.0), axis));
}

// The joints' rotations for a move, as deviations from their rest rotations (identity for
// joints the move leaves alone).
void move_deviation(const Skeleton& s, const Move& m, std::span<Quaterniond> dev) {
  std::fill(dev.begin(), dev.end(), Quaterniond::Identity());
  const Vector3d x = Vector3d::UnitX(), y = Vector3d::UnitY(), z = Vector3d::UnitZ();
  auto set = [&](const char* name, const Quaterniond& q) {
    if (const int j = s.find(name); j >= 0) dev[j] = q;
  };
  set("pelvis", about(z, m.hip_sway));
  set("chest", about(y, m.chest_twist) * about(z, m.chest_sway));
  set("neck", about(x, m.nod));
  set("left_shoulder", about(z, m.raise_l) * about(x, -m.swing_l));
  set("right_shoulder", about(z, -m.raise_r) * about(x, -m.swing_r));
  set("left_elbow", about(x, -m.elbow_l));
  set("right_elbow", about(x, -m.elbow_r));
  for (const char* hip : {"left_hip", "right_hip"})
    set(hip, about(z, -m.hip_sway) * about(x, -m.knee));
  set("left_knee", about(x, 2 * m.knee));
  set("right_knee", about(x, 2 * m.knee));
  set("left_ankle", about(x, -m.knee));
  set("right_ankle", about(x, -m.knee));
}

}  // namespace

std::vector<double> constant_tempo_beats(double bpm, double duration, double first) {
  std::vector<double> beats;
  const double period = 60.0 / bpm;
  for (int i = 0; first + i * period <= duration; ++i) beats.push_back(first + i * period);
  return beats;
}

Dance::Dance(Mannequin mannequin, DanceSpec spec, std::vector<double> beats,
             std::vector<double> beat_amplitude)
    : mannequin_(std::move(mannequin)), spec_(spec), rest_(rest_pose(mannequin_.skeleton)) {
  for (std::size_t i = 1; i < beats.size(); ++i)
    if (!(beats[i] > beats[i - 1])) throw std::invalid_argument("dance: beats must increase");
  if (!beat_amplitude.empty() && beat_amplitude.size() != beats.size())
    throw std::invalid_argument("dance: one amplitude per beat, or none");
  spec_.blend_beats = std::max(spec_.blend_beats, 1);
  for (int i = 0; i < primitive_count(); ++i)
    if (mannequin_.primitives[i].shape == BodyShape::box &&
        mannequin_.primitives[i].name.ends_with("foot"))
      feet_.push_back(i);
  std::array<JointFrame, kMaxJoints> world;
  forward_kinematics(mannequin_.skeleton, rest_, world);
  rest_sole_ = sole_height(world);
  build_keyframes(beats, beat_amplitude);
  build_curves();
}

void Dance::build_keyframes(const std::vector<double>& beats,
                            const std::vector<double>& amplitude) {
  const auto first_after_settle =
      std::lower_bound(beats.begin(), beats.end(), spec_.settle_seconds);
  const std::size_t k0 = (first_after_settle - beats.begin()) + spec_.blend_beats;
  const int n = mannequin_.skeleton.size();
  std::array<Quaterniond, kMaxJoints> dev;
  std::array<JointFrame, kMaxJoints> world;
  double turns_done = 0;  // full turns of earlier loops, rad
  bool turning = false;
  for (std::size_t i = k0; i < beats.size(); ++i) {
    const auto beat = static_cast<int>((i - k0) % kLoop.size());
    const double a =
        spec_.amplitude * (amplitude.empty() ? 1.0 : std::clamp(amplitude[i], 0.0, 1.0));
    // The turn is all or nothing (half a turn would leave her facing backwards): a loop turns
    // where the music is loud enough on the beat the turn starts.
    if (beat == 0 && turning) turns_done += 2 * std::numbers::pi;
    if (beat == 0) turning = false;
    if (beat == kTurnBeat) turning = a >= 0.5;
    const Move& m = kLoop[beat];
    move_deviation(mannequin_.skeleton, m, std::span(dev.data(), n));
    SkeletonPose key = rest_;
    for (int j = 0; j < n; ++j)  // slerp from rest by a, in the exponential map
      key.local[j] = rest_.local[j] * exp_map(a * log_map(dev[j]));
    const double yaw = turns_done + (turning ? 2 * std::numbers::pi * m.turn : 0.0);
    key.root_rotation = Quaterniond(AngleAxisd(yaw, Vector3d::UnitY()));
    key.root_translation = key.root_rotation * Vector3d(a * m.step, 0, 0);
    forward_kinematics(mannequin_.skeleton, key, world);
    key.root_translation.y() = rest_sole_ - sole_height(world);
    key_times_.push_back(beats[i]);
    keys_.push_back(key);
    key_yaw_.push_back(yaw);
  }
}

void Dance::build_curves() {
  const int n = mannequin_.skeleton.size();
  const int count = static_cast<int>(keys_.size());
  std::vector<Vector3d> omega(count * n, Vector3d::Zero());  // body angular velocity at knots
  yaw_slope_.assign(count, 0.0);
  step_slope_.assign(count, Vector3d::Zero());
  // Interior knots get Catmull-Rom slopes; the first and last are at rest (zero slope), so the
  // curve joins the held poses before and after C1.
  for (int k = 1; k + 1 < count; ++k) {
    const double dl = key_times_[k] - key_times_[k - 1], dr = key_times_[k + 1] - key_times_[k];
    for (int j = 0; j < n; ++j) {
      // A relative rotation's vector is the same seen from either end, so both chords are in
      // the frame of key k.
      const Vector3d left = log_map(keys_[k - 1].local[j].conjugate() * keys_[k].local[j]);
      const Vector3d right = log_map(keys_[k].local[j].conjugate() * keys_[k + 1].local[j]);
      omega[k * n + j] = knot_slope(left, dl, right, dr);
    }
    yaw_slope_[k] =
        knot_slope(key_yaw_[k] - key_yaw_[k - 1], dl, key_yaw_[k + 1] - key_yaw_[k], dr);
    const Vector3d step_l = keys_[k].root_translation - keys_[k - 1].root_translation;
    const Vector3d step_r = keys_[k + 1].root_translation - keys_[k].root_translation;
    step_slope_[k] = knot_slope(step_l, dl, step_r, dr);
    step_slope_[k].y() = 0;  // the height comes from the floor, not from this curve
  }
  segments_.resize(std::max(count - 1, 0) * n);
  for (int k = 0; k + 1 < count; ++k) {
    const double dt = key_times_[k + 1] - key_times_[k];
    for (int j = 0; j < n; ++j) {
      // Kim, Kim & Shin 1995: control rotations a and c set the end angular velocities; b closes
      // the curve on the next keyframe.
      JointSegment& seg = segments_[k * n + j];
      seg.a = omega[k * n + j] * dt / 3;
      seg.c = omega[(k + 1) * n + j] * dt / 3;
      seg.b = log_map(exp_map(-seg.a) * keys_[k].local[j].conjugate() * keys_[k + 1].local[j] *
                      exp_map(-seg.c));
    }
  }
}

void Dance::dance_pose(double t, SkeletonPose& out) const {
  const int n = mannequin_.skeleton.size();
  const int count = static_cast<int>(keys_.size());
  if (t <= key_times_.front() || count == 1) {
    out = keys_.front();
  } else if (t >= key_times_.back()) {
    out = keys_.back();
  } else {
    const int k = static_cast<int>(std::upper_bound(key_times_.begin(), key_times_.end(), t) -
                                   key_times_.begin()) -
                  1;
    const double dt = key_times_[k + 1] - key_times_[k];
    const double s = (t - key_times_[k]) / dt;
    const auto w = cumulative_bezier(s);
    for (int j = 0; j < n; ++j) {
      const JointSegment& seg = segments_[k * n + j];
      out.local[j] =
          keys_[k].local[j] * exp_map(w[0] * seg.a) * exp_map(w[1] * seg.b) * exp_map(w[2] * seg.c);
    }
    const double yaw =
        hermite(key_yaw_[k], yaw_slope_[k], key_yaw_[k + 1], yaw_slope_[k + 1], s, dt);
    out.root_rotation = Quaterniond(AngleAxisd(yaw, Vector3d::UnitY()));
    out.root_translation = hermite(keys_[k].root_translation, step_slope_[k],
                                   keys_[k + 1].root_translation, step_slope_[k + 1], s, dt);
  }
  out.root_translation.y() = 0;
}

void Dance::evaluate(double t, SkeletonPose& pose, std::span<JointFrame> world) const {
  const Skeleton& skeleton = mannequin_.skeleton;
  if (keys_.empty() || t <= spec_.settle_seconds) {
    pose = rest_;
    forward_kinematics(skeleton, pose, world);
    return;
  }
  dance_pose(t, pose);
  if (t < blend_end()) {  // C1 blend from rest: smoothstep weight, zero slope at both ends
    const double u = (t - spec_.settle_seconds) / (blend_end() - spec_.settle_seconds);
    const double w = u * u * (3 - 2 * u);
    for (int j = 0; j < skeleton.size(); ++j)
      pose.local[j] = rest_.local[j].slerp(w, pose.local[j]);
    pose.root_rotation = rest_.root_rotation.slerp(w, pose.root_rotation);
    pose.root_translation *= w;
  }
  // Lift or lower the whole figure so its soles rest where they do in the rest pose. A soft
  // minimum over the sole corners keeps this smooth where the lowest corner changes.
  forward_kinematics(skeleton, pose, world);
  const double lift = rest_sole_ - sole_height(world);
  pose.root_translation.y() += lift;
  for (int j = 0; j < skeleton.size(); ++j) world[j].position.y() += lift;
}

double Dance::sole_height(std::span<const JointFrame> world) const {
  // Soft minimum -s log sum exp(-y/s) over the foot boxes' corners, shifted by the true minimum
  // for range; it lies within s log(corners) below the lowest corner.
  std::array<double, 64> y;
  int count = 0;
  for (const int i : feet_) {
    const BodyPrimitive& p = mannequin_.primitives[i];
    const RigidState f = primitive_frame(p, world[p.joint]);
    for (int c = 0; c < 8 && count < static_cast<int>(y.size()); ++c) {
      const Vector3d corner((c & 1 ? 1 : -1) * p.half_extents.x(),
                            (c & 2 ? 1 : -1) * p.half_extents.y(),
                            (c & 4 ? 1 : -1) * p.half_extents.z());
      y[count++] = (f.rotation * corner + f.position).y();
    }
  }
  if (count == 0) return 0.0;
  const double lowest = *std::min_element(y.begin(), y.begin() + count);
  double sum = 0;
  for (int c = 0; c < count; ++c) sum += std::exp(-(y[c] - lowest) / kSoleSoftness);
  return lowest - kSoleSoftness * std::log(sum);
}

void Dance::pose(double t, SkeletonPose& out) const {
  std::array<JointFrame, kMaxJoints> world;
  evaluate(t, out, world);
}

void Dance::joint_frames(double t, std::span<JointFrame> out) const {
  SkeletonPose pose;
  evaluate(t, pose, out);
}

void Dance::states(double t, std::span<RigidState> out) const {
  std::array<JointFrame, kMaxJoints> now, before, after;
  joint_frames(t, now);
  joint_frames(t - kVelocityStep, before);
  joint_frames(t + kVelocityStep, after);
  for (int i = 0; i < primitive_count(); ++i) {
    const BodyPrimitive& p = mannequin_.primitives[i];
    const RigidState x0 = primitive_frame(p, before[p.joint]);
    const RigidState x1 = primitive_frame(p, after[p.joint]);
    out[i] = primitive_frame(p, now[p.joint]);
    out[i].velocity = (x1.position - x0.position) / (2 * kVelocityStep);
    // R1 = exp(w 2h) R0 with w in world axes.
    out[i].angular_velocity = log_map(x1.rotation * x0.rotation.conjugate()) / (2 * kVelocityStep);
  }
}

Eigen::AlignedBox3d Dance::body_bounds(double t) const {
  std::array<JointFrame, kMaxJoints> world;
  joint_frames(t, world);
  Eigen::AlignedBox3d box;  // empty
  for (const BodyPrimitive& p : mannequin_.primitives)
    box.extend(primitive_bounds(p, primitive_frame(p, world[p.joint])));
  return box;
}

}  // namespace clothlab
