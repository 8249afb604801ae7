#include "vis/textures/planar_uv.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

namespace clothlab::vis {

glm::vec2 planar_uvs(const float* rest, int first, int last, float* uv) {
  glm::vec3 lo(0.0f), hi(0.0f);
  for (int v = first; v < last; ++v) {
    const glm::vec3 p(rest[3 * std::size_t(v)], rest[3 * std::size_t(v) + 1],
                      rest[3 * std::size_t(v) + 2]);
    lo = v == first ? p : glm::min(lo, p);
    hi = v == first ? p : glm::max(hi, p);
  }
  const glm::vec3 extent = hi - lo;
  std::array<int, 3> axes{0, 1, 2};
  std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return extent[a] > extent[b]; });
  const float span = std::max(extent[axes[0]], 1e-6f);
  for (int v = first; v < last; ++v) {
    const float* p = rest + 3 * std::size_t(v);
    uv[2 * std::size_t(v)] = (p[axes[0]] - lo[axes[0]]) / span;
    uv[2 * std::size_t(v) + 1] = (p[axes[1]] - lo[axes[1]]) / span;
  }
  return {span, span};
}

}  // namespace clothlab::vis
