// Dear ImGui without a window, for text and legends drawn into headless renders: its own ImGui
// context and the OpenGL3 back-end on the current (EGL) context. The window has its own context
// (apps/view/imgui_layer.hpp); this one is made current only while it draws.
#pragma once

#include <functional>

struct ImGuiContext;
struct ImDrawList;

namespace clothlab::vis {

class HeadlessOverlay {
 public:
  HeadlessOverlay();  // needs a current OpenGL 4.5 context
  ~HeadlessOverlay();
  HeadlessOverlay(const HeadlessOverlay&) = delete;
  HeadlessOverlay& operator=(const HeadlessOverlay&) = delete;

  // One ImGui frame of width x height pixels: `build` adds to the foreground draw list, which is
  // then drawn into the bound framebuffer (sRGB encoding off: ImGui's colours are sRGB already).
  void draw(int width, int height, const std::function<void(ImDrawList*)>& build);

 private:
  ImGuiContext* context_ = nullptr;
};

}  // namespace clothlab::vis
