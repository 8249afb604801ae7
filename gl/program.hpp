// Building GL programs from the embedded shaders, with errors that name the shader file, the line
// and the driver's log.
#pragma once

#include <string>
#include <vector>

#include "gl/objects.hpp"

namespace clothlab::vis {

struct ShaderStage {
  GLenum type;       // GL_VERTEX_SHADER, ...
  std::string file;  // name in shaders/ (for messages)
  std::string text;
};

// Replaces each line `#include "name"` by shaders/name, framed by #line directives that number
// the included text as source string k (1, 2, ...), so the driver's log can be mapped back:
// files[0] is the shader itself, files[k] the k-th include. One level deep.
std::string expand_includes(const std::string& text, const std::string& file,
                            std::vector<std::string>& files);

// Compiles and links; throws ShaderError on failure. `defines` ("#define NAME VALUE" lines) go
// after each stage's #version line, the stage's own lines keeping their numbers. `captured`
// names the last vertex-processing stage's outputs that transform feedback writes, each into
// its own buffer binding (GL_SEPARATE_ATTRIBS), in that order.
Program link_program(const std::vector<ShaderStage>& stages, const std::string& defines = "",
                     const std::vector<const char*>& captured = {});

// The same from shader file names, the stage taken from the extension (.vert, .geom, .frag).
Program build_program(const std::vector<std::string>& files, const std::string& defines = "",
                      const std::vector<const char*>& captured = {});

// Rewrites a driver log so "0:12(5): error" lines read "shaders/cloth.frag:12:5: error" (Mesa
// prints "<source>:<line>(<column>)", NVIDIA "<source>(<line>)"); files[k] names source string k.
std::string annotate_shader_log(const std::string& log, const std::vector<std::string>& files);

}  // namespace clothlab::vis
