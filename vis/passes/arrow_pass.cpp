#include "vis/passes/arrow_pass.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>

#include "gl/program.hpp"

namespace clothlab::vis {
namespace {

// Explicit uniform locations in shaders/arrow.vert and arrow.frag.
constexpr GLint kRadius = 0, kColoring = 1;
constexpr int kSegments = 12;  // around the axis: faces within 15 degrees of any view direction

// A mesh vertex: its direction around the axis (cos, sin) and which ring it belongs to
// (shaders/arrow.vert turns the ring into a radius, a height and a normal for each arrow).
struct MeshVertex {
  float c, s, ring;
};

// Rings, in shaders/arrow.vert's numbering.
enum Ring {
  shaft_bottom = 0,
  shaft_top,
  head_base,
  tip,
  cap_centre,
  cap_rim,
  under_inner,
  under_outer
};

std::vector<MeshVertex> arrow_mesh() {
  std::vector<MeshVertex> v;
  auto quad = [&](float c0, float s0, float c1, float s1, Ring a, Ring b) {
    v.insert(v.end(), {{c0, s0, float(a)}, {c1, s1, float(a)}, {c1, s1, float(b)}});
    v.insert(v.end(), {{c0, s0, float(a)}, {c1, s1, float(b)}, {c0, s0, float(b)}});
  };
  for (int k = 0; k < kSegments; ++k) {
    const double a0 = 2.0 * std::numbers::pi * k / kSegments;
    const double a1 = 2.0 * std::numbers::pi * (k + 1) / kSegments;
    const double am = 0.5 * (a0 + a1);
    const float c0 = float(std::cos(a0)), s0 = float(std::sin(a0));
    const float c1 = float(std::cos(a1)), s1 = float(std::sin(a1));
    quad(c0, s0, c1, s1, shaft_bottom, shaft_top);  // shaft side
    // Cone side: the tip takes the segment's middle direction for a smooth normal there.
    v.insert(v.end(), {{c0, s0, float(head_base)},
                       {c1, s1, float(head_base)},
                       {float(std::cos(am)), float(std::sin(am)), float(tip)}});
    // Bottom cap (facing -axis) and the head's underside ring.
    v.insert(v.end(),
             {{c1, s1, float(cap_rim)}, {c0, s0, float(cap_rim)}, {1, 0, float(cap_centre)}});
    quad(c1, s1, c0, s0, under_inner, under_outer);
  }
  return v;
}

}  // namespace

ArrowPass::ArrowPass()
    : program_(build_program({"arrow.vert", "arrow.frag"})),
      mesh_vbo_(make_buffer()),
      vao_(make_vertex_array()) {
  const std::vector<MeshVertex> mesh = arrow_mesh();
  mesh_vertices_ = static_cast<GLsizei>(mesh.size());
  glNamedBufferStorage(mesh_vbo_.get(), static_cast<GLsizeiptr>(mesh.size() * sizeof(MeshVertex)),
                       mesh.data(), 0);
  glVertexArrayVertexBuffer(vao_.get(), 0, mesh_vbo_.get(), 0, sizeof(MeshVertex));
  glEnableVertexArrayAttrib(vao_.get(), 0);
  glVertexArrayAttribFormat(vao_.get(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_.get(), 0, 0);
  // Per instance (binding 1, divisor 1): base, vector, value.
  const struct {
    GLuint index;
    GLint size;
    GLuint offset;
  } per_instance[] = {{1, 3, offsetof(ArrowInstance, base)},
                      {2, 3, offsetof(ArrowInstance, vector)},
                      {3, 1, offsetof(ArrowInstance, value)}};
  for (const auto& a : per_instance) {
    glEnableVertexArrayAttrib(vao_.get(), a.index);
    glVertexArrayAttribFormat(vao_.get(), a.index, a.size, GL_FLOAT, GL_FALSE, a.offset);
    glVertexArrayAttribBinding(vao_.get(), a.index, 1);
  }
  glVertexArrayBindingDivisor(vao_.get(), 1, 1);
  glObjectLabel(GL_VERTEX_ARRAY, vao_.get(), -1, "arrow glyphs");
}

void ArrowPass::draw(const std::vector<ArrowInstance>& instances, ArrowColoring coloring,
                     float radius, GLuint lut) {
  last_count_ = instances.size();
  if (instances.empty()) return;
  if (instances.size() > capacity_) {  // immutable storage: a larger buffer when it grows
    capacity_ = instances.size();
    instance_vbo_ = make_buffer();
    glNamedBufferStorage(instance_vbo_.get(),
                         static_cast<GLsizeiptr>(capacity_ * sizeof(ArrowInstance)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    glVertexArrayVertexBuffer(vao_.get(), 1, instance_vbo_.get(), 0, sizeof(ArrowInstance));
  }
  glNamedBufferSubData(instance_vbo_.get(), 0,
                       static_cast<GLsizeiptr>(instances.size() * sizeof(ArrowInstance)),
                       instances.data());
  glUseProgram(program_.get());
  glProgramUniform1f(program_.get(), kRadius, radius);
  glProgramUniform1i(program_.get(), kColoring, coloring == ArrowColoring::direction ? 1 : 0);
  glBindTextureUnit(1, lut);
  glEnable(GL_DEPTH_TEST);
  glBindVertexArray(vao_.get());
  glDrawArraysInstanced(GL_TRIANGLES, 0, mesh_vertices_, static_cast<GLsizei>(instances.size()));
  glBindVertexArray(0);
}

}  // namespace clothlab::vis
