// Music in the window: plays a scene's [music] through OpenAL and lets the audio clock drive the
// simulation (the rule is MusicClock's, music/music_clock.hpp; this file only carries its
// plans out on the playback). Where no device opens, or CLOTHLAB_VIEW_NO_AUDIO=1 asks for
// silence, it says so once per run and the simulation follows the frame's wall time, as in a
// scene without music.
#pragma once

#include <optional>
#include <string>

#include "apps/view/audio_playback.hpp"
#include "apps/view/sim_session.hpp"
#include "music/music_clock.hpp"

namespace clothlab::vis {

class MusicSync {
 public:
  explicit MusicSync(bool no_audio) : no_audio_(no_audio) {}

  // At start and when the scene picker opens a scene: drops the previous playback (OpenAL keeps
  // one context current at a time) and opens one on the scene's track, if it has music.
  void load(const Scene& scene);

  // The simulated seconds to ask the FrameStepper for this frame: audio time - solver time while
  // the music plays, the wall time without music or after its end, 0 while paused. Also seeks,
  // plays and pauses the playback to keep it with the session (reset, pause, single steps).
  // max_advance: the frame's cap in simulated seconds (FrameStepper::cap).
  double frame_advance(const SimSession& session, double wall_seconds, double max_advance);

  bool audible() const { return playback_.has_value(); }
  // A short line for the panel: "playing", "paused", "ended: wall clock", "silent: ...".
  const char* status() const { return status_; }

 private:
  void fall_silent(const std::string& message);  // prints the message once per run

  bool no_audio_;
  bool told_silent_ = false;
  std::optional<AudioPlayback> playback_;
  std::optional<MusicClock> clock_;
  const char* status_ = "no music";
};

}  // namespace clothlab::vis
