// The field pass behind probes: draws the cloth once more, with the main pass's geometry and
// camera, into single-sample float targets (force, velocity, world position) and a triangle id,
// so one pixel can be read back as raw SI values rather than colours. Only built and drawn when
// something probes (docs/design.md: no field export unless something displays, probes or traces
// it).
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "gl/objects.hpp"

namespace clothlab {
class SolverState;
struct FrameFields;
}  // namespace clothlab

namespace clothlab::vis {

class Renderer;

enum class Field { force, velocity, position };

// What lies under one pixel: the fields interpolated linearly over the front-most triangle at
// the pixel's centre, that triangle (an index into Solver::triangles()) and, filled in by the
// caller, the triangle's vertex nearest to `position`.
struct ProbeSample {
  glm::vec3 force{0.0f};     // N
  glm::vec3 velocity{0.0f};  // m/s
  glm::vec3 position{0.0f};  // m
  int triangle = -1;
  int vertex = -1;
  glm::vec3 value(Field f) const {
    return f == Field::force ? force : f == Field::velocity ? velocity : position;
  }
};

class FieldPass {
 public:
  FieldPass(int width, int height);

  // Draws `renderer`'s cloth (positions from its last update_cloth()) with per-vertex force and
  // velocity (3 floats per vertex each, renderer.vertex_count() solver vertices; a tube's seam
  // copies get their solver vertex's).
  void draw(const Renderer& renderer, const std::vector<float>& force,
            const std::vector<float>& velocity, const glm::mat4& view_proj);
  // The sample under pixel (px, py) of the last draw, row 0 at the top; nothing where no cloth
  // covers the pixel's centre.
  std::optional<ProbeSample> read(int px, int py) const;

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  Framebuffer fbo_;
  Renderbuffer force_, velocity_, world_, triangle_, depth_;
  Program program_;
  VertexArray vao_;
  Buffer field_vbo_;  // force for every render vertex, then velocity
  std::size_t field_vertices_ = 0;
  std::vector<float> copy_scratch_;  // the seam copies' force, then velocity
};

// The one probe both the headless renderer and the window use: uploads the snapshot's total force
// and velocities (`fields` taken for frame_request(view, renderer, true), so nothing pays for
// them unless something probes), draws `pass` with `renderer`'s cloth (positions from its last
// update_cloth(), which the caller does with the same snapshot), reads pixel (px, py) (row 0 at
// the top) and names the triangle's vertex nearest to the surface point there. Nothing where the
// pixel misses the cloth or lies outside the pass. Leaves the pass's framebuffer bound.
std::optional<ProbeSample> probe_fields(const SolverState& solver, const FrameFields& fields,
                                        const Renderer& renderer, FieldPass& pass,
                                        const glm::mat4& view_proj, int px, int py);

}  // namespace clothlab::vis
