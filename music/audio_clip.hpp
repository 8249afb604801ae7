// A sound as plain data: mono float samples at one sample rate, read from and written to sound
// files through libsndfile (WAV, FLAC, OGG/Vorbis, MP3 as libsndfile 1.2 decodes them). The
// analysis (beat_tracker.hpp) and playback (apps/view/audio_playback.hpp) both take this struct.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace clothlab {

// A file that cannot be read or written; the message names the path and libsndfile's reason.
class AudioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct AudioClip {
  int sample_rate = 44100;     // Hz
  std::vector<float> samples;  // mono, nominally in [-1, 1]
  // Length in seconds (0 for an empty clip or a non-positive rate).
  double duration() const;
};

// Decodes a sound file and mixes its channels to mono (their mean, so a signal present on every
// channel keeps its level). Throws AudioError for a missing file, a file libsndfile does not
// recognise as sound, or one without samples.
AudioClip read_audio(const std::string& path);

// Writes 16-bit PCM WAV. The samples go to `path + ".tmp"`, which is renamed over `path` only
// once complete, so `path` is complete or absent. Samples outside [-1, 1] are clipped, not
// wrapped. Throws AudioError (with the path) on failure, leaving no temporary file behind.
void write_wav(const std::string& path, const AudioClip& clip);

}  // namespace clothlab
