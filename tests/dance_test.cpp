// The dance (sim/body/dance.hpp): the rest pose held while garments settle, keyframes exactly on
// the beats (constant and changing tempo), C1 motion across every knot, joint speeds under the
// limit at 140 BPM, velocities that are the derivative of the motion, a full turn, soles on the
// floor, amplitude scaling, bounds, and no allocation per call.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "allocation_counter.hpp"
#include "body_box_distance.hpp"
#include "sim/body/dance.hpp"

namespace clothlab {
namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;
using Frames = std::array<RigidState, 32>;

double angle_between(const Quaterniond& a, const Quaterniond& b) {
  return a.angularDistance(b);
}

Frames frames_at(const Dance& d, double t) {
  Frames f;
  d.states(t, f);
  return f;
}

// Lowest corner of the foot boxes at time t.
double lowest_sole(const Dance& d, double t) {
  const Frames f = frames_at(d, t);
  double lowest = INFINITY;
  for (int i = 0; i < d.primitive_count(); ++i) {
    const BodyPrimitive& p = d.primitives()[i];
    if (!p.name.ends_with("foot")) continue;
    for (int c = 0; c < 8; ++c) {
      const Vector3d corner((c & 1 ? 1 : -1) * p.half_extents.x(),
                            (c & 2 ? 1 : -1) * p.half_extents.y(),
                            (c & 4 ? 1 : -1) * p.half_extents.z());
      lowest = std::min(lowest, (f[i].rotation * corner + f[i].position).y());
    }
  }
  return lowest;
}

// Beats whose tempo ramps linearly from bpm0 to bpm1 over `duration` seconds.
std::vector<double> ramp_beats(double bpm0, double bpm1, double duration) {
  std::vector<double> beats;
  for (double t = 0.2; t < duration;) {
    beats.push_back(t);
    t += 60.0 / (bpm0 + (bpm1 - bpm0) * t / duration);
  }
  return beats;
}

double max_pose_difference(const SkeletonPose& a, const SkeletonPose& b, int joints) {
  double diff = (a.root_translation - b.root_translation).norm();
  diff = std::max(diff, angle_between(a.root_rotation, b.root_rotation));
  for (int j = 0; j < joints; ++j) diff = std::max(diff, angle_between(a.local[j], b.local[j]));
  return diff;
}

// Largest jump of any primitive's velocity and angular velocity across each knot in `knots`
// (states at t -+ 5e-6 s, outside the 1e-6 s difference stencil, so a kink would show), and of
// position over +-1e-7 s beyond what the velocity carries it.
struct Jumps {
  double velocity = 0, angular_velocity = 0, position = 0;
};
Jumps jumps_at(const Dance& d, const std::vector<double>& knots) {
  Jumps j;
  for (const double t : knots) {
    const Frames a = frames_at(d, t - 5e-6), b = frames_at(d, t + 5e-6);
    const Frames pa = frames_at(d, t - 1e-7), pb = frames_at(d, t + 1e-7);
    for (int i = 0; i < d.primitive_count(); ++i) {
      j.velocity = std::max(j.velocity, (a[i].velocity - b[i].velocity).norm());
      j.angular_velocity =
          std::max(j.angular_velocity, (a[i].angular_velocity - b[i].angular_velocity).norm());
      const Vector3d carried = 1e-7 * (pa[i].velocity + pb[i].velocity);
      j.position = std::max(j.position, (pb[i].position - pa[i].position - carried).norm());
    }
  }
  return j;
}

TEST(Dance, HoldsTheRestPoseExactlyUntilSettled) {
  const Mannequin m = make_mannequin();
  const Dance d(m, DanceSpec{}, constant_tempo_beats(120, 20));
  Frames rest;
  primitive_frames(m, rest_pose(m.skeleton), rest);
  for (double t = -1.0; t <= 1.5; t += 0.01) {
    const Frames f = frames_at(d, t);
    for (int i = 0; i < d.primitive_count(); ++i) {
      EXPECT_EQ(f[i].position, rest[i].position) << "t = " << t;
      EXPECT_EQ(f[i].rotation.coeffs(), rest[i].rotation.coeffs()) << "t = " << t;
      if (t < 1.5 - 1e-5) {
        EXPECT_EQ(f[i].velocity.norm(), 0.0);
      }
    }
  }
  // ... and has left it well before the first keyframe.
  EXPECT_GT(max_pose_difference(
                [&] {
                  SkeletonPose p;
                  d.pose(2.5, p);
                  return p;
                }(),
                d.rest(), m.skeleton.size()),
            0.05);
}

TEST(Dance, KeyframesLandExactlyOnTheirBeats) {
  const Mannequin m = make_mannequin();
  const std::vector<double> beats = constant_tempo_beats(120, 20);
  const Dance d(m, DanceSpec{}, beats);
  const std::vector<double> keys = d.keyframe_times();
  // First beat at or after settle (1.5 s) is 1.5 s; four beats of blend later: 3.5 s.
  ASSERT_FALSE(keys.empty());
  EXPECT_DOUBLE_EQ(keys.front(), 3.5);
  EXPECT_EQ(keys.size(), static_cast<std::size_t>(std::count_if(
                             beats.begin(), beats.end(), [](double b) { return b >= 3.5; })));
  const int n = m.skeleton.size();
  double worst = 0, largest_move = 0;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    SkeletonPose p;
    d.pose(keys[k], p);
    worst = std::max(worst, max_pose_difference(p, d.keyframe(static_cast<int>(k)), n));
    largest_move = std::max(largest_move, max_pose_difference(d.keyframe(k), d.rest(), n));
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(largest_move, 1.0);  // the keyframes are real moves (arms raised 100 degrees)
  // Between beats the pose is neither neighbour.
  SkeletonPose mid;
  d.pose(keys[4] + 0.25, mid);
  EXPECT_GT(max_pose_difference(mid, d.keyframe(4), n), 0.05);
  EXPECT_GT(max_pose_difference(mid, d.keyframe(5), n), 0.05);
}

TEST(Dance, MotionIsC1AcrossEveryKnot) {
  const Mannequin m = make_mannequin();
  const Dance d(m, DanceSpec{}, constant_tempo_beats(120, 20));
  std::vector<double> knots = d.keyframe_times();
  knots.push_back(d.blend_start());
  const Jumps j = jumps_at(d, knots);
  std::printf("C1 at 120 BPM: max jump |dv| %.2e m/s, |dw| %.2e rad/s, |dx| %.2e m\n", j.velocity,
              j.angular_velocity, j.position);
  // Over 1e-5 s an acceleration of ~100 m/s^2 changes the velocity by 1e-3; a kink by ~1.
  EXPECT_LT(j.velocity, 5e-3);
  EXPECT_LT(j.angular_velocity, 2e-2);
  EXPECT_LT(j.position, 1e-9);
}

TEST(Dance, JointsStayUnderTheSpeedLimitAt140Bpm) {
  const Mannequin m = make_mannequin();
  const DanceSpec spec;
  const Dance d(m, spec, constant_tempo_beats(140, 25));
  const int n = m.skeleton.size();
  const double dt = 1e-3;
  SkeletonPose prev, now;
  d.pose(0, prev);
  double fastest = 0, fastest_root = 0;
  for (int step = 1; step <= 20000; ++step) {
    d.pose(step * dt, now);
    for (int j = 0; j < n; ++j)
      fastest = std::max(fastest, angle_between(prev.local[j], now.local[j]) / dt);
    fastest_root =
        std::max(fastest_root, angle_between(prev.root_rotation, now.root_rotation) / dt);
    prev = now;
  }
  std::printf("140 BPM: fastest joint %.2f rad/s, root turn %.2f rad/s\n", fastest, fastest_root);
  EXPECT_LE(fastest, spec.max_joint_speed);
  EXPECT_LE(fastest_root, spec.max_joint_speed);
  EXPECT_GT(fastest, 1.0);  // it does dance
}

TEST(Dance, VelocitiesAreTheDerivativeOfTheMotion) {
  const Mannequin m = make_mannequin();
  const Dance d(m, DanceSpec{}, constant_tempo_beats(128, 20));
  const double h = 1e-4;
  double worst = 0, fastest = 0;
  for (double t = 1.6; t < 12; t += 0.0731) {
    const Frames f = frames_at(d, t), a = frames_at(d, t - h), b = frames_at(d, t + h);
    for (int i = 0; i < d.primitive_count(); ++i) {
      const Vector3d v = (b[i].position - a[i].position) / (2 * h);
      const Quaterniond dq = b[i].rotation * a[i].rotation.conjugate();
      const Eigen::AngleAxisd aa(dq);
      const Vector3d w = aa.angle() * aa.axis() / (2 * h);
      const double scale = std::max({v.norm(), w.norm(), 0.1});
      worst = std::max(worst, (f[i].velocity - v).norm() / scale);
      worst = std::max(worst, (f[i].angular_velocity - w).norm() / scale);
      fastest = std::max(fastest, f[i].velocity.norm());
    }
  }
  std::printf("velocity vs finite difference: worst relative error %.2e (fastest %.2f m/s)\n",
              worst, fastest);
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(fastest, 0.5);
}

TEST(Dance, PelvisTurnsAFullCircleInEachLoop) {
  const Mannequin m = make_mannequin();
  const Dance d(m, DanceSpec{}, constant_tempo_beats(120, 20));
  const std::vector<double> keys = d.keyframe_times();
  ASSERT_GE(keys.size(), 17u);
  const int pelvis = 0;
  ASSERT_EQ(d.primitives()[pelvis].name, "pelvis");
  auto heading = [&](double t) {
    const Vector3d forward = frames_at(d, t)[pelvis].rotation * Vector3d::UnitZ();
    return std::atan2(forward.x(), forward.z());
  };
  double unwrapped = 0, previous = heading(keys[0]), lo = 0, hi = 0;
  for (double t = keys[0]; t <= keys[16]; t += 1e-3) {
    const double h = heading(t);
    unwrapped += std::remainder(h - previous, 2 * std::numbers::pi);
    previous = h;
    lo = std::min(lo, unwrapped);
    hi = std::max(hi, unwrapped);
  }
  std::printf("pelvis heading over one loop: %.3f rad in all, range %.3f\n", unwrapped, hi - lo);
  EXPECT_NEAR(std::abs(unwrapped), 2 * std::numbers::pi, 0.05);
  EXPECT_GT(hi - lo, 2 * std::numbers::pi - 0.2);
}

TEST(Dance, ChangingTempoStillLandsKeyframesAndStaysC1) {
  const Mannequin m = make_mannequin();
  const std::vector<double> beats = ramp_beats(110, 130, 20);
  const Dance d(m, DanceSpec{}, beats);
  const std::vector<double> keys = d.keyframe_times();
  ASSERT_GT(keys.size(), 30u);
  // The intervals really change: 60/110 s early, 60/130 s late.
  EXPECT_GT((keys[1] - keys[0]) - (keys.back() - keys[keys.size() - 2]), 0.06);
  double worst = 0;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    EXPECT_TRUE(std::binary_search(beats.begin(), beats.end(), keys[k]));
    SkeletonPose p;
    d.pose(keys[k], p);
    worst = std::max(worst, max_pose_difference(p, d.keyframe(k), m.skeleton.size()));
  }
  EXPECT_LT(worst, 1e-9);
  const Jumps j = jumps_at(d, keys);
  std::printf("C1 at 110->130 BPM: max jump |dv| %.2e m/s, |dw| %.2e rad/s\n", j.velocity,
              j.angular_velocity);
  EXPECT_LT(j.velocity, 5e-3);
  EXPECT_LT(j.angular_velocity, 2e-2);
  EXPECT_LT(j.position, 1e-9);
}

