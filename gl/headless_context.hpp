// An OpenGL 4.5 core context without a window or display, through EGL: the NVIDIA EGL driver
// where a device is enumerable (EGL_EXT_platform_device), else Mesa's surfaceless platform
// (llvmpipe on machines without a GPU). Rendering goes to framebuffer objects.
#pragma once

#include <string>

namespace clothlab::vis {

class HeadlessContext {
 public:
  // Creates the context and makes it current on this thread; loads GL with glad.
  // Throws GlUnavailable with one clear line when EGL or GL 4.5 core is missing.
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

}  // namespace clothlab::vis
