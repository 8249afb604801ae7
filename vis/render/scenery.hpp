// The scene's solid objects besides the cloth and the floor: the pole the cloth's pinned vertices
// hang from and the [[render.meshes]] (sphere, box, torus knot). Drawn lit and shadowed in every
// shaded mode, and into the shadow map as casters.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gl/objects.hpp"
#include "sim/scene/render_spec.hpp"
#include "vis/passes/object_pass.hpp"
#include "vis/render/gpu_mesh.hpp"

namespace clothlab {
class SolverState;
}

namespace clothlab::vis {

class ShadowPass;
struct Mesh;

class Scenery {
 public:
  // Builds the pole (from the solver's pinned vertices at rest, when at least two of a cloth's
  // pins lie on a line) and the meshes of `spec`.
  void set_scene(const RenderSpec& spec, const SolverState& solver);
  // Main pass (the Frame block and the shadow map bound).
  void draw(const std::string& shading);  // lit by ShadingVariant::defines()
  void draw_shadow(ShadowPass& pass) const;

  bool empty() const { return objects_.empty(); }
  // World-space bounds of all objects (valid when not empty).
  glm::vec3 lo() const { return lo_; }
  glm::vec3 hi() const { return hi_; }
  std::size_t object_count() const { return objects_.size(); }

 private:
  struct Object {
    GpuMesh mesh;
    glm::mat4 model{1.0f};
    glm::vec3 color{0.8f};  // sRGB albedo
  };
  void add(const Mesh& mesh, const glm::mat4& model, glm::vec3 color);

  ObjectPass pass_;
  std::vector<Object> objects_;
  glm::vec3 lo_{0.0f}, hi_{0.0f};
};

}  // namespace clothlab::vis
