#include "apps/view/error_view.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <exception>

#include "apps/view/message_colours.hpp"
#include "sim/solver.hpp"

namespace clothlab::vis {
namespace {

constexpr double kPaceWindowSeconds = 0.5;
const ImVec4 kRmsColour{0.35f, 0.75f, 1.0f, 1.0f};
const ImVec4 kMaxColour{1.0f, 0.6f, 0.25f, 1.0f};

std::string comparing_from(double time, const std::string& why) {
  char text[128];
  std::snprintf(text, sizeof text, "comparing from t = %.2f s (%s)", time, why.c_str());
  return text;
}

// Keeps the last `cap` values of a plot's series.
void push_capped(std::vector<float>& series, float value, std::size_t cap) {
  if (series.size() >= cap)
    series.erase(series.begin(), series.begin() + (series.size() - cap + 1));
  series.push_back(value);
}

// The RMS and the largest distance against time in one box (mm, from 0 to the largest shown).
void plot_history(const std::vector<float>& rms, const std::vector<float>& max, float top) {
  const ImVec2 size(ImGui::GetContentRegionAvail().x, 70.0f);
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(p0, ImVec2(p0.x + size.x, p0.y + size.y),
                      ImGui::GetColorU32(ImGuiCol_FrameBg));
  const auto polyline = [&](const std::vector<float>& v, ImU32 colour) {
    const std::size_t n = v.size();
    for (std::size_t i = 1; i < n; ++i) {
      const auto at = [&](std::size_t k) {
        return ImVec2(p0.x + size.x * float(k) / float(n - 1), p0.y + size.y * (1.0f - v[k] / top));
      };
      draw->AddLine(at(i - 1), at(i), colour, 1.5f);
    }
  };
  polyline(max, ImGui::GetColorU32(kMaxColour));
  polyline(rms, ImGui::GetColorU32(kRmsColour));
  ImGui::Dummy(size);
}

}  // namespace

std::string ErrorView::toggle(const SimSession& session) {
  if (on()) {
    reference_.reset();
    latest_.per_vertex.clear();
    has_latest_ = false;
    slowed_ = false;
    return "error view off";
  }
  build(session, "error view on");
  if (!on()) return "error view: " + error_;
  return "error view: reference " + reference_->label() + ", " + note_;
}

void ErrorView::build(const SimSession& session, const std::string& why) {
  reference_.reset();  // its thread ends before the new one starts
  error_.clear();
  try {
    reference_ = std::make_unique<tune::LiveReference>(tune::live_reference_scene(session.scene()));
  } catch (const std::exception& e) {
    error_ = e.what();
    return;
  }
  build_ = session.builds();
  generation_ = session.generation();
  restart(session, why.c_str());
}

void ErrorView::restart(const SimSession& session, const char* why) {
  if (!on()) return;
  reference_->restart(session.solver());
  submitted_ = -1.0;
  has_latest_ = false;  // the last colours stay until the new comparison's first
  times_.clear();
  rms_mm_.clear();
  max_mm_.clear();
  shown_wall_ = shown_simulated_ = 0.0;
  note_ = comparing_from(session.solver().time(), why);
}

bool ErrorView::may_advance() {
  waiting_ = on() && reference_->failure().empty() && reference_->busy();
  return !waiting_;
}

void ErrorView::after_advance(const SimSession& session, double step_seconds, double simulated,
                              double wall_seconds) {
  if (!on()) return;
  if (session.generation() != generation_)
    build(session, "reset or another scene");
  else if (session.builds() != build_)
    build(session, "the solver changed");
  if (!on()) return;
  collect();
  shown_wall_ += step_seconds;
  shown_simulated_ += simulated;
  record_pace(waiting_, simulated, wall_seconds);
  ++frames_;
  waited_frames_ += waiting_ ? 1 : 0;
  const double now = session.solver().time();
  if (now != submitted_ && reference_->submit(session.solver())) submitted_ = now;
}

void ErrorView::collect() {
  if (!reference_->take(latest_)) return;
  has_latest_ = true;
  ++comparisons_;
  push_capped(times_, float(latest_.time), kHistory);
  push_capped(rms_mm_, float(1e3 * latest_.distance.rms), kHistory);
  push_capped(max_mm_, float(1e3 * latest_.distance.max), kHistory);
}

// The share of real time simulated over half-second windows, and whether the shown run waited.
void ErrorView::record_pace(bool waited, double simulated, double wall_seconds) {
  window_wall_ += wall_seconds;
  window_simulated_ += simulated;
  window_waited_ |= waited;
  if (window_wall_ < kPaceWindowSeconds) return;
  slowed_ = window_waited_;
  pace_percent_ = 100.0 * window_simulated_ / window_wall_;
  window_wall_ = window_simulated_ = 0.0;
  window_waited_ = false;
}

std::string ErrorView::title_note() const {
  if (!on()) return "";
  char text[160] = "error view: waiting for the first comparison";
  if (has_latest_)
    std::snprintf(text, sizeof text, "error %.3g mm RMS, %.3g mm max at t = %.2f s",
                  1e3 * latest_.distance.rms, 1e3 * latest_.distance.max, latest_.time);
  std::string note = text;
  if (slowed_) {
    char pace[96];
    std::snprintf(pace, sizeof pace, " (slowed to the reference: %.0f %% of real time)",
                  pace_percent_);
    note += pace;
  }
  return note;
}

std::string ErrorView::summary() const {
  if (frames_ == 0) return "";
  char text[256];
  std::snprintf(text, sizeof text,
                "error view: %ld comparisons to t = %.2f s, the last %.3g mm RMS and %.3g mm max; "
                "the shown run waited in %ld of %ld frames",
                comparisons_, latest_.time, 1e3 * latest_.distance.rms, 1e3 * latest_.distance.max,
                waited_frames_, frames_);
  return text;
}

void ErrorView::draw_panel() {
  panel_bottom_ = 0.0f;
  if (!on() && error_.empty()) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(
      ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10.0f, viewport->WorkPos.y + 10.0f),
      ImGuiCond_FirstUseEver, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(330.0f, 0.0f), ImVec2(330.0f, FLT_MAX));
  const bool open =
      ImGui::Begin("Error against the reference (E)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  panel_bottom_ = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y + 10.0f;
  if (!open) {
    ImGui::End();
    return;
  }
  ImGui::PushTextWrapPos(0.0f);
  if (!error_.empty()) ImGui::TextColored(kErrorColour, "no reference: %s", error_.c_str());
  if (on()) panel_contents();
  ImGui::PopTextWrapPos();
  ImGui::End();
}

void ErrorView::panel_contents() const {
  ImGui::Text("reference: %s, one thread", reference_->label().c_str());
  ImGui::TextDisabled("%s", note_.c_str());
  if (has_latest_) {
    ImGui::Text("t = %.2f s: RMS %.3g mm, max %.3g mm", latest_.time, 1e3 * latest_.distance.rms,
                1e3 * latest_.distance.max);
    const float top = std::max(*std::max_element(max_mm_.begin(), max_mm_.end()), 1e-3f);
    ImGui::TextColored(kRmsColour, "RMS");
    ImGui::SameLine();
    ImGui::TextColored(kMaxColour, "max");
    ImGui::SameLine();
    ImGui::TextDisabled("0 to %.3g mm, over the last %.1f s", top, times_.back() - times_.front());
    plot_history(rms_mm_, max_mm_, top);
  }
  if (shown_simulated_ > 0.0)
    ImGui::Text("wall s per simulated s: shown %.3g, reference %.3g",
                shown_wall_ / shown_simulated_, reference_->cost());
  if (slowed_)
    ImGui::TextColored(kWarningColour,
                       "the shown run waits for the reference: simulated time at %.0f %% of real "
                       "time",
                       pace_percent_);
  const std::string failure = reference_->failure();
  if (!failure.empty()) ImGui::TextColored(kErrorColour, "%s", failure.c_str());
  ImGui::TextDisabled("colour by \"error\" (Scientific views) shows each vertex's distance");
}

}  // namespace clothlab::vis
