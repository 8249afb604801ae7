#include "music/beat_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/FFT>

namespace clothlab {
namespace {

// Tempo search range and prior (Ellis 2007, section 3.1: log-Gaussian weight on the
// autocorrelation centred on tau0 = 0.5 s, against octave errors). Ellis uses sigma = 1.4
// octaves; 1.0 (librosa's default) is needed for a kick-snare pattern, whose autocorrelation is
// strongest at two beats (snare on 2 and 4), to be counted in beats rather than half-bars.
constexpr double kMinBpm = 60.0, kMaxBpm = 200.0;
constexpr double kPriorPeriodS = 0.5, kPriorOctaves = 1.0;
// Local tempo: windows of this length every kLocalStepS; weighted around the global period with a
// narrow prior so a window never jumps to the half or double tempo (0.5 octave: weight 0.14 at
// a factor of 2, 0.87 at a 20% tempo change).
constexpr double kLocalWindowS = 6.0, kLocalStepS = 1.0, kLocalOctaves = 0.5;
// Ellis 2007, eq. 3: how strongly the DP holds beat intervals to the local period, on an onset
// envelope of unit standard deviation (librosa's default "tightness").
constexpr double kTightness = 100.0;
// Log compression of magnitudes before the flux, log(1 + gamma |X|) (Bello et al. 2005,
// section 3.1; Klapuri 1999): |X| is the amplitude of a sinusoid, so gamma = 1000 puts the knee
// at -60 dBFS and quiet onsets still count.
constexpr float kLogGamma = 1000.0f;

struct Spectrogram {
  double frame_rate = 0.0;  // frames per second
  std::vector<float> flux;  // half-wave-rectified spectral flux per frame
  BandEnergies bands;
  bool silent = true;
};

// The power of two nearest to 23.2 ms of samples: 1024 at 44.1 and 48 kHz. Long enough for
// ~43 Hz bins (three bins below 150 Hz), short enough to place onsets to a few ms.
int window_length(int sample_rate) {
  const double target = 0.0232 * sample_rate;
  int n = 64;
  while (std::abs(2.0 * n - target) < std::abs(n - target)) n *= 2;
  return n;
}

// STFT with centred frames (frame k covers samples k hop +- n/2, zero outside the clip), band
// amplitudes and spectral flux in one pass; only the previous frame's spectrum is kept.
Spectrogram analyse_spectrum(const AudioClip& clip) {
  Spectrogram out;
  const int n = window_length(clip.sample_rate), hop = n / 4, bins = n / 2 + 1;
  const long size = static_cast<long>(clip.samples.size());
  const long frames = size / hop + 1;
  out.frame_rate = static_cast<double>(clip.sample_rate) / hop;
  out.bands.hop_seconds = 1.0 / out.frame_rate;
  out.bands.frames.assign(static_cast<std::size_t>(frames), {0.0f, 0.0f, 0.0f});
  out.flux.assign(static_cast<std::size_t>(frames), 0.0f);

  std::vector<float> window(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)  // periodic Hann
    window[i] = static_cast<float>(0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * i / n));
  // A sinusoid of amplitude A under a Hann window peaks at A n / 4 in its bin.
  const float to_amplitude = 4.0f / static_cast<float>(n);
  const int low_end = static_cast<int>(std::ceil(150.0 * n / clip.sample_rate));
  const int mid_end = static_cast<int>(std::ceil(2000.0 * n / clip.sample_rate));