TEST(Dance, SolesStayOnTheFloor) {
  const Mannequin m = make_mannequin();
  double lo = INFINITY, hi = -INFINITY;
  for (const double bpm : {90.0, 120.0, 140.0}) {
    const Dance d(m, DanceSpec{}, constant_tempo_beats(bpm, 20));
    for (double t = 0; t < 20; t += 2e-3) {
      const double y = lowest_sole(d, t);
      lo = std::min(lo, y);
      hi = std::max(hi, y);
    }
  }
  std::printf("lowest sole corner over the dances: [%.4f, %.4f] m\n", lo, hi);
  EXPECT_GE(lo, -0.005);
  EXPECT_LE(hi, 0.03);
}

TEST(Dance, AmplitudeScalesTheDeviationFromRest) {
  const Mannequin m = make_mannequin();
  const std::vector<double> beats = constant_tempo_beats(120, 20);
  const int n = m.skeleton.size();
  // Zero amplitude, either way: the rest pose throughout.
  DanceSpec still;
  still.amplitude = 0;
  const Dance a(m, still, beats);
  const Dance b(m, DanceSpec{}, beats, std::vector<double>(beats.size(), 0.0));
  double worst = 0;
  for (double t = 0; t < 20; t += 0.013) {
    SkeletonPose pa, pb;
    a.pose(t, pa);
    b.pose(t, pb);
    worst = std::max(
        {worst, max_pose_difference(pa, a.rest(), n), max_pose_difference(pb, b.rest(), n)});
  }
  EXPECT_LT(worst, 1e-9);
  // Amplitude 0.4 scales every joint's angle from rest on the keyframes by 0.4 (slerp from rest).
  const Dance full(m, DanceSpec{}, beats);
  const Dance quiet(m, DanceSpec{}, beats, std::vector<double>(beats.size(), 0.4));
  double ratio_error = 0;
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < n; ++j) {
      const double af = angle_between(full.keyframe(k).local[j], full.rest().local[j]);
      const double ah = angle_between(quiet.keyframe(k).local[j], quiet.rest().local[j]);
      ratio_error = std::max(ratio_error, std::abs(ah - 0.4 * af));
    }
  EXPECT_LT(ratio_error, 1e-9);
  // ... and, under 0.5, skips the all-or-nothing turn.
  EXPECT_LT(angle_between(quiet.keyframe(10).root_rotation, Quaterniond::Identity()), 1e-9);
  EXPECT_GT(angle_between(full.keyframe(10).root_rotation, Quaterniond::Identity()), 3.0);
}

