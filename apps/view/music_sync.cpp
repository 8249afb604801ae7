#include "apps/view/music_sync.hpp"

#include <cstdio>

#include "music/music_track.hpp"

namespace clothlab::vis {

void MusicSync::load(const Scene& scene) {
  playback_.reset();  // before opening the next: one OpenAL context at a time
  clock_.reset();
  status_ = "no music";
  if (!scene.music || !scene.music->track) return;
  const AudioClip& clip = scene.music->track->clip;
  if (no_audio_) {
    fall_silent("audio off (CLOTHLAB_VIEW_NO_AUDIO=1)");
    return;
  }
  std::string message;
  playback_ = AudioPlayback::open(clip, message);
  if (!playback_) {
    fall_silent(message);
    return;
  }
  clock_.emplace(playback_->duration());
  status_ = "playing";
}

// A device that goes away mid-run ends the playback the same way as one that never opened.
void MusicSync::fall_silent(const std::string& message) {
  playback_.reset();
  clock_.reset();
  status_ = "silent: simulation clock";
  if (told_silent_) return;
  told_silent_ = true;
  std::printf("clothlab view: %s; running silently on the simulation clock\n", message.c_str());
  std::fflush(stdout);
}

double MusicSync::frame_advance(const SimSession& session, double wall_seconds,
                                double max_advance) {
  if (!playback_) return wall_seconds;
  MusicReading reading;
  reading.audio = playback_->time();
  reading.solver = session.solver().time();
  reading.generation = session.generation();
  reading.running = !session.paused && !session.divergence();
  const MusicPlan plan = clock_->plan(reading, wall_seconds, max_advance);
  bool ok = true;
  if (plan.seek) ok = playback_->seek(*plan.seek) && ok;
  if (plan.play != playback_->playing())
    ok = (plan.play ? playback_->play() : playback_->pause()) && ok;
  if (!ok) {
    fall_silent("audio: the playback stopped with an OpenAL error");
    return wall_seconds;
  }
  status_ = !reading.running ? "paused" : plan.on_audio ? "playing" : "ended: on the wall clock";
  return plan.advance;
}

}  // namespace clothlab::vis
