#include "apps/view/glfw_window.hpp"

#include <algorithm>

#include <cstdio>
#include <cstdlib>

#include "gl/draw_state.hpp"
#include "gl/gl.hpp"
#include "gl/gl_error.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace clothlab::vis {
namespace {

constexpr const char* kHeadlessHint = "; use 'clothlab render SCENE --out DIR' to render headless";

// GLFW's description of its last error (glfwGetError instead of an error callback, which would
// need a global to reach us).
std::string last_glfw_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

bool has_display_variable() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
}

}  // namespace

GlfwWindow::GlfwWindow(const std::string& title, int width, int height) {
  if (!glfwInit()) {
    const std::string why =
        has_display_variable() ? last_glfw_error() : std::string("DISPLAY is not set");
    throw GlUnavailable("no display available (" + why + ")" + kHeadlessHint);
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // The renderer writes linear colour and lets GL encode sRGB (GL_FRAMEBUFFER_SRGB).
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_TRUE);
  // Single-sampled: the scene is drawn into a multisampled target of its own when the render
  // quality asks for MSAA (vis/render/render_quality.hpp), the panel straight into the window.
  glfwWindowHint(GLFW_SAMPLES, 0);
#ifndef NDEBUG
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
#endif
  // No larger than the monitor's work area (a 1280x800 window is taller than a 720-line screen,
  // and the panel's last rows would be cut off), less room for the title bar.
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
    int x = 0, y = 0, w = 0, h = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
    constexpr int kTitleBar = 40;  // pixels a window manager may add above the client area
    if (w > 0) width = std::min(width, w);
    if (h > kTitleBar) height = std::min(height, h - kTitleBar);
  }
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    const std::string why = description ? description : "unknown GLFW error";
    glfwTerminate();
    if (code == GLFW_VERSION_UNAVAILABLE || code == GLFW_API_UNAVAILABLE)
      throw GlUnavailable("OpenGL 4.5 core is not available on this display (" + why + ")" +
                          kHeadlessHint);
    throw GlUnavailable("cannot open a window (" + why + ")" + kHeadlessHint);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);  // vsync: the frame loop runs at the display's rate, not flat out
  if (!gladLoadGL(glfwGetProcAddress) || !GLAD_GL_VERSION_4_5) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw GlUnavailable("OpenGL 4.5 core is not available on this display" +
                        std::string(kHeadlessHint));
  }
#ifndef NDEBUG
  enable_debug_output("clothlab view");
#endif
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlfwWindow::should_close() const {
  return glfwWindowShouldClose(window_);
}

void GlfwWindow::request_close() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void GlfwWindow::set_title(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

void GlfwWindow::framebuffer_size(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}

void GlfwWindow::swap_buffers() {
  glfwSwapBuffers(window_);
}

}  // namespace clothlab::vis
