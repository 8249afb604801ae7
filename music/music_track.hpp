// The music a scene dances to ([music], issue 9): the sound, where it came from, and its
// analysis (beats and band energies), made once when the scene is read.
#pragma once

#include <string>
#include <vector>

#include "music/audio_clip.hpp"
#include "music/beat_tracker.hpp"

namespace clothlab {

struct MusicTrack {
  AudioClip clip;
  BeatTrack analysis;
  std::string source;  // the file read, or "generated drum track, 120 BPM, 40 s"
  bool generated = false;
};

// The lowest sample rate the beat tracker works at: its high band starts at 2 kHz, so the
// Nyquist frequency must lie well above it (8 kHz is telephone sound).
inline constexpr int kMinMusicRate = 8000;
// The highest: 768 kHz, the highest rate in use (DXD and PCM masters). The tracker's window is
// 23 ms of samples; a header claiming 2^31 Hz asked for an FFT of 2^26 points (fuzz pass).
inline constexpr int kMaxMusicRate = 768000;

// Reads and analyses a sound file (libsndfile: WAV, FLAC, OGG, MP3). Throws AudioError, also for
// a sample rate below kMinMusicRate or above kMaxMusicRate.
MusicTrack load_music(const std::string& path);
// The project's own drum track (music/drum_track.hpp) at `bpm` for `seconds`, analysed like a
// file would be (the dance follows what the tracker hears, not the tempo it was made at).
MusicTrack generated_music(double bpm, double seconds);

// How big the dance is on each beat: 0.5 + 0.5 * the mean of the three band levels over the
// beat's interval (to the next beat; the last takes the previous interval), so loud passages
// dance fully and quiet ones at half size.
std::vector<double> beat_amplitudes(const BeatTrack& track);

}  // namespace clothlab
