#include "vis/overlay/headless_overlay.hpp"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "gl/draw_state.hpp"

namespace clothlab::vis {
namespace {

// Makes `context` current for a scope and restores the previous one (the window's, if any).
class ContextScope {
 public:
  explicit ContextScope(ImGuiContext* context) : previous_(ImGui::GetCurrentContext()) {
    ImGui::SetCurrentContext(context);
  }
  ~ContextScope() { ImGui::SetCurrentContext(previous_); }
  ContextScope(const ContextScope&) = delete;
  ContextScope& operator=(const ContextScope&) = delete;

 private:
  ImGuiContext* previous_;
};

}  // namespace

HeadlessOverlay::HeadlessOverlay() {
  ImGuiContext* previous = ImGui::GetCurrentContext();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  ImGui_ImplOpenGL3_Init("#version 450 core");
  ImGui::SetCurrentContext(previous);
}

HeadlessOverlay::~HeadlessOverlay() {
  {
    ContextScope scope(context_);
    ImGui_ImplOpenGL3_Shutdown();
  }
  ImGui::DestroyContext(context_);
}

void HeadlessOverlay::draw(int width, int height, const std::function<void(ImDrawList*)>& build) {
  ContextScope scope(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
  io.DeltaTime = 1.0f / 60.0f;
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  build(ImGui::GetForegroundDrawList());
  ImGui::Render();
  // The UI's colours are sRGB already: no second encoding.
  const ScopedCapability srgb_off(GL_FRAMEBUFFER_SRGB, false);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace clothlab::vis
