// Instanced arrow glyphs (F force arrows, N normal arrows): one small cylinder-and-cone mesh,
// drawn once per ArrowInstance with the instance's base, vector and colour value as per-instance
// attributes. The shaft and head are sized in the vertex shader from each arrow's length, so a
// short arrow stays an arrow (radius at most a tenth of its length, as Polyscope clips it).
#pragma once

#include <cstddef>
#include <vector>

#include "gl/objects.hpp"
#include "vis/render/arrow_field.hpp"

namespace clothlab::vis {

enum class ArrowColoring { colormap, direction };

class ArrowPass {
 public:
  ArrowPass();

  // Draws `instances` into the bound framebuffer with the Frame block of the Renderer's last
  // draw() (binding 0): call right after Renderer::draw in the same frame. `radius` is the
  // largest shaft radius (m); `lut` the colour map texture for ArrowColoring::colormap.
  void draw(const std::vector<ArrowInstance>& instances, ArrowColoring coloring, float radius,
            GLuint lut);

  // Instances drawn by the last draw(), for tests.
  std::size_t last_instance_count() const { return last_count_; }
  // Triangles per arrow.
  GLsizei mesh_triangles() const { return mesh_vertices_ / 3; }

 private:
  Program program_;
  Buffer mesh_vbo_, instance_vbo_;
  VertexArray vao_;
  GLsizei mesh_vertices_ = 0;
  std::size_t capacity_ = 0;  // instances the instance buffer holds
  std::size_t last_count_ = 0;
};

}  // namespace clothlab::vis
