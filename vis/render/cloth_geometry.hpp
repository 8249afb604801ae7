// The cloth on the GPU for drawing: its vertex buffers (what changes every frame: positions,
// then normals; what does not: UVs, rest positions, the atlas place), the triangle and spring
// line indices, the colour-by scalars and the tangent frame, and the vertex arrays over them.
// Filled from the solver's CPU arrays, or with the GPU backend from its device buffers by a
// compute pass (shaders/cloth_pack.comp) without a trip through the CPU. Needs a current GL 4.5
// context.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "gl/objects.hpp"
#include "vis/passes/cloth_pack_pass.hpp"
#include "vis/render/cloth_detail.hpp"
#include "vis/render/cloth_layout.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
class DeviceCloth;
class SolverState;
struct FrameFields;
}  // namespace clothlab

namespace clothlab::vis {

// Mode 1's automatic strain range: a robust top, so a few springs at the pins do not leave the
// rest of the sheet grey; never below kMinStrainRange (a sheet at rest is not all saturated).
inline constexpr double kStrainRangeQuantile = 0.8;
inline constexpr float kMinStrainRange = 1e-4f;

class ClothGeometry {
 public:
  // (Re)builds every buffer for `solver`'s cloths (after building or resizing the solver).
  void build(const SolverState& solver);
  // The snapshot's positions and smooth normals into the vertex buffer, in place (or, with a
  // device cloth, packed from its buffers on the GPU), the box around the positions (the
  // light's frustum follows the cloth) and, when the snapshot holds the springs' strain, its
  // strain_top().
  void update(const FrameFields& fields);
  // The colour-by scalar, one per solver vertex.
  void set_scalars(const std::vector<float>& values);
  // The kStrainRangeQuantile quantile of |strain| over the springs of the last update() whose
  // snapshot held their strain (kMinStrainRange before any), at least kMinStrainRange: mode 1's
  // automatic colour range. Springs are sampled (at most about 4096) so a large cloth pays
  // little.
  float strain_top() const { return strain_top_; }
  // The tangent frame of the last update(), computed only when a mode needs it.
  void update_tangents();

  GLuint cloth_vao() const { return cloth_vao_.get(); }
  GLuint line_vao() const { return line_vao_.get(); }
  // Every triangle (the probe's field pass, translucency's diffusion and the checks for a
  // surface draw them all).
  GLsizei triangle_indices() const { return triangle_indices_; }
  // The triangles the cloth and its shadow are drawn with: every one, or a coarser level of a
  // large grid cloth (cloth_detail.hpp) chosen by set_detail; `first` indexes the element buffer.
  struct Drawn {
    GLsizei count = 0;
    std::size_t first = 0;
    int stride = 1;
  };
  const Drawn& drawn() const { return drawn_; }
  // Draws the coarsest level whose cells cover at most kDetailCellPixels when a metre at the
  // cloth's nearest point covers pixels_per_metre pixels; 0 (or less) draws every triangle.
  void set_detail(double pixels_per_metre);
  GLsizei line_indices() const { return line_indices_; }
  // The buffer the positions are drawn from and its stride (bytes): the vertex buffer's, or the
  // transform-feedback backend's captured buffer (vec4 per vertex) while flat_normals().
  GLuint position_buffer() const { return position_buffer_; }
  GLsizei position_stride() const { return position_stride_; }
  // True while the positions are drawn straight from a device cloth that leaves the normals to
  // the renderer's geometry shader (shaders/cloth_flat.geom).
  bool flat_normals() const { return position_buffer_ != dynamic_vbo_.get(); }
  GLuint triangle_buffer() const { return triangle_ebo_.get(); }
  std::size_t vertex_count() const { return layout_.vertices; }
  std::size_t render_vertex_count() const { return layout_.render_vertices(); }
  const std::vector<int>& seam_copies() const { return layout_.seam_copies; }
  glm::vec2 atlas_per_metre() const { return layout_.atlas_per_metre; }
  glm::vec3 lo() const { return lo_; }
  glm::vec3 hi() const { return hi_; }

 private:
  void make_vertex_arrays();
  void draw_positions_from(GLuint buffer, GLsizei stride);
  void update_bounds();
  void update_strain_top(const std::vector<float>& spring_strain);
  void copy_seams(float* values, std::size_t stride, std::size_t offset) const;

  ClothLayout layout_;
  Buffer dynamic_vbo_, static_vbo_, triangle_ebo_, line_ebo_;
  Buffer scalar_vbo_;   // the colour-by scalar per render vertex
  Buffer tangent_vbo_;  // modes 4-6: per-vertex tangent frame (xyz, handedness)
  VertexArray cloth_vao_, line_vao_;
  GLsizei triangle_indices_ = 0, line_indices_ = 0;
  ClothDetail detail_;  // coarse levels after the triangles in triangle_ebo_
  Drawn drawn_;
  std::vector<float> staging_;         // positions, then normals, per render vertex
  std::vector<float> scalar_staging_;  // the colour-by scalar per render vertex
  std::vector<float> tangents_, tangent_scratch_;
  std::vector<float> strains_;  // strain_top's sample
  float strain_top_ = kMinStrainRange;
  bool tangents_stale_ = true;
  glm::vec3 lo_{0.0f}, hi_{0.0f};
  // The GPU backend's cloth the last update() packed from (the tangents read its normals back
  // only when a mode needs them), else null.
  const DeviceCloth* device_ = nullptr;
  ClothPackPass pack_;          // the GPU backend's buffers into dynamic_vbo_
  GLuint position_buffer_ = 0;  // dynamic_vbo_, or the device cloth's captured buffer
  GLsizei position_stride_ = 0;
};

}  // namespace clothlab::vis
