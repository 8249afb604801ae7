// Music playback in the window through OpenAL (docs/contact.md section 4). The audio clock is the
// master and the simulation catches up to time(); where no device opens (a headless machine has
// no /dev/snd) open() returns nothing and the caller runs on the simulation clock. Interactive
// only: no test opens a device.
#pragma once

#include <AL/al.h>
#include <AL/alc.h>

#include <optional>
#include <string>

#include "music/audio_clip.hpp"

namespace clothlab::vis {

class AudioPlayback {
 public:
  // Opens the default device, makes a context current and uploads the clip as 16-bit mono.
  // On any failure releases what was made, writes a one-line reason to `message` (what failed;
  // the caller prints it with what it does instead) and returns nothing. Makes its context the
  // process's current OpenAL context (an OpenAL rule), so keep one playback at a time.
  static std::optional<AudioPlayback> open(const AudioClip& clip, std::string& message);

  AudioPlayback(AudioPlayback&& other) noexcept;
  AudioPlayback& operator=(AudioPlayback&& other) noexcept;
  AudioPlayback(const AudioPlayback&) = delete;
  AudioPlayback& operator=(const AudioPlayback&) = delete;
  ~AudioPlayback();

  // Each returns false when OpenAL reported an error (the device went away); the caller may then
  // drop the playback and continue on the simulation clock.
  bool play();  // from the current time; from the start once the end was reached
  bool pause();
  bool seek(double seconds);  // clamped to [0, duration()]; keeps playing if playing

  // Playback position in seconds: the source's offset while playing or paused, duration() once
  // it has played to the end (OpenAL then reports offset 0), the sought time before play().
  double time() const;
  double duration() const { return duration_; }
  bool playing() const;

 private:
  AudioPlayback() = default;
  void release();
  ALint state() const;

  ALCdevice* device_ = nullptr;
  ALCcontext* context_ = nullptr;
  ALuint source_ = 0, buffer_ = 0;
  bool has_source_ = false, has_buffer_ = false;
  double duration_ = 0.0;
  double held_ = 0.0;     // s, position while the source is initial (before play, after seek)
  bool started_ = false;  // play() was called since the last seek from a stopped source
};

}  // namespace clothlab::vis
