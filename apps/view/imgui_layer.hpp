// Dear ImGui bound to the window: context, GLFW and OpenGL3 back-ends, created and destroyed
// together. Dear ImGui keeps its context in a global (its design); this object is its only owner.
#pragma once

struct GLFWwindow;

namespace clothlab::vis {

class ImGuiLayer {
 public:
  // Install the window's own GLFW callbacks first: the back-end chains to them.
  explicit ImGuiLayer(GLFWwindow* window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void begin_frame();                // before any ImGui:: call of the frame
  void end_frame();                  // draws the UI into the bound framebuffer
  void end_frame_without_drawing();  // closes the frame when there is nowhere to draw
  bool wants_keyboard() const;
  bool wants_mouse() const;
};

}  // namespace clothlab::vis
