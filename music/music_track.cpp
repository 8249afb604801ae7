#include "music/music_track.hpp"

#include <algorithm>
#include <cstdio>

#include "music/drum_track.hpp"

namespace clothlab {

MusicTrack load_music(const std::string& path) {
  MusicTrack m;
  m.clip = read_audio(path);
  if (m.clip.sample_rate < kMinMusicRate)
    throw AudioError("audio file '" + path + "': a sample rate of " +
                     std::to_string(m.clip.sample_rate) +
                     " Hz is too low for the beat tracker (at least " +
                     std::to_string(kMinMusicRate) + " Hz: its high band starts at 2 kHz)");
  if (m.clip.sample_rate > kMaxMusicRate)
    throw AudioError("audio file '" + path + "': a sample rate of " +
                     std::to_string(m.clip.sample_rate) + " Hz is beyond the highest in use (" +
                     std::to_string(kMaxMusicRate) + " Hz)");
  m.analysis = track_beats(m.clip);
  m.source = path;
  return m;
}

MusicTrack generated_music(double bpm, double seconds) {
  MusicTrack m;
  DrumTrackSpec spec;
  spec.bpm = bpm;
  spec.seconds = seconds;
  m.clip = make_drum_track(spec);
  m.analysis = track_beats(m.clip);
  char text[96];
  std::snprintf(text, sizeof text, "generated drum track, %g BPM, %g s", bpm, seconds);
  m.source = text;
  m.generated = true;
  return m;
}

std::vector<double> beat_amplitudes(const BeatTrack& track) {
  const std::vector<double>& beats = track.beats;
  std::vector<double> out(beats.size(), 1.0);
  if (track.bands.frames.empty() || beats.size() < 2) return out;
  for (std::size_t k = 0; k < beats.size(); ++k) {
    const double t0 = beats[k];
    const double t1 = k + 1 < beats.size() ? beats[k + 1] : 2.0 * beats[k] - beats[k - 1];
    double sum = 0.0;
    int samples = 0;
    for (double t = t0; t < t1; t += track.bands.hop_seconds, ++samples)
      for (int b = 0; b < 3; ++b) sum += band_level(track.bands, t, b) / 3.0;
    const double level = samples > 0 ? sum / samples : 0.0;
    out[k] = std::clamp(0.5 + 0.5 * level, 0.0, 1.0);
  }
  return out;
}

}  // namespace clothlab
