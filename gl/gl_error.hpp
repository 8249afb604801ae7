// Errors at the GL boundary (context creation, shaders, framebuffers): thrown once, with a
// message a user can act on.
#pragma once

#include <stdexcept>
#include <string>

namespace clothlab::vis {

// OpenGL 4.5 (or a display, for the window) is not available on this machine.
struct GlUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A shader failed to compile or link: what() names the file, line and the driver's log.
struct ShaderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace clothlab::vis
