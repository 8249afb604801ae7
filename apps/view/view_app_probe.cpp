// ViewApp's probe (keys 8 / 9 / 0, a click pins it to a vertex) and its CSV recorder (Record):
// the parts of the window that read fields and write traces (view_app.cpp has the rest).
#include <cmath>
#include <cstdio>
#include <utility>

#include "apps/view/probe_readout.hpp"
#include "apps/view/screenshot.hpp"
#include "apps/view/view_app.hpp"
#include "sim/solver.hpp"
#include "sim/trace/trace_run.hpp"
#include "vis/passes/field_pass.hpp"
#include "vis/render/renderer.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace clothlab::vis {

// Pressing the active probe's key again turns probing off, and with it the field pass (and the
// force field, computed only while something probes).
void ViewApp::toggle_probe(Field field) {
  if (panel_.probe == field) {
    panel_.probe.reset();
    field_pass_.reset();
    probe_title_.clear();
    pinned_vertex_ = -1;
  } else {
    panel_.probe = field;
  }
  last_title_time_ = -1.0;  // show the change at once
}

// The field pass at the framebuffer's size, the pixel under the cursor (or under the pinned
// vertex) and its nearest vertex: a readout next to the cursor and, shorter, in the title.
void ViewApp::probe_under_cursor(int width, int height) {
  const Field field = *panel_.probe;
  double x = 0.0, y = 0.0;
  if (hooks_.cursor) {
    x = (*hooks_.cursor)[0];
    y = (*hooks_.cursor)[1];
  } else {
    glfwGetCursorPos(window_.handle(), &x, &y);
  }
  // Cursor positions are in window (screen) coordinates; the framebuffer has more pixels where
  // the content scale is above 1.
  int window_width = 0, window_height = 0;
  glfwGetWindowSize(window_.handle(), &window_width, &window_height);
  if (window_width <= 0 || window_height <= 0) return;
  Solver& solver = session_.solver();
  const glm::mat4 view_proj = view_projection(view_.camera, width, height);
  const std::optional<std::array<double, 2>> clicked = std::exchange(pending_click_, std::nullopt);
  if (clicked) {
    x = (*clicked)[0];
    y = (*clicked)[1];
  } else if (pinned_vertex_ >= 0) {
    // A pinned probe reads at its vertex's pixel, wherever the vertex has moved.
    const Vec3d p = solver.position(pinned_vertex_);
    const glm::vec4 c = view_proj * glm::vec4(float(p[0]), float(p[1]), float(p[2]), 1.0f);
    if (c.w > 0.0f) {
      x = (c.x / c.w * 0.5 + 0.5) * window_width;
      y = (0.5 - c.y / c.w * 0.5) * window_height;
    }
  }
  const int px = static_cast<int>(std::floor(x * width / window_width));
  const int py = static_cast<int>(std::floor(y * height / window_height));

  const char* name = field_name(field);
  if (session_.divergence()) {
    probe_title_ = std::string(name) + ": simulation diverged";
    draw_probe_overlay(probe_title_, static_cast<float>(x), static_cast<float>(y),
                       panel_.panel_right());
    return;
  }
  if (!field_pass_ || field_pass_->width() != width || field_pass_->height() != height)
    field_pass_ = std::make_unique<FieldPass>(width, height);
  const std::optional<ProbeSample> s =
      probe_fields(solver, snapshot_.fields(), *renderer_, *field_pass_, view_proj, px, py);
  if (clicked) pinned_vertex_ = s ? s->vertex : -1;  // a click off the cloth unpins
  const int vertex = pinned_vertex_ >= 0 ? pinned_vertex_ : s ? s->vertex : -1;
  if (vertex < 0) {
    probe_title_ = std::string(name) + ": no cloth under the cursor";
    draw_probe_overlay(probe_title_ + " (click the cloth to pin)", static_cast<float>(x),
                       static_cast<float>(y), panel_.panel_right());
    return;
  }
  const ProbeReadout readout = probe_readout(field, solver, s, vertex, pinned_vertex_ >= 0, px, py);
  probe_title_ = readout.title;
  draw_probe_overlay(readout.text, static_cast<float>(x), static_cast<float>(y),
                     panel_.panel_right());
}

// With a probe on, a click on the cloth pins the probe to the vertex nearest the clicked point
// (it then follows that vertex); a click off the cloth unpins it.
void ViewApp::click(double x, double y) {
  if (panel_.probe) pending_click_ = std::array<double, 2>{x, y};
}

// What Record writes: the pinned probe's vertex, else the scene's [trace] vertices, else the
// documented default vertex; all fields (the scene's choice of fields and `every` where it has
// a [trace] table).
TraceSpec ViewApp::record_spec() const {
  TraceSpec spec =
      session_.scene().trace ? *session_.scene().trace : default_trace(session_.scene());
  if (pinned_vertex_ >= 0) {
    const VertexRef v = session_.solver().vertex_ref(pinned_vertex_);
    spec.vertices = {{v.cloth, v.i, v.j}};
  }
  return spec;
}

void ViewApp::toggle_record() {
  if (session_.recording()) {
    stop_recording();
    return;
  }
  const std::string path = record_file_name();
  try {
    session_.start_recording(path, record_spec());
    panel_.message = "recording to " + path + " (Stop finishes the file)";
  } catch (const std::exception& e) {
    panel_.message = e.what();
  }
}

void ViewApp::stop_recording() {
  if (!session_.recording()) return;
  panel_.message = session_.stop_recording();
  std::printf("clothlab view: %s\n", panel_.message.c_str());
}

}  // namespace clothlab::vis