TEST(Dance, ArmsNeverEnterTheTorso) {
  // Cloth caught between an arm and the chest would be crushed: the choreography keeps arms out.
  const Mannequin m = make_mannequin();
  const Dance d(m, DanceSpec{}, constant_tempo_beats(120, 20));
  double closest = INFINITY;
  for (double t = 0; t < 20; t += 0.01) {
    const Frames f = frames_at(d, t);
    for (const int b : {0, 1}) {  // pelvis, chest
      for (int i = 0; i < d.primitive_count(); ++i) {
        const BodyPrimitive& p = d.primitives()[i];
        if (!p.name.ends_with("arm") && !p.name.ends_with("hand")) continue;
        // Sample the axis; the upper arm's shoulder end overlaps the chest at the joint.
        const double top = p.name.ends_with("upper_arm") ? 1 - p.radius / p.half_length : 1;
        for (double s = -1; s <= top; s += 0.05) {
          const Vector3d x = f[i].rotation * Vector3d(0, s * p.half_length, 0) + f[i].position;
          closest = std::min(closest, testing::box_distance(d.primitives()[b], f[b], x) - p.radius);
        }
      }
    }
  }
  std::printf("closest arm to torso: %.4f m\n", closest);
  EXPECT_GT(closest, -0.003);
}