  Eigen::FFT<float> fft;
  fft.SetFlag(Eigen::FFT<float>::HalfSpectrum);
  std::vector<float> frame(static_cast<std::size_t>(n));
  std::vector<std::complex<float>> spectrum;
  std::vector<float> log_mag(static_cast<std::size_t>(bins)), prev_log_mag(log_mag.size());
  std::array<float, 3> band_max{0.0f, 0.0f, 0.0f};
  for (long k = 0; k < frames; ++k) {
    const long start = k * hop - n / 2;
    for (int i = 0; i < n; ++i) {
      const long s = start + i;
      frame[i] = (s >= 0 && s < size) ? clip.samples[static_cast<std::size_t>(s)] * window[i] : 0.f;
    }
    fft.fwd(spectrum, frame);
    std::array<float, 3> energy{0.0f, 0.0f, 0.0f};
    float flux = 0.0f;
    for (int b = 1; b < bins; ++b) {  // bin 0 is DC offset, not sound
      const float mag =
          std::sqrt(std::norm(spectrum[b])) * to_amplitude;  // no hypot: no overflow here
      energy[b < low_end ? 0 : (b < mid_end ? 1 : 2)] += mag * mag;
      log_mag[b] = std::log1p(kLogGamma * mag);
      flux += std::max(0.0f, log_mag[b] - prev_log_mag[b]);
    }
    std::swap(log_mag, prev_log_mag);
    if (k > 0) out.flux[k] = flux;  // frame 0 has no predecessor
    for (int band = 0; band < 3; ++band) {
      const float amplitude = std::sqrt(energy[band]);
      out.bands.frames[k][band] = amplitude;
      band_max[band] = std::max(band_max[band], amplitude);
    }
  }
  for (int band = 0; band < 3; ++band) {
    if (band_max[band] <= 0.0f) continue;
    for (auto& f : out.bands.frames) f[band] /= band_max[band];
  }
  // A full-scale sinusoid has amplitude 1; below 1e-6 (-120 dBFS) nothing is audible.
  out.silent = *std::max_element(band_max.begin(), band_max.end()) < 1e-6f;
  return out;
}

// Onset envelope: the flux minus its mean over the surrounding second (the adaptive threshold of
// Bello et al. 2005, section 4, with a mean instead of a median), divided by its standard
// deviation so the DP's tightness has a fixed meaning. Zero throughout for constant flux.
std::vector<float> onset_envelope(const std::vector<float>& flux, double frame_rate) {
  const long n = static_cast<long>(flux.size());
  const long half = std::max(1L, std::lround(0.5 * frame_rate));
  std::vector<double> prefix(static_cast<std::size_t>(n + 1), 0.0);
  for (long k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + flux[k];
  std::vector<float> o(flux.size());
  double sum_sq = 0.0;
  for (long k = 0; k < n; ++k) {
    const long lo = std::max(0L, k - half), hi = std::min(n, k + half + 1);
    const double v = flux[k] - (prefix[hi] - prefix[lo]) / static_cast<double>(hi - lo);
    o[k] = static_cast<float>(v);
    sum_sq += v * v;
  }
  const double sd = n > 0 ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0;
  if (!(sd > 1e-12)) return std::vector<float>(flux.size(), 0.0f);
  for (float& v : o) v = static_cast<float>(v / sd);
  return o;
}

// Unbiased autocorrelation r[l] = sum_k o[k] o[k + l] / (n - l) for l = 0..max_lag of o[0, n).
std::vector<double> autocorrelation(const float* o, long n, long max_lag) {
  max_lag = std::min(max_lag, n - 1);
  std::vector<double> r(static_cast<std::size_t>(std::max(0L, max_lag + 1)), 0.0);
  for (long l = 0; l <= max_lag; ++l) {
    double s = 0.0;
    for (long k = 0; k + l < n; ++k) s += static_cast<double>(o[k]) * o[k + l];
    r[l] = s / static_cast<double>(n - l);
  }
  return r;
}

// Offset of the vertex of the parabola through (-1, a), (0, b), (1, c), in [-0.5, 0.5]; the
// standard three-point peak interpolation.
double parabolic_offset(double a, double b, double c) {
  const double denom = a - 2.0 * b + c;
  if (!(denom < 0.0)) return 0.0;
  return std::clamp(0.5 * (a - c) / denom, -0.5, 0.5);
}

// The period (frames, sub-frame) of the strongest weighted autocorrelation peak with lag in
// [min_lag, max_lag]; the weight is log-Gaussian around prior_lag. 0 if there is no positive peak.
double pick_period(const std::vector<double>& r, double min_lag, double max_lag, double prior_lag,
                   double sigma_octaves) {
  const long lo = std::max(1L, static_cast<long>(std::ceil(min_lag)));
  const long hi = std::min(static_cast<long>(r.size()) - 2, static_cast<long>(max_lag));
  long best = -1;
  double best_score = 0.0;
  for (long l = lo; l <= hi; ++l) {
    if (!(r[l] > 0.0) || r[l] < r[l - 1] || r[l] < r[l + 1]) continue;
    const double octaves = std::log2(static_cast<double>(l) / prior_lag) / sigma_octaves;
    const double score = r[l] * std::exp(-0.5 * octaves * octaves);
    if (score > best_score) best_score = score, best = l;
  }
  if (best < 0) return 0.0;
  return static_cast<double>(best) + parabolic_offset(r[best - 1], r[best], r[best + 1]);
}

// Sharpens a period with the autocorrelation peaks at its multiples m = 2, 3, ... (an error of
// one frame at lag m P is an error of 1/m frame in P): least squares of peak_m = m P.
double refine_with_multiples(const std::vector<double>& r, double period) {
  double sum_mp = period, sum_mm = 1.0;
  const double first_peak = r[static_cast<std::size_t>(std::lround(period))];
  for (int m = 2;; ++m) {
    const long centre = std::lround(m * period);
    if (centre + 3 >= static_cast<long>(r.size())) break;
    long best = centre - 2;
    for (long l = centre - 1; l <= centre + 2; ++l)
      if (r[l] > r[best]) best = l;
    // Stop where the periodicity fades or drifts (a tempo change): no peak inside the window.
    if (r[best] < 0.3 * first_peak || r[best] < r[best - 1] || r[best] < r[best + 1]) break;
    const double peak = best + parabolic_offset(r[best - 1], r[best], r[best + 1]);
    sum_mp += m * peak;
    sum_mm += static_cast<double>(m) * m;
  }
  return sum_mp / sum_mm;
}

// Period (frames) at every frame from autocorrelations of overlapping windows, linearly
// interpolated between window centres.
std::vector<double> local_periods(const std::vector<float>& o, double frame_rate,
                                  double global_period) {
  const long n = static_cast<long>(o.size());
  const long win = std::lround(kLocalWindowS * frame_rate);
  const long step = std::max(1L, std::lround(kLocalStepS * frame_rate));
  const double min_lag = 60.0 / kMaxBpm * frame_rate, max_lag = 60.0 / kMinBpm * frame_rate;
  if (n <= win) return std::vector<double>(o.size(), global_period);
  std::vector<double> centres, periods;
  for (long start = 0;; start += step) {
    start = std::min(start, n - win);  // the last window ends at the clip's end
    const auto r = autocorrelation(o.data() + start, win, static_cast<long>(max_lag) + 2);
    const double p = pick_period(r, min_lag, max_lag, global_period, kLocalOctaves);
    centres.push_back(static_cast<double>(start) + 0.5 * win);
    periods.push_back(p > 0.0 ? p : global_period);
    if (start == n - win) break;
  }
  std::vector<double> out(o.size());
  std::size_t j = 0;
  for (long k = 0; k < n; ++k) {
    while (j + 1 < centres.size() && centres[j + 1] <= k) ++j;
    if (k <= centres.front())
      out[k] = periods.front();
    else if (j + 1 >= centres.size())
      out[k] = periods.back();
    else {
      const double f = (k - centres[j]) / (centres[j + 1] - centres[j]);
      out[k] = periods[j] + f * (periods[j + 1] - periods[j]);
    }
  }
  return out;
}

// Ellis 2007, eq. 3-4: C(t) = O(t) + max over tau in [t - 2P, t - P/2] of
// C(tau) - alpha (log((t - tau) / P))^2, with P the local period at t. A chain whose best
// predecessor scores below zero starts afresh. Returns beat frames in ascending order.
std::vector<long> dp_beat_frames(const std::vector<float>& o, const std::vector<double>& period) {
  const long n = static_cast<long>(o.size());
  std::vector<double> score(o.size()), log_d(static_cast<std::size_t>(n + 1), 0.0);
  std::vector<long> back(o.size(), -1);
  for (long d = 1; d <= n; ++d) log_d[d] = std::log(static_cast<double>(d));
  for (long t = 0; t < n; ++t) {
    const double p = period[t], log_p = std::log(p);
    const long lo = std::max(0L, t - std::lround(2.0 * p)), hi = t - std::lround(0.5 * p);
    double best = 0.0;
    for (long tau = lo; tau <= hi; ++tau) {
      const double x = log_d[t - tau] - log_p;
      const double v = score[tau] - kTightness * x * x;
      if (v > best) best = v, back[t] = tau;
    }
    score[t] = o[t] + best;
  }
  // Ellis 2007, section 3.2: backtrace from the largest C, which lies within a period of the
  // end (C only grows along a chain). The last of equal maxima, so a chain through a silent
  // outro reaches the end and trim_weak_beats decides where it stops.
  long last = 0;
  for (long t = 1; t < n; ++t)
    if (score[t] >= score[last]) last = t;
  std::vector<long> beats;
  for (long t = last; t >= 0; t = back[t]) beats.push_back(t);
  std::reverse(beats.begin(), beats.end());
  return beats;
}

// Drops leading and trailing beats on weak onsets (below half the RMS onset at the beats):
// the DP extends its chain into a quiet intro or outro where there is nothing to hit.
void trim_weak_beats(const std::vector<float>& o, std::vector<long>& beats) {
  if (beats.empty()) return;
  double sum_sq = 0.0;
  for (long b : beats) sum_sq += static_cast<double>(o[b]) * o[b];
  const double threshold = 0.5 * std::sqrt(sum_sq / static_cast<double>(beats.size()));
  auto strong = [&](long b) { return o[b] >= threshold; };
  const auto first = std::find_if(beats.begin(), beats.end(), strong);
  const auto last = std::find_if(beats.rbegin(), beats.rend(), strong).base();
  if (first >= last)
    beats.clear();
  else
    beats = std::vector<long>(first, last);
}

// Beat time in seconds from a beat frame: moves to the envelope's highest frame within +-2 frames
// (the DP may sit a frame off the peak when the period pulls), then interpolates the peak.
double refined_beat_time(const std::vector<float>& o, long frame, double frame_rate) {
  const long n = static_cast<long>(o.size());
  long peak = frame;
  for (long k = std::max(1L, frame - 2); k <= std::min(n - 2, frame + 2); ++k)
    if (o[k] > o[peak]) peak = k;
  double offset = 0.0;
  if (peak >= 1 && peak + 1 < n) offset = parabolic_offset(o[peak - 1], o[peak], o[peak + 1]);
  return (static_cast<double>(peak) + offset) / frame_rate;
}

}  // namespace

BeatTrack track_beats(const AudioClip& clip) {
  BeatTrack out;
  if (clip.sample_rate <= 0 || clip.samples.empty()) return out;
  Spectrogram spec = analyse_spectrum(clip);
  out.bands = std::move(spec.bands);
  if (spec.silent) return out;
  const std::vector<float> o = onset_envelope(spec.flux, spec.frame_rate);

  const double fps = spec.frame_rate;
  const double min_lag = 60.0 / kMaxBpm * fps, max_lag = 60.0 / kMinBpm * fps;
  const long n = static_cast<long>(o.size());
  // Up to four slowest periods for the refinement by multiples, at most half the envelope so
  // each lag still averages over many products.
  const auto r = autocorrelation(o.data(), n, std::min(std::lround(4.0 * max_lag), n / 2));
  double period = pick_period(r, min_lag, max_lag, kPriorPeriodS * fps, kPriorOctaves);
  if (period <= 0.0) return out;
  period = refine_with_multiples(r, period);
  out.bpm = 60.0 * fps / period;

  std::vector<long> frames = dp_beat_frames(o, local_periods(o, fps, period));
  trim_weak_beats(o, frames);
  for (long f : frames) out.beats.push_back(refined_beat_time(o, f, fps));
  return out;
}

double band_level(const BandEnergies& bands, double t, int band) {
  const auto& f = bands.frames;
  if (f.empty() || band < 0 || band > 2 || !(bands.hop_seconds > 0.0)) return 0.0;
  const double x = t / bands.hop_seconds;
  if (!(x > 0.0)) return f.front()[band];
  const double last = static_cast<double>(f.size() - 1);
  if (x >= last) return f.back()[band];
  const auto i = static_cast<std::size_t>(x);
  const double frac = x - static_cast<double>(i);
  return (1.0 - frac) * f[i][band] + frac * f[i + 1][band];
}

double beat_phase(const std::vector<double>& beats, double t) {
  const std::size_t n = beats.size();
  if (n < 2) return 0.0;
  if (t < beats.front()) return (t - beats[0]) / (beats[1] - beats[0]);
  if (t >= beats.back())
    return static_cast<double>(n - 1) + (t - beats[n - 1]) / (beats[n - 1] - beats[n - 2]);
  const auto it = std::upper_bound(beats.begin(), beats.end(), t);
  const auto i = static_cast<std::size_t>(it - beats.begin()) - 1;
  return static_cast<double>(i) + (t - beats[i]) / (beats[i + 1] - beats[i]);
}

}  // namespace clothlab
