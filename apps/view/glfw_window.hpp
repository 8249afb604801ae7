// The window: GLFW with an OpenGL 4.5 core context (vsync on), GL loaded through glad. In debug
// builds the context is a debug context and GL reports its errors through
// glDebugMessageCallback (docs/style.md: no glGetError polling). Owns glfwInit/glfwTerminate, so
// one GlfwWindow lives at a time.
#pragma once

#include <string>

struct GLFWwindow;

namespace clothlab::vis {

class GlfwWindow {
 public:
  // Opens the window and makes its context current. Throws GlUnavailable with one line a user
  // can act on when there is no display or no OpenGL 4.5 core context.
  GlfwWindow(const std::string& title, int width, int height);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close();
  void set_title(const std::string& title);
  void framebuffer_size(int& width, int& height) const;  // pixels (may differ from window size)
  void swap_buffers();

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace clothlab::vis
