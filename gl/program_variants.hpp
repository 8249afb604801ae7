// One shader program compiled once per set of #defines a pass asks for: the lit shaders' shadow
// filter and quality are compile-time choices (vis/render/shading_variant.hpp), because Mesa's
// llvmpipe runs both sides of a branch on a uniform with the lanes masked off, so a shadow filter
// that is switched off by a uniform still costs its whole loop (measured: the floor alone took
// 65 ms per 1280x720 frame with the PCF loop present and switched off, 29 ms compiled out).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "gl/objects.hpp"

namespace clothlab::vis {

class ProgramVariants {
 public:
  // Builds the variant for `first_defines` at once, so a shader that does not compile fails
  // where the pass is made (ShaderError), not in the middle of a frame.
  ProgramVariants(std::vector<std::string> files, const std::string& first_defines);

  // The program for `defines`, compiled the first time it is asked for and kept.
  GLuint get(const std::string& defines);
  std::size_t built() const { return variants_.size(); }

 private:
  std::vector<std::string> files_;
  std::vector<std::pair<std::string, Program>> variants_;
};

}  // namespace clothlab::vis
