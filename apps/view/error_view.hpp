// The window's error view (E; docs/tuning.md, "The error in the window"). A reference run of the
// shown scene (tune/live_reference.hpp: RK4 in double at half its stability limit) steps on a
// thread of its own to every time the shown run reaches; the cloth can be coloured by each
// vertex's distance from it ("error" in the colour-by list) and a panel plots the RMS and largest
// distance against time beside both runs' costs. When the reference cannot keep up, the shown
// run waits for it: simulated time slows, and the panel and the title say so. A new solver (an
// edit in the panel), a reset, another scene, a push, a drop or a released pull starts a new
// comparison from the shown state at that moment.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "apps/view/sim_session.hpp"
#include "tune/live_reference.hpp"

namespace clothlab::vis {

class ErrorView {
 public:
  bool on() const { return reference_ != nullptr; }
  // E and the panel's switch: compares from the shown state now, or stops. Returns a line for
  // the panel and stdout.
  std::string toggle(const SimSession& session);
  // The shown run was changed by hand (`why`: "push", "drop", "pull"): a new comparison from
  // its state now.
  void restart(const SimSession& session, const char* why);

  // Before the frame's advance: false while the reference is still on its way to the last time
  // handed to it (the shown run waits this frame).
  bool may_advance();
  // After the advance, with the wall time it took and the simulated time it covered: rebuilds
  // the reference when the session built another solver, collects the newest comparison, and
  // hands over the shown state when it moved.
  void after_advance(const SimSession& session, double step_seconds, double simulated,
                     double wall_seconds);

  bool has_comparison() const { return has_latest_; }  // since the last (re)start
  // The newest comparison's distance of each vertex (m); empty before the first one.
  const std::vector<float>& per_vertex() const { return latest_.per_vertex; }
  // The shown run waited for the reference in the last half second.
  bool slowed() const { return slowed_; }
  // Share of real time simulated over the last half second, while slowed (percent).
  double pace_percent() const { return pace_percent_; }
  // "error 3.2 mm RMS, 8.1 mm max at t = 1.20 s" (and the wait), for the title; empty when off.
  std::string title_note() const;

  // "error view: 37 comparisons to t = 0.61 s, the last 0.12 mm RMS and 0.40 mm max; the shown
  // run waited in 0 of 40 frames", printed when the window closes; empty if it was never on.
  std::string summary() const;
  const std::string& note() const { return note_; }  // "comparing from t = 1.20 s (push)"

  // The panel's window (top right) while the view is on.
  void draw_panel();
  // Where that window ended last frame (window points from the top; 0 when it is not shown):
  // the colour bars stand below it.
  float panel_bottom() const { return panel_bottom_; }

 private:
  void build(const SimSession& session, const std::string& why);
  void collect();
  void record_pace(bool waited, double simulated, double wall_seconds);
  void panel_contents() const;

  std::unique_ptr<tune::LiveReference> reference_;
  long build_ = -1, generation_ = -1;  // the session's solver the reference follows
  double submitted_ = -1.0;            // s: the last shown time handed over
  tune::LiveComparison latest_;
  bool has_latest_ = false;
  // The plot: the last kHistory comparisons.
  static constexpr std::size_t kHistory = 1800;
  std::vector<float> times_, rms_mm_, max_mm_;
  std::string note_;                                 // where and why the comparison began
  std::string error_;                                // why the reference could not be built
  double shown_wall_ = 0.0, shown_simulated_ = 0.0;  // the shown run's cost since then
  // The pace over half-second windows.
  double window_wall_ = 0.0, window_simulated_ = 0.0;
  bool waiting_ = false;                                   // may_advance said no this frame
  long comparisons_ = 0, frames_ = 0, waited_frames_ = 0;  // while on, over the window's life
  bool window_waited_ = false, slowed_ = false;
  double pace_percent_ = 100.0;
  float panel_bottom_ = 0.0f;
};

}  // namespace clothlab::vis