TEST(Dance, BodyBoundsHoldEveryPrimitive) {
  const Mannequin m = make_mannequin();
  const Dance d(m, DanceSpec{}, constant_tempo_beats(120, 20));
  for (double t = 0; t < 20; t += 0.137) {
    const Eigen::AlignedBox3d box = d.body_bounds(t);
    const Frames f = frames_at(d, t);
    for (int i = 0; i < d.primitive_count(); ++i) {
      EXPECT_TRUE(box.contains(f[i].position)) << d.primitives()[i].name << " at " << t;
      EXPECT_TRUE(box.contains(primitive_bounds(d.primitives()[i], f[i])));
    }
    EXPECT_GT(box.sizes().y(), 1.4);
    EXPECT_LT(box.sizes().y(), 2.2);
  }
}

TEST(Dance, StatesDoNotAllocate) {
  const Mannequin m = make_mannequin();
  const Dance d(m, DanceSpec{}, constant_tempo_beats(120, 60));
  Frames f;
  const long before = g_allocations.load();
  const auto start = std::chrono::steady_clock::now();
  const int calls = 20000;
  for (int i = 0; i < calls; ++i) d.states(1.0 + i * 2e-3, f);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(g_allocations.load() - before, 0);
  std::printf("states(): %.2f us per call\n", 1e6 * seconds / calls);
}

TEST(Dance, RejectsBeatsThatDoNotIncrease) {
  const Mannequin m = make_mannequin();
  EXPECT_THROW(Dance(m, DanceSpec{}, {0.5, 1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(Dance(m, DanceSpec{}, {0.5, 1.0}, {1.0}), std::invalid_argument);
}

TEST(Dance, TooFewBeatsKeepTheRestPose) {
  const Mannequin m = make_mannequin();
  const Dance d(m, DanceSpec{}, {0.5, 1.0, 2.0, 2.5});  // no fourth beat after settling
  EXPECT_TRUE(d.keyframe_times().empty());
  SkeletonPose p;
  d.pose(10.0, p);
  EXPECT_LT(max_pose_difference(p, d.rest(), m.skeleton.size()), 1e-12);
}

}  // namespace
}  // namespace clothlab
