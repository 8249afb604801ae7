#include "vis/render/headless_renderer.hpp"

#include <cmath>

#include "sim/solver.hpp"

namespace clothlab::vis {

HeadlessRenderer::HeadlessRenderer(int width, int height) : target_(width, height) {}

std::vector<std::uint8_t> HeadlessRenderer::render(Solver& solver, const ViewSettings& view) {
  renderer_.update_cloth(solver);
  target_.bind();
  renderer_.draw(view, target_.width(), target_.height());
  return target_.read_rgba();
}

std::optional<ProbeSample> HeadlessRenderer::probe(Solver& solver, const ViewSettings& view, int px,
                                                   int py) {
  if (px < 0 || py < 0 || px >= width() || py >= height()) return std::nullopt;
  if (!fields_) fields_ = std::make_unique<FieldPass>(width(), height());
  const std::size_t n = solver.vertex_count();
  std::vector<float> force(3 * n), velocity(3 * n);
  solver.update_force_field();  // the only caller on this path: a plain render never pays
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3d f = solver.force(static_cast<int>(v));
    for (int k = 0; k < 3; ++k) force[3 * v + k] = static_cast<float>(f[k]);
  }
  solver.copy_velocities(velocity.data());
  renderer_.update_cloth(solver);
  fields_->draw(renderer_, force, velocity, view_projection(view.camera, width(), height()));
  std::optional<ProbeSample> s = fields_->read(px, py);
  if (!s) return s;
  // The triangle's vertex nearest to the surface point under the pixel, measured in double.
  double best = INFINITY;
  for (int v : solver.triangles().at(static_cast<std::size_t>(s->triangle))) {
    const Vec3d p = solver.position(v);
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) d2 += (p[k] - s->position[k]) * (p[k] - s->position[k]);
    if (d2 < best) best = d2, s->vertex = v;
  }
  return s;
}

}  // namespace clothlab::vis
