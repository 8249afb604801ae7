#include "music/drum_track.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace clothlab {
namespace {

// xorshift32 (Marsaglia 2003, "Xorshift RNGs"): small, fast and the same on every platform,
// unlike std::uniform_real_distribution whose output is implementation-defined.
struct Xorshift32 {
  std::uint32_t state;
  explicit Xorshift32(unsigned seed) : state(seed * 2654435761u + 0x9E3779B9u) {
    if (state == 0) state = 1;
  }
  // Uniform in [-1, 1).
  float uniform() {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return static_cast<float>(state >> 8) * (2.0f / 16777216.0f) - 1.0f;
  }
};

constexpr double kTwoPi = 2.0 * std::numbers::pi;

AudioClip silence(double seconds, int sample_rate) {
  AudioClip clip;
  clip.sample_rate = sample_rate;
  clip.samples.assign(static_cast<std::size_t>(std::max(0.0, seconds) * sample_rate), 0.0f);
  return clip;
}

// Adds gain * sound(t) for t in [0, length) starting at `start` seconds; samples past the clip's
// end are dropped.
template <class Sound>
void add_sound(AudioClip& clip, double start, double length, double gain, Sound sound) {
  const auto first = static_cast<long>(std::ceil(start * clip.sample_rate));
  const auto count = static_cast<long>(length * clip.sample_rate);
  const auto size = static_cast<long>(clip.samples.size());
  for (long i = std::max(0L, first); i < std::min(size, first + count); ++i) {
    const double t = static_cast<double>(i) / clip.sample_rate - start;
    clip.samples[static_cast<std::size_t>(i)] += static_cast<float>(gain * sound(t));
  }
}

// Kick: a sine whose frequency falls exponentially from 150 to 50 Hz,
// f(t) = 50 + 100 exp(-t / 0.03), so its phase is 2 pi (50 t + 3 (1 - exp(-t / 0.03))).
void add_kick(AudioClip& clip, double start) {
  add_sound(clip, start, 0.5, 1.0, [](double t) {
    const double phase = kTwoPi * (50.0 * t + 100.0 * 0.03 * (1.0 - std::exp(-t / 0.03)));
    return std::sin(phase) * std::exp(-t / 0.12);
  });
}

// Snare: a noise burst (the wires) plus a 185 Hz tone (the shell), both decaying fast.
void add_snare(AudioClip& clip, double start, Xorshift32& rng) {
  add_sound(clip, start, 0.3, 0.7, [&rng](double t) {
    return 0.6 * rng.uniform() * std::exp(-t / 0.045) +
           0.5 * std::sin(kTwoPi * 185.0 * t) * std::exp(-t / 0.07);
  });
}

// Closed hi-hat: white noise through a first-order high-pass (RC filter, cut-off ~7 kHz at
// 44.1 kHz: y[n] = a (y[n-1] + x[n] - x[n-1])), decaying in ~15 ms.
void add_hihat(AudioClip& clip, double start, Xorshift32& rng) {
  const double rc = 1.0 / (kTwoPi * 7000.0);
  const double a = rc / (rc + 1.0 / clip.sample_rate);
  double x_prev = 0.0, y = 0.0;
  add_sound(clip, start, 0.06, 0.35, [&](double t) {
    const double x = rng.uniform();
    y = a * (y + x - x_prev);
    x_prev = x;
    return y * std::exp(-t / 0.015);
  });
}

void normalise_peak(AudioClip& clip, float peak) {
  float max_abs = 0.0f;
  for (float s : clip.samples) max_abs = std::max(max_abs, std::abs(s));
  if (max_abs <= 0.0f) return;
  for (float& s : clip.samples) s *= peak / max_abs;
}

std::vector<double> regular_beats(double bpm, double seconds, double first_beat_s) {
  std::vector<double> beats;
  if (bpm <= 0) return beats;
  for (long k = 0;; ++k) {
    const double t = first_beat_s + static_cast<double>(k) * 60.0 / bpm;
    if (t >= seconds) break;
    beats.push_back(t);
  }
  return beats;
}

}  // namespace

AudioClip make_drum_track(const std::vector<double>& beat_times, double seconds, int sample_rate,
                          unsigned seed) {
  AudioClip clip = silence(seconds, sample_rate);
  Xorshift32 rng(seed);
  for (std::size_t k = 0; k < beat_times.size(); ++k) {
    const double t = beat_times[k];
    add_kick(clip, t);
    if (k % 2 == 1) add_snare(clip, t, rng);  // beats 2 and 4 of each bar
    add_hihat(clip, t, rng);
    double interval = 0.0;
    if (k + 1 < beat_times.size())
      interval = beat_times[k + 1] - t;
    else if (k > 0)
      interval = t - beat_times[k - 1];
    if (interval > 0) add_hihat(clip, t + 0.5 * interval, rng);
  }
  normalise_peak(clip, 0.9f);
  return clip;
}

AudioClip make_drum_track(const DrumTrackSpec& spec) {
  return make_drum_track(regular_beats(spec.bpm, spec.seconds, 0.0), spec.seconds, spec.sample_rate,
                         spec.seed);
}

AudioClip make_click_track(const std::vector<double>& beat_times, double seconds, int sample_rate,
                           double noise_level) {
  AudioClip clip = silence(seconds, sample_rate);
  // Uniform noise in [-1, 1) has RMS 1/sqrt(3); scale it to the requested RMS.
  Xorshift32 rng(12345u);
  const float noise_gain = static_cast<float>(noise_level * std::sqrt(3.0));
  for (float& s : clip.samples) s = noise_gain * rng.uniform();
  for (double t : beat_times)
    add_sound(clip, t, 0.02, 0.8,
              [](double u) { return std::sin(kTwoPi * 1500.0 * u) * std::exp(-u / 0.004); });
  return clip;
}

AudioClip make_click_track(double bpm, double seconds, int sample_rate, double noise_level,
                           double first_beat_s) {
  return make_click_track(regular_beats(bpm, seconds, first_beat_s), seconds, sample_rate,
                          noise_level);
}

}  // namespace clothlab
