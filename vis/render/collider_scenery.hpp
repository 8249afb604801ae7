// The scene's [[colliders]] drawn with the shapes the cloth collides with (docs/contact.md section
// 1): sphere, box (rotated; rounded edges where it has rounding), capsule, and planes other than
// the floor (floor_collider.hpp) as a large two-sided quad. Lit and shadowed like the other scenery
// in every shaded mode and drawn into the shadow map as casters (so also into mode 7's depth
// view). Moving colliders follow the solver's clock: update() poses every shape at a time.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gl/objects.hpp"
#include "sim/contact/collider.hpp"
#include "sim/scene/collider_spec.hpp"
#include "vis/passes/object_pass.hpp"
#include "vis/render/gpu_mesh.hpp"

namespace clothlab {
class Solver;
}

namespace clothlab::vis {

class ShadowPass;

// Colliders carry no colour in the scene: one neutral grey (sRGB), apart from cloth and floor.
inline constexpr glm::vec3 kColliderColor{0.7f, 0.7f, 0.72f};

class ColliderScenery {
 public:
  // Builds one mesh per collider but the floor plane. Planes get a quad of half size
  // max(3 m, 3 x the cloth's rest diagonal) about their point. Then poses them at solver.time().
  void set_colliders(const std::vector<ColliderSpec>& colliders, const Solver& solver);
  // Model matrices and bounds at time t (s); allocates nothing (every frame).
  void update(double t);
  // Main pass (the Frame block and the shadow map bound).
  void draw(const std::string& shading);  // lit by ShadingVariant::defines()
  void draw_shadow(ShadowPass& pass) const;

  std::size_t object_count() const { return objects_.size(); }
  // World bounds of the bounded shapes (planes left out: the light frames what casts onto the
  // floor), valid when has_bounds().
  bool has_bounds() const { return bounded_; }
  glm::vec3 lo() const { return lo_; }
  glm::vec3 hi() const { return hi_; }
  // The model matrix of collider object k (in the order of the specs, floor left out).
  const glm::mat4& model(std::size_t k) const { return objects_[k].model; }

 private:
  struct Object {
    Collider collider;
    GpuMesh mesh;
    glm::vec3 local_lo{0.0f}, local_hi{0.0f};  // the mesh's box in the collider's frame
    bool plane = false;
    glm::mat4 model{1.0f};
  };

  ObjectPass pass_;
  std::vector<Object> objects_;
  bool bounded_ = false;
  glm::vec3 lo_{0.0f}, hi_{0.0f};
};

}  // namespace clothlab::vis
