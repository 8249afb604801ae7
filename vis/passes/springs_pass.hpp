// Mode 1: every spring as a line, coloured by its strain on Moreland's cool-warm map
// (shaders/springs.*), over the cloth's own vertex buffer; and, for a cloth without triangles
// (drawn so in every mode), its vertices as dots. Needs a current GL 4.5 context.
#pragma once

#include "gl/objects.hpp"

namespace clothlab::vis {

class ClothGeometry;

class SpringsPass {
 public:
  SpringsPass();
  void draw(const ClothGeometry& cloth) const;
  void draw_vertices(const ClothGeometry& cloth) const;

 private:
  Program program_, vertices_program_;
};

}  // namespace clothlab::vis
