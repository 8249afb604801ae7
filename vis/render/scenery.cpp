#include "vis/render/scenery.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "sim/solver.hpp"
#include "vis/meshes/mesh.hpp"
#include "vis/meshes/obj_mesh.hpp"
#include "vis/meshes/shapes.hpp"
#include "vis/passes/shadow_pass.hpp"
#include "vis/render/gpu_mesh.hpp"
#include "vis/render/to_glm.hpp"

namespace clothlab::vis {
namespace {

const glm::vec3 kPoleColor{0.42f, 0.30f, 0.20f};  // sRGB: oiled wood
constexpr float kPoleOverhang = 0.06f;            // of the pinned span, beyond each end pin
constexpr float kCollinear = 0.02f;               // pins this far (of the span) off the line

// The rotation taking +x to unit d.
glm::mat4 rotate_x_to(glm::vec3 d) {
  const glm::vec3 x(1.0f, 0.0f, 0.0f);
  const glm::vec3 axis = glm::cross(x, d);
  const float s = glm::length(axis), c = glm::dot(x, d);
  if (s < 1e-6f)
    return c > 0.0f ? glm::mat4(1.0f)
                    : glm::rotate(glm::mat4(1.0f), glm::pi<float>(), glm::vec3(0, 1, 0));
  return glm::rotate(glm::mat4(1.0f), std::atan2(s, c), axis / s);
}

}  // namespace

void Scenery::add(const Mesh& mesh, const glm::mat4& model, glm::vec3 color) {
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::vec3 w = glm::vec3(model * glm::vec4(mesh.positions[v], 1.0f));
    lo_ = objects_.empty() && v == 0 ? w : glm::min(lo_, w);
    hi_ = objects_.empty() && v == 0 ? w : glm::max(hi_, w);
  }
  objects_.push_back({upload_mesh(mesh), model, color});
}

void Scenery::set_scene(const RenderSpec& spec, const SolverState& solver) {
  objects_.clear();
  if (spec.pole.enabled) {
    std::vector<float> rest(3 * solver.vertex_count());
    solver.copy_rest_positions(rest.data());
    auto at = [&](int v) {
      return glm::vec3(rest[3 * std::size_t(v)], rest[3 * std::size_t(v) + 1],
                       rest[3 * std::size_t(v) + 2]);
    };
    const float r = static_cast<float>(spec.pole.radius);
    for (const ClothRange& c : solver.cloths()) {
      std::vector<glm::vec3> pins;
      for (int v = c.offset; v < c.offset + c.nu * c.nv; ++v)
        if (solver.pinned(v)) pins.push_back(at(v));
      if (pins.size() < 2) continue;
      // The two pins farthest apart span the pole; every pin must lie on that line.
      glm::vec3 a = pins[0], b = pins[1];
      for (const glm::vec3& p : pins)
        for (const glm::vec3& q : pins)
          if (glm::length(p - q) > glm::length(a - b)) a = p, b = q;
      const float span = glm::length(b - a);
      if (span < 1e-4f) continue;
      const glm::vec3 d = (b - a) / span;
      const bool line = std::all_of(pins.begin(), pins.end(), [&](const glm::vec3& p) {
        return glm::length(glm::cross(p - a, d)) <= kCollinear * span;
      });
      if (!line) continue;  // e.g. a tablecloth's corners: no single pole holds them
      const float length = span * (1.0f + 2.0f * kPoleOverhang);
      // The cloth hangs below the pole: its axis one radius above the pins.
      const glm::vec3 start = a - d * (kPoleOverhang * span) + glm::vec3(0.0f, r, 0.0f);
      add(make_cylinder(r, length, 24, true),
          glm::translate(glm::mat4(1.0f), start) * rotate_x_to(d), kPoleColor);
    }
  }
  for (const MeshSpec& m : spec.meshes) {
    const glm::vec3 rot = to_glm(m.rotation);
    // Degrees about x, then y, then z: R = Rz Ry Rx.
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), to_glm(m.center)) *
                            glm::rotate(glm::mat4(1.0f), glm::radians(rot.z), {0, 0, 1}) *
                            glm::rotate(glm::mat4(1.0f), glm::radians(rot.y), {0, 1, 0}) *
                            glm::rotate(glm::mat4(1.0f), glm::radians(rot.x), {1, 0, 0});
    const float r = static_cast<float>(m.radius);
    switch (m.kind) {
      case MeshKind::sphere:
        add(make_uv_sphere(r, 48, 24), model, to_glm(m.color));
        break;
      case MeshKind::box:
        add(make_box(to_glm(m.half_extents)), model, to_glm(m.color));
        break;
      case MeshKind::torus_knot:
        // A (2, 3) trefoil: overall radius r, tube 0.14 r.
        add(make_torus_knot(2, 3, 0.72f * r, 0.14f * r, 256, 16), model, to_glm(m.color));
        break;
      case MeshKind::obj:
        if (m.obj) add(make_obj_mesh(*m.obj, m.smooth), model, to_glm(m.color));
        break;
    }
  }
}

void Scenery::draw(const std::string& shading) {
  if (objects_.empty()) return;
  pass_.begin(shading);
  for (const Object& o : objects_) pass_.draw(o.mesh, o.model, o.color);
  pass_.end();
}

void Scenery::draw_shadow(ShadowPass& pass) const {
  for (const Object& o : objects_) pass.draw_triangles(o.mesh.vao.get(), o.mesh.indices, o.model);
}

}  // namespace clothlab::vis
