// Key 7: the light's depth map drawn over the whole view (shaders/depth_view.*), coloured by a
// colour map, with the shadow pass's depth texture bound as the frame leaves it.
#pragma once

#include "gl/objects.hpp"

namespace clothlab::vis {

class DepthViewPass {
 public:
  DepthViewPass();
  // One full-screen triangle over a width x height target (from `empty_vao`, which has no
  // attributes), depth test off for it.
  void draw(int width, int height, GLuint colormap, GLuint empty_vao) const;

 private:
  Program program_;
};

}  // namespace clothlab::vis
