#include "vis/render/view_settings.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "sim/contact/collider.hpp"
#include "sim/scene/scene.hpp"
#include "sim/solver.hpp"
#include "vis/render/floor_collider.hpp"
#include "vis/render/to_glm.hpp"

namespace clothlab::vis {

glm::vec3 OrbitCamera::eye() const {
  const float yaw = glm::radians(yaw_deg), pitch = glm::radians(pitch_deg);
  const glm::vec3 dir{std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                      std::cos(pitch) * std::cos(yaw)};
  return target + distance * dir;
}

glm::mat4 OrbitCamera::view() const {
  return glm::lookAt(eye(), target, glm::vec3(0, 1, 0));
}

glm::mat4 OrbitCamera::projection(float aspect) const {
  const float near = std::max(0.01f, distance * 0.01f);
  const glm::mat4 lens = glm::translate(glm::mat4(1.0f), glm::vec3(lens_shift, 0.0f, 0.0f));
  return lens * glm::perspective(glm::radians(fov_deg), aspect, near, near * 10000.0f);
}

glm::mat4 view_projection(const OrbitCamera& camera, int width, int height) {
  const float aspect = height > 0 ? float(width) / float(height) : 1.0f;
  return camera.projection(aspect) * camera.view();
}

void OrbitCamera::orbit(float dyaw_deg, float dpitch_deg) {
  yaw_deg = std::fmod(yaw_deg + dyaw_deg, 360.0f);
  pitch_deg = std::clamp(pitch_deg + dpitch_deg, -89.0f, 89.0f);
}

void OrbitCamera::pan(float right, float up) {
  const glm::mat4 v = view();
  const glm::vec3 r{v[0][0], v[1][0], v[2][0]}, u{v[0][1], v[1][1], v[2][1]};
  target += right * r + up * u;
}

void OrbitCamera::zoom(float factor) {
  distance = std::clamp(distance * factor, 0.05f, 500.0f);
}

namespace {

// Camera, floor and light around the box lo..hi (what default_view frames).
void frame_box(ViewSettings& s, glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.25f, 0.5f * glm::length(hi - lo));
  s.floor_height = std::min(0.0f, lo.y - 0.5f * radius);
  s.camera.target = centre;
  // Far enough that the bounding sphere fills about 85 % of the view's height.
  s.camera.distance = radius / std::sin(glm::radians(0.5f * s.camera.fov_deg)) / 0.85f;
  s.light_position = centre + glm::vec3(0.6f * radius, 1.8f * radius, 1.4f * radius);
  // Irradiance of about 1 at the cloth, whatever its size.
  const float d = glm::length(s.light_position - centre);
  s.light_intensity = 1.2f * d * d;
  s.floor_half_size = std::max(30.0f, 15.0f * radius);  // out to near the horizon
  s.floor_tile_size = std::max(2.0f, 1.5f * radius);    // 4 x 4 stone tiles per repeat
}

void cloth_bounds(const SolverState& solver, glm::vec3& lo, glm::vec3& hi) {
  std::vector<float> xyz(3 * solver.vertex_count());
  solver.copy_positions(xyz.data());
  lo = glm::vec3(INFINITY);
  hi = glm::vec3(-INFINITY);
  for (std::size_t i = 0; i < solver.vertex_count(); ++i) {
    const glm::vec3 p{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
}

}  // namespace

float fabric_repeat_of(const ViewSettings& view) {
  return view.mode == DisplayMode::weave ? view.fabric_repeat / view.weave_coarsening
                                         : view.fabric_repeat;
}

ViewSettings default_view(const SolverState& solver) {
  ViewSettings s;
  glm::vec3 lo, hi;
  cloth_bounds(solver, lo, hi);
  frame_box(s, lo, hi);
  return s;
}

ViewSettings scene_view(const Scene& scene, const SolverState& solver) {
  ViewSettings s = default_view(solver);
  // The cloth lands on its colliders: frame them too (where they are at t = 0; planes have no
  // bounds and are left out).
  glm::vec3 lo, hi;
  cloth_bounds(solver, lo, hi);
  bool grown = false;
  for (const ColliderSpec& spec : scene.colliders) {
    if (spec.kind == ColliderKind::plane) continue;
    const Collider c = pose_only_collider(spec);
    const clothlab::Bounds b = c.bounds(c.pose(0.0), 0.0);
    lo = glm::min(lo, glm::vec3(float(b.lo.x()), float(b.lo.y()), float(b.lo.z())));
    hi = glm::max(hi, glm::vec3(float(b.hi.x()), float(b.hi.y()), float(b.hi.z())));
    grown = true;
  }
  if (grown) frame_box(s, lo, hi);
  // A ground plane collider is the floor: the cloth must be seen landing on the floor it hits.
  if (const auto floor = floor_collider(scene.colliders))
    s.floor_height = static_cast<float>(scene.colliders[*floor].point[1]);
  const RenderSpec& r = scene.render;
  // The scene's own camera, where it gives one.
  if (r.camera.target) s.camera.target = to_glm(*r.camera.target);
  if (r.camera.yaw) s.camera.yaw_deg = static_cast<float>(*r.camera.yaw);
  if (r.camera.pitch) s.camera.pitch_deg = static_cast<float>(*r.camera.pitch);
  if (r.camera.distance) s.camera.distance = static_cast<float>(*r.camera.distance);
  s.mode = static_cast<DisplayMode>(r.mode);
  s.shadows = r.shadows;
  s.quality = r.quality;
  s.window_scale = static_cast<float>(r.window_scale);
  s.shadow_map_size = r.shadow_map_size;
  s.sky = r.sky.enabled;
  s.sky_turbidity = static_cast<float>(r.sky.turbidity);
  s.look = r.cloth;
  const LightSpec& l = r.light;
  s.light_type = l.type;
  s.light_color = to_glm(l.color);
  s.light_size = static_cast<float>(l.size);
  s.light_direction = to_glm(l.direction);
  if (l.position) s.light_position = to_glm(*l.position);
  if (l.target) s.light_target = to_glm(*l.target);
  if (l.type == LightType::directional) {
    s.light_intensity = static_cast<float>(l.intensity);
  } else {
    // Irradiance `intensity` at the cloth's centre (the camera's target), whatever the distance.
    const float d =
        glm::length(s.light_position - (s.light_target ? *s.light_target : s.camera.target));
    s.light_intensity = static_cast<float>(l.intensity) * d * d;
  }
  return s;
}

}  // namespace clothlab::vis
