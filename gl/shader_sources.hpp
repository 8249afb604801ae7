// The shaders of shaders/, embedded into the program at build time (cmake/embed_shaders.cmake).
#pragma once

#include <string>
#include <vector>

namespace clothlab::vis {

struct ShaderSource {
  const char* name;  // file name in shaders/, e.g. "cloth.frag"
  const char* text;
};

const std::vector<ShaderSource>& embedded_shaders();

// The text of shaders/<name>; throws ShaderError if there is no such shader.
std::string shader_text(const std::string& name);

}  // namespace clothlab::vis
