#include "vis/passes/cloth_pack_pass.hpp"

#include <cstdint>

#include "gl/uploads.hpp"
#include "sim/step_backend.hpp"

namespace clothlab::vis {

void ClothPackPass::set_seams(const std::vector<int>& seam_copies) {
  const std::vector<std::int32_t> seams(seam_copies.begin(), seam_copies.end());
  seam_source_ = static_buffer(seams);
}

void ClothPackPass::pack(const DeviceCloth& device, std::size_t vertices,
                         std::size_t render_vertices, GLuint vertex_buffer) {
  if (!program_) program_ = build_program({"cloth_pack.comp"});
  const GLuint p = program_.get();
  glProgramUniform1ui(p, glGetUniformLocation(p, "n"), static_cast<GLuint>(vertices));
  glProgramUniform1ui(p, glGetUniformLocation(p, "render_n"), static_cast<GLuint>(render_vertices));
  glUseProgram(p);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, device.position_buffer());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, device.normal_buffer());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, seam_source_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, vertex_buffer);
  glDispatchCompute(static_cast<GLuint>((render_vertices + 63) / 64), 1, 1);
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
  glUseProgram(0);
}

}  // namespace clothlab::vis
