// Synthesised test music with a known beat: a drum pattern and click tracks. Deterministic (own
// seeded generator), so the beat tracker's tests and demos have exact ground truth.
#pragma once

#include <vector>

#include "music/audio_clip.hpp"

namespace clothlab {

struct DrumTrackSpec {
  double bpm = 120;         // beats per minute; beat k at k * 60 / bpm seconds, from 0
  double seconds = 20;      // length
  int sample_rate = 44100;  // Hz
  unsigned seed = 1;        // noise of the snare and hi-hat
};

// A 4/4 rock pattern: kick on every beat, snare on beats 2 and 4, closed hi-hat on every eighth.
// Peak-normalised to 0.9.
AudioClip make_drum_track(const DrumTrackSpec& spec);

// The same pattern on explicit beat times (seconds, ascending), for tempo changes; the eighth
// between two beats is their midpoint, the one after the last beat uses the previous interval.
AudioClip make_drum_track(const std::vector<double>& beat_times, double seconds, int sample_rate,
                          unsigned seed);

// Clicks (a 20 ms decaying 1.5 kHz burst) at first_beat_s + k * 60 / bpm, over white noise of
// RMS noise_level. The click peaks at about 0.8.
AudioClip make_click_track(double bpm, double seconds, int sample_rate, double noise_level,
                           double first_beat_s);

// Clicks at explicit times (seconds), over white noise of RMS noise_level.
AudioClip make_click_track(const std::vector<double>& beat_times, double seconds, int sample_rate,
                           double noise_level);

}  // namespace clothlab
