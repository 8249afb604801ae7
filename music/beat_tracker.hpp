// Beat tracking for music-driven animation (issue 9, docs/contact.md section 4): band energies, an
// onset envelope, a global tempo and beat times that follow tempo changes. Our own analysis on an
// STFT (Eigen's FFT); no aubio.
//
// Pipeline (one pass over the samples, then work on the ~170 Hz envelope only):
//  1. STFT, Hann window of ~23 ms (1024 samples at 44.1 kHz), hop a quarter window (5.8 ms).
//  2. Per hop: the amplitude in three bands (low < 150 Hz, mid 150-2000 Hz, high > 2000 Hz),
//     each normalised to 0..1 over the track; and the half-wave-rectified spectral flux of
//     log-compressed magnitudes (Bello et al. 2005, "A tutorial on onset detection in music
//     signals", IEEE TSAP 13(5), section 3.1), minus its local mean.
//  3. Global tempo: autocorrelation of the envelope over 60-200 BPM with Ellis's log-Gaussian
//     weighting around 120 BPM against octave errors, refined by parabolic interpolation and by
//     the peaks at multiples of the period (the resonator idea of Scheirer 1998, "Tempo and beat
//     analysis of acoustic musical signals", JASA 103(1)).
//  4. Local tempo: the same autocorrelation over 6 s windows, weighted around the global tempo.
//  5. Beats: dynamic programming (Ellis 2007, "Beat tracking by dynamic programming", JNMR
//     36(1)) with the local period, so a track whose tempo changes is followed; each beat is then
//     refined to sub-hop precision on the envelope.
// Cost: ~80 ms for a 30 s track at 44.1 kHz in a Release build (measured on a busy 2-core
// machine; the STFT dominates).
#pragma once

#include <array>
#include <vector>

#include "music/audio_clip.hpp"

namespace clothlab {

enum AudioBand : int { kLowBand = 0, kMidBand = 1, kHighBand = 2 };

struct BandEnergies {
  double hop_seconds = 0.0;  // frame k describes the window centred at k * hop_seconds
  // Per frame: amplitude of the low, mid and high band, each divided by its maximum over the
  // track (0..1; a band that is silent throughout stays 0).
  std::vector<std::array<float, 3>> frames;
};

struct BeatTrack {
  double bpm = 0.0;           // global tempo estimate; 0 when no beat was found (silence)
  std::vector<double> beats;  // beat times in seconds, ascending
  BandEnergies bands;
};

// Analyses a clip. Silence (or a clip shorter than one window) gives bpm 0 and no beats.
BeatTrack track_beats(const AudioClip& clip);

// The level of `band` at time t (seconds): linear interpolation between frames, clamped to the
// first and last frame outside them; 0 with no frames.
double band_level(const BandEnergies& bands, double t, int band);

// Musical time at t: beat index plus the fraction of the way to the next beat (beats[i] maps to
// i), piecewise linear between beats and extrapolated with the first or last interval outside
// them. With fewer than two beats there is no interval, and the result is 0.
double beat_phase(const std::vector<double>& beats, double t);

}  // namespace clothlab
