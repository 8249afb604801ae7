#include "vis/render/view_ray.hpp"

#include <cmath>

namespace clothlab::vis {

glm::vec3 point_on_view_plane(const OrbitCamera& camera, int width, int height, double x, double y,
                              glm::vec3 anchor) {
  if (width <= 0 || height <= 0) return anchor;
  // The cursor's ray: unproject its pixel at two depths (the same matrix every
  // pass draws with, so the point lands back under the same pixel).
  const glm::mat4 inverse = glm::inverse(view_projection(camera, width, height));
  const float nx = static_cast<float>(2.0 * x / width - 1.0);
  const float ny = static_cast<float>(1.0 - 2.0 * y / height);
  const glm::vec4 near = inverse * glm::vec4(nx, ny, -1.0f, 1.0f);
  const glm::vec4 far = inverse * glm::vec4(nx, ny, 0.0f, 1.0f);  // NDC 0: about 2x near
  const glm::vec3 origin = glm::vec3(near) / near.w;
  const glm::vec3 dir = glm::normalize(glm::vec3(far) / far.w - origin);
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye());
  const float along = glm::dot(dir, forward);  // > 0 for every ray inside the frustum
  if (!(std::abs(along) > 1e-6f)) return anchor;
  return origin + dir * (glm::dot(anchor - origin, forward) / along);
}

}  // namespace clothlab::vis
