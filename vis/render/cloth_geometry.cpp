#include "vis/render/cloth_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "gl/program.hpp"
#include "gl/uploads.hpp"
#include "sim/fields/frame_fields.hpp"
#include "sim/solver.hpp"
#include "sim/step_backend.hpp"
#include "vis/render/quantile.hpp"
#include "vis/textures/cloth_tangents.hpp"

namespace clothlab::vis {

void ClothGeometry::build(const SolverState& solver) {
  layout_ = make_cloth_layout(solver);
  const std::size_t rn = layout_.render_vertices();
  triangle_indices_ = static_cast<GLsizei>(layout_.triangles.size());
  line_indices_ = static_cast<GLsizei>(layout_.lines.size());
  dynamic_vbo_ = dynamic_float_buffer(6 * rn);
  pack_.set_seams(layout_.seam_copies);
  static_vbo_ = static_buffer(layout_.fixed);
  scalar_vbo_ = dynamic_float_buffer(rn);
  tangent_vbo_ = dynamic_float_buffer(4 * rn);
  detail_ = make_cloth_detail(layout_);
  std::vector<std::uint32_t> elements = layout_.triangles;
  elements.insert(elements.end(), detail_.indices.begin(), detail_.indices.end());
  triangle_ebo_ = static_buffer(elements);
  drawn_ = {triangle_indices_, 0, 1};
  line_ebo_ = static_buffer(layout_.lines);
  tangents_.assign(4 * rn, 0.0f);
  tangents_stale_ = true;
  strain_top_ = kMinStrainRange;
  make_vertex_arrays();
  draw_positions_from(dynamic_vbo_.get(), 3 * sizeof(float));
  staging_.resize(6 * rn);
  scalar_staging_.resize(rn);
}

void ClothGeometry::set_detail(double pixels_per_metre) {
  drawn_ = {triangle_indices_, 0, 1};
  if (!(pixels_per_metre > 0.0)) return;
  const int stride = detail_stride(detail_, pixels_per_metre);
  for (const DetailLevel& level : detail_.levels)
    if (level.stride == stride)
      drawn_ = {static_cast<GLsizei>(level.count), layout_.triangles.size() + level.first, stride};
}

// Two vertex arrays over the same vertex buffers: triangles and spring lines. Attributes:
// 0 position, 1 normal, 2 uv, 3 rest position (both); 4 scalar, 5 tangent, 6 atlas place
// (triangles).
void ClothGeometry::make_vertex_arrays() {
  const std::size_t rn = layout_.render_vertices();
  cloth_vao_ = make_vertex_array();
  line_vao_ = make_vertex_array();
  const std::size_t f = sizeof(float);
  for (GLuint vao : {cloth_vao_.get(), line_vao_.get()}) {
    vertex_buffer(vao, 0, dynamic_vbo_.get(), 0, 3 * f);
    vertex_buffer(vao, 1, dynamic_vbo_.get(), 3 * rn * f, 3 * f);
    vertex_buffer(vao, 2, static_vbo_.get(), 0, 2 * f);
    vertex_buffer(vao, 3, static_vbo_.get(), 2 * rn * f, 3 * f);
    for (GLuint a = 0; a < 4; ++a) float_attribute(vao, a, a, a == 2 ? 2 : 3);
  }
  const GLuint vao = cloth_vao_.get();
  vertex_buffer(vao, 4, scalar_vbo_.get(), 0, f);
  float_attribute(vao, 4, 4, 1);
  vertex_buffer(vao, 5, tangent_vbo_.get(), 0, 4 * f);
  float_attribute(vao, 5, 5, 4);
  vertex_buffer(vao, 6, static_vbo_.get(), 5 * rn * f, 2 * f);
  float_attribute(vao, 6, 6, 2);
  element_buffer(vao, triangle_ebo_.get());
  element_buffer(line_vao_.get(), line_ebo_.get());
}

// Attribute 0 (position) of both vertex arrays from `buffer`.
void ClothGeometry::draw_positions_from(GLuint buffer, GLsizei stride) {
  for (GLuint vao : {cloth_vao_.get(), line_vao_.get()})
    vertex_buffer(vao, 0, buffer, 0, static_cast<std::size_t>(stride));
  position_buffer_ = buffer;
  position_stride_ = stride;
}

void ClothGeometry::update(const FrameFields& fields) {
  if (fields.vertices != layout_.vertices || fields.positions.size() != 3 * fields.vertices)
    throw std::invalid_argument("ClothGeometry::update: a snapshot of another cloth");
  device_ = fields.device;
  std::copy(fields.positions.begin(), fields.positions.end(), staging_.begin());
  update_bounds();
  tangents_stale_ = true;
  if (!fields.spring_strain.empty()) update_strain_top(fields.spring_strain);
  // The transform-feedback backend's captured buffer is drawn as it is (its ping-pong half
  // changes every substep); a grid cloth has no seam copies (sim/scene/validate.cpp).
  const bool direct = device_ && device_->flat_normals() && layout_.seam_copies.empty();
  if (direct) return draw_positions_from(device_->position_buffer(), 4 * sizeof(float));
  if (flat_normals()) draw_positions_from(dynamic_vbo_.get(), 3 * sizeof(float));
  if (device_)
    return pack_.pack(*device_, layout_.vertices, layout_.render_vertices(), dynamic_vbo_.get());
  const std::size_t rn = layout_.render_vertices();
  std::copy(fields.normals.begin(), fields.normals.end(), staging_.begin() + 3 * rn);
  // The seam copies take their solver vertex's position and normal.
  copy_seams(staging_.data(), 3, 0);
  copy_seams(staging_.data(), 3, 3 * rn);
  update_buffer(dynamic_vbo_.get(), staging_);
}

void ClothGeometry::update_strain_top(const std::vector<float>& spring_strain) {
  const std::size_t every = std::max<std::size_t>(1, spring_strain.size() / 4096);
  strains_.clear();
  for (std::size_t s = 0; s < spring_strain.size(); s += every)
    if (std::isfinite(spring_strain[s])) strains_.push_back(std::abs(spring_strain[s]));
  strain_top_ = strains_.empty()
                    ? kMinStrainRange
                    : std::max(quantile(strains_, kStrainRangeQuantile), kMinStrainRange);
}

// values[offset + stride * (vertices + k) + d] = values[offset + stride * seam_copies[k] + d].
void ClothGeometry::copy_seams(float* values, std::size_t stride, std::size_t offset) const {
  for (std::size_t k = 0; k < layout_.seam_copies.size(); ++k) {
    const std::size_t from = offset + stride * static_cast<std::size_t>(layout_.seam_copies[k]),
                      to = offset + stride * (layout_.vertices + k);
    for (std::size_t d = 0; d < stride; ++d) values[to + d] = values[from + d];
  }
}

// The cloth's current bounds: the light's frustum follows the cloth, so the shadow map spends
// its texels on it wherever it has moved.
void ClothGeometry::update_bounds() {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t v = 0; v < layout_.vertices; ++v) {
    const glm::vec3 p(staging_[3 * v], staging_[3 * v + 1], staging_[3 * v + 2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  if (layout_.vertices == 0 || !std::isfinite(lo.x + hi.x + lo.y + hi.y + lo.z + hi.z))
    lo = hi = glm::vec3(0.0f);
  lo_ = lo;
  hi_ = hi;
}

void ClothGeometry::set_scalars(const std::vector<float>& values) {
  if (values.size() != layout_.vertices)
    throw std::invalid_argument("Renderer::set_scalars: one value per vertex expected");
  // Through the staging copy (sized by build: no allocation per frame), seam copies filled.
  std::copy(values.begin(), values.end(), scalar_staging_.begin());
  copy_seams(scalar_staging_.data(), 1, 0);
  update_buffer(scalar_vbo_.get(), scalar_staging_);
}

// The tangent frame of every cloth from the positions and normals of the last update(), only
// when a mode that needs it is drawn.
void ClothGeometry::update_tangents() {
  if (!tangents_stale_ || layout_.vertices == 0) return;
  const std::size_t rn = layout_.render_vertices();
  if (device_) device_->read_normals(staging_.data() + 3 * rn);  // the normals stayed there
  // Mode 6's irradiance pass reads attribute 1: the flat normals the device gave, per vertex.
  if (flat_normals())
    update_buffer(dynamic_vbo_.get(), staging_.data() + 3 * rn, 3 * rn * sizeof(float),
                  3 * rn * sizeof(float));
  const float* positions = staging_.data();
  const float* normals = staging_.data() + 3 * rn;
  for (const ClothRange& c : layout_.cloths) {
    const std::size_t o = static_cast<std::size_t>(c.offset);
    if (c.mesh) {
      compute_mesh_tangents(c.offset, c.offset + c.nu, layout_.mesh_triangles, positions, normals,
                            layout_.mesh_uvs.data(), tangents_.data(), tangent_scratch_);
      continue;
    }
    compute_grid_tangents(c.nu, c.nv, positions + 3 * o, normals + 3 * o, tangents_.data() + 4 * o,
                          c.wrap_u);
  }
  // A seam copy has column 0's frame: the ring's dP/du is continuous there, so is the frame.
  copy_seams(tangents_.data(), 4, 0);
  update_buffer(tangent_vbo_.get(), tangents_);
  tangents_stale_ = false;
}

}  // namespace clothlab::vis
