// The GPU backend's cloth into the renderer's vertex buffer, on the GPU (shaders/cloth_pack.comp):
// positions and normals go from the device's buffers (4 floats per vertex) to the cloth's render
// layout (3 floats each, a tube's seam copies appended; vis/render/cloth_layout.hpp), never
// through the CPU.
#pragma once

#include <cstddef>
#include <vector>

#include "gl/objects.hpp"
#include "gl/program.hpp"

namespace clothlab {
class DeviceCloth;
}

namespace clothlab::vis {

class ClothPackPass {
 public:
  // The seam copies of the cloth's layout (render vertex vertices + k copies seam_copies[k]);
  // call whenever the layout is rebuilt.
  void set_seams(const std::vector<int>& seam_copies);
  // Packs `device`'s `vertices` positions and normals into `vertex_buffer` (positions, then
  // normals, of `render_vertices` render vertices). Builds the program on first use.
  void pack(const DeviceCloth& device, std::size_t vertices, std::size_t render_vertices,
            GLuint vertex_buffer);

 private:
  Program program_;
  Buffer seam_source_;
};

}  // namespace clothlab::vis
