#include "apps/view/cloth_grab.hpp"

#include <cmath>
#include <cstdio>

#include "sim/solver.hpp"
#include "vis/passes/field_pass.hpp"
#include "vis/render/to_glm.hpp"
#include "vis/render/view_ray.hpp"

namespace clothlab::vis {
namespace {

Vec3d to_vec(glm::vec3 v) {
  return {double(v.x), double(v.y), double(v.z)};
}

}  // namespace

bool ClothGrab::pick(Solver& solver, const FrameFields& fields, const Renderer& renderer,
                     std::unique_ptr<FieldPass>& pass, const ViewSettings& view, int width,
                     int height, int window_w, int window_h) {
  if (!pending_ || width <= 0 || height <= 0 || window_w <= 0 || window_h <= 0) return false;
  const auto [x, y] = *pending_;
  pending_.reset();
  if (!pass || pass->width() != width || pass->height() != height)
    pass = std::make_unique<FieldPass>(width, height);
  // Cursor positions are in window points; the framebuffer may have more pixels.
  const int px = static_cast<int>(std::floor(x * width / window_w));
  const int py = static_cast<int>(std::floor(y * height / window_h));
  const std::optional<ProbeSample> s = probe_fields(
      solver, fields, renderer, *pass, view_projection(view.camera, width, height), px, py);
  if (!s || s->vertex < 0) return false;
  const glm::vec3 p = to_glm(solver.position(s->vertex));
  if (!solver.grab(s->vertex, to_vec(p))) return false;  // a pinned vertex stays where it is
  vertex_ = s->vertex;
  anchor_ = target_ = p;
  return true;
}

void ClothGrab::drag_to(Solver& solver, const OrbitCamera& camera, double x, double y, int window_w,
                        int window_h) {
  if (vertex_ < 0) return;
  target_ = point_on_view_plane(camera, window_w, window_h, x, y, anchor_);
  solver.grab(vertex_, to_vec(target_));
}

std::string ClothGrab::release(Solver& solver) {
  pending_.reset();
  if (vertex_ < 0) return {};
  solver.release_grab();
  const glm::vec3 now = to_glm(solver.position(vertex_));
  const float before = glm::length(anchor_ - target_), after = glm::length(now - target_);
  const VertexRef ref = solver.vertex_ref(vertex_);
  char line[200];
  std::snprintf(line, sizeof line,
                "released vertex %d (cloth %d, %d, %d): %.4f m from the target when grabbed, "
                "%.4f m at release (%s)",
                vertex_, ref.cloth, ref.i, ref.j, double(before), double(after),
                after < before ? "closer" : "not closer");
  vertex_ = -1;
  return line;
}

}  // namespace clothlab::vis
