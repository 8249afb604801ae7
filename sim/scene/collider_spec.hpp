// [[colliders]]: the solid shapes the cloth collides with (docs/design.md "Scene file",
// docs/contact.md section 1). Plain data; sim/contact/ builds the signed distances from it and vis/
// draws the same shapes.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace clothlab {

struct TriangleMesh;
class BodyMotion;

using Vec3d = std::array<double, 3>;

enum class ColliderKind { plane, sphere, box, capsule, mesh };

// A pose at a time, for keyframed motion: the collider's centre (plane: its point; capsule: the
// midpoint of a-b) moved by `offset` and turned by `rotation` (degrees about x, then y, then z,
// about the centre) at time `time` s.
struct ColliderKey {
  double time = 0.0;
  Vec3d offset{0.0, 0.0, 0.0};
  Vec3d rotation{0.0, 0.0, 0.0};
};

// Rigid motion: constant linear and angular velocity (about the collider's centre), or poses
// at keyframe times, interpolated linearly in between (offsets) and by slerp (rotations), held
// before the first and after the last.
struct ColliderMotion {
  Vec3d velocity{0.0, 0.0, 0.0};          // m/s
  Vec3d angular_velocity{0.0, 0.0, 0.0};  // rad/s, world axes
  std::vector<ColliderKey> keys;          // non-empty: keyframed (times increasing)
  bool moving() const {
    return !keys.empty() || velocity != Vec3d{0.0, 0.0, 0.0} ||
           angular_velocity != Vec3d{0.0, 0.0, 0.0};
  }
};

struct ColliderSpec {
  ColliderKind kind = ColliderKind::sphere;
  Vec3d point{0.0, 0.0, 0.0};                 // plane: a point on it
  Vec3d normal{0.0, 1.0, 0.0};                // plane: the side the cloth stays on
  Vec3d center{0.0, 0.5, 0.0};                // sphere, box
  double radius = 0.4;                        // sphere, capsule
  Vec3d half_extents{0.3, 0.3, 0.3};          // box
  Vec3d rotation{0.0, 0.0, 0.0};              // box: degrees about x, then y, then z
  double rounding = 0.0;                      // box: edge radius, inside the half extents
  Vec3d a{-0.5, 0.5, 0.0}, b{0.5, 0.5, 0.0};  // capsule: the ends of its axis
  std::string file;                          // mesh: OBJ path (relative to the scene file's folder)
  double scale = 1.0;                        // mesh: applied to the OBJ's coordinates
  int sdf_resolution = 64;                   // mesh: distance-grid cells along its longest side
  std::shared_ptr<const TriangleMesh> mesh;  // mesh: read by the load step (closed surface)
  double static_friction = 0.6;              // Coulomb: sticks while |v_t| <= mu_s dv_n
  double kinetic_friction = 0.4;             // Coulomb: sliding loses mu_k dv_n
  double thickness = 0.005;                  // m: the cloth stays this far outside
  ColliderMotion motion;
  // A primitive of the dancing mannequin (sim/body/body_motion.hpp): its pose at a time is the
  // body's part `body_part` (sphere, box or capsule sized as that part, in the part's frame;
  // `motion` and the placement keys above are not used).
  std::shared_ptr<const BodyMotion> body;
  int body_part = -1;
  std::string key;  // "colliders[2]", or "mannequin.pelvis", for messages
  bool moves() const { return body || motion.moving(); }
};

extern const std::array<std::pair<ColliderKind, const char*>, 5> kColliderKindNames;
const char* to_string(ColliderKind kind);

}  // namespace clothlab
