#include "vis/render/collider_scenery.hpp"

#include <algorithm>
#include <cmath>

#include "sim/solver.hpp"
#include "vis/meshes/mesh.hpp"
#include "vis/meshes/obj_mesh.hpp"
#include "vis/meshes/shapes.hpp"
#include "vis/passes/shadow_pass.hpp"
#include "vis/render/floor_collider.hpp"

namespace clothlab::vis {
namespace {

// Tessellation: fine enough that the drawn silhouette stays within about 0.1 % of the radius of
// the surface the cloth rests on (a coarser sphere would show the cloth floating over its
// flat facets' middles or sinking through their corners).
constexpr int kSlices = 64, kStacks = 32, kCapStacks = 16, kRoundingSegments = 6;
constexpr float kMinPlaneHalfSize = 3.0f;  // m
constexpr float kPlaneHalfSizePerCloth = 3.0f;

// A square of half size `half` in the local y = 0 plane about (cx, 0, cz), both faces: the top
// one (normal +y) and, with the opposite winding, the bottom one (normal -y), so back-face culling
// shows whichever side the camera is on, lit from that side.
Mesh make_plane_quad(float half, float cx, float cz) {
  Mesh mesh;
  const float corners[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};  // CCW seen from +y
  for (float side : {1.0f, -1.0f}) {
    const auto base = std::uint32_t(mesh.positions.size());
    for (const auto& c : corners) {
      mesh.positions.emplace_back(cx + half * c[0], 0.0f, cz + half * c[1]);
      mesh.normals.emplace_back(0.0f, side, 0.0f);
      mesh.uvs.emplace_back(0.5f * (c[0] + 1.0f), 0.5f * (c[1] + 1.0f));
    }
    const std::uint32_t top[6] = {0, 1, 2, 0, 2, 3}, bottom[6] = {0, 2, 1, 0, 3, 2};
    for (std::uint32_t i : side > 0.0f ? top : bottom) mesh.indices.push_back(base + i);
  }
  return mesh;
}

// The collider's shape in its own frame (sim/contact/collider.hpp: the plane is local y = 0 with
// its normal +y, the capsule's axis runs along local y).
Mesh collider_mesh(const ColliderSpec& c, float plane_half, glm::vec2 plane_centre) {
  const auto f = [](double v) { return static_cast<float>(v); };
  switch (c.kind) {
    case ColliderKind::plane:
      return make_plane_quad(plane_half, plane_centre.x, plane_centre.y);
    case ColliderKind::sphere:
      return make_uv_sphere(f(c.radius), kSlices, kStacks);
    case ColliderKind::box: {
      const glm::vec3 h(f(c.half_extents[0]), f(c.half_extents[1]), f(c.half_extents[2]));
      return c.rounding > 0.0 ? make_rounded_box(h, f(c.rounding), kRoundingSegments) : make_box(h);
    }
    case ColliderKind::capsule: {
      double len2 = 0.0;
      for (int k = 0; k < 3; ++k) len2 += (c.b[k] - c.a[k]) * (c.b[k] - c.a[k]);
      return make_capsule(f(c.radius), 0.5f * f(std::sqrt(len2)), kSlices, kCapStacks);
    }
    case ColliderKind::mesh:
      return c.mesh ? make_obj_mesh(*c.mesh, false) : Mesh{};  // crisp edges
  }
  return Mesh{};
}

glm::mat4 model_matrix(const ColliderPose& pose) {
  glm::mat4 m(1.0f);
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) m[col][row] = static_cast<float>(pose.rotation(row, col));
  for (int row = 0; row < 3; ++row) m[3][row] = static_cast<float>(pose.centre[row]);
  return m;
}

}  // namespace

void ColliderScenery::set_colliders(const std::vector<ColliderSpec>& colliders,
                                    const Solver& solver) {
  objects_.clear();
  // The cloth at rest: planes are drawn around the point under its centre, as large as a few
  // cloths (a finite stand-in for an infinite plane that still fits the depth range).
  std::vector<float> rest(3 * solver.vertex_count());
  solver.copy_rest_positions(rest.data());
  glm::vec3 lo(0.0f), hi(0.0f);
  for (std::size_t v = 0; v < solver.vertex_count(); ++v) {
    const glm::vec3 p(rest[3 * v], rest[3 * v + 1], rest[3 * v + 2]);
    lo = v == 0 ? p : glm::min(lo, p);
    hi = v == 0 ? p : glm::max(hi, p);
  }
  const glm::vec3 cloth_centre = 0.5f * (lo + hi);
  const float plane_half =
      std::max(kMinPlaneHalfSize, kPlaneHalfSizePerCloth * glm::length(hi - lo));

  const std::optional<std::size_t> floor = floor_collider(colliders);
  for (std::size_t i = 0; i < colliders.size(); ++i) {
    if (floor && *floor == i) continue;  // drawn as the floor
    Collider collider = pose_only_collider(colliders[i]);
    const Eigen::Vector3d local = collider.pose(0.0).to_local(
        Eigen::Vector3d(cloth_centre.x, cloth_centre.y, cloth_centre.z));
    const Mesh mesh = collider_mesh(colliders[i], plane_half,
                                    {static_cast<float>(local.x()), static_cast<float>(local.z())});
    const Bounds b = mesh_bounds(mesh);
    objects_.push_back({std::move(collider), upload_mesh(mesh), b.min, b.max,
                        colliders[i].kind == ColliderKind::plane, glm::mat4(1.0f)});
  }
  update(solver.time());
}

void ColliderScenery::update(double t) {
  bounded_ = false;
  for (Object& o : objects_) {
    o.model = model_matrix(o.collider.pose(t));
    if (o.plane) continue;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 local(corner & 1 ? o.local_hi.x : o.local_lo.x,
                            corner & 2 ? o.local_hi.y : o.local_lo.y,
                            corner & 4 ? o.local_hi.z : o.local_lo.z);
      const glm::vec3 w = glm::vec3(o.model * glm::vec4(local, 1.0f));
      lo_ = bounded_ ? glm::min(lo_, w) : w;
      hi_ = bounded_ ? glm::max(hi_, w) : w;
      bounded_ = true;
    }
  }
}

void ColliderScenery::draw(const std::string& shading) {
  if (objects_.empty()) return;
  pass_.begin(shading);
  for (const Object& o : objects_) pass_.draw(o.mesh, o.model, kColliderColor);
  pass_.end();
}

void ColliderScenery::draw_shadow(ShadowPass& pass) const {
  for (const Object& o : objects_) pass.draw_triangles(o.mesh.vao.get(), o.mesh.indices, o.model);
}

}  // namespace clothlab::vis
