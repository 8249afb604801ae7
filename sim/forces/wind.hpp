// Wind with deterministic gusts. The wind velocity at time t and position x is
//   w(t, x) = W (1 + gust * g((t - (x . W^) / |W|) / period)),
// a gust field that travels with the mean wind W, so a flag ripples instead of breathing.
// g is seeded value noise in [-1, 1]: the same seed gives the same gusts, so traces repeat.
// Force on vertex i (a linear pressure model on the cloth's surface normal):
//   F_i = coefficient * A_i * ((w - v_i) . n_i) n_i,
// with A_i a third of the area of the triangles around i and n_i their area-weighted normal.
#pragma once

#include <cmath>
#include <cstdint>

#include "sim/scene/scene.hpp"

namespace clothlab {

namespace detail {

// SplitMix64 finaliser: a well-mixed hash of (seed, lattice cell).
inline std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

inline double lattice_value(std::uint64_t seed, std::int64_t cell) {
  const std::uint64_t h = mix(seed * 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(cell));
  return static_cast<double>(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;  // [-1, 1)
}

// The lattice values at the ends of the last cell looked up: neighbouring vertices almost always
// share a cell, so a sweep over a block hashes only when the cell changes.
struct LatticeCache {
  std::int64_t cell = INT64_MIN;
  double a = 0.0, b = 0.0;
};

inline double value_noise(std::uint64_t seed, double s, LatticeCache& cache) {
  const double cell = std::floor(s);
  const double f = s - cell;
  const double w = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);  // Perlin's quintic fade
  const auto c = static_cast<std::int64_t>(cell);
  if (c != cache.cell) {
    cache.cell = c;
    cache.a = lattice_value(seed, c);
    cache.b = lattice_value(seed, c + 1);
  }
  return cache.a + (cache.b - cache.a) * w;
}

}  // namespace detail

// Caches for the two octaves of gust_noise.
struct GustCache {
  detail::LatticeCache octave[2];
};

// Seeded smooth noise in [-1, 1] (quintic-interpolated value noise, two octaves).
inline double gust_noise(std::uint64_t seed, double s, GustCache& cache) {
  return (2.0 / 3.0) * detail::value_noise(seed, s, cache.octave[0]) +
         (1.0 / 3.0) * detail::value_noise(seed + 1, 2.17 * s + 0.5, cache.octave[1]);
}
inline double gust_noise(std::uint64_t seed, double s) {
  GustCache cache;
  return gust_noise(seed, s, cache);
}

// The wind field with its per-scene constants worked out once.
class WindField {
 public:
  explicit WindField(const WindSpec& spec) : spec_(spec) {
    const Vec3d& w = spec.velocity;
    speed_ = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    if (speed_ > 0.0)
      for (int a = 0; a < 3; ++a) lag_[a] = w[a] / (speed_ * speed_);  // W^ / |W|
  }

  // The factor (1 + gust g(...)) by which the mean wind is scaled at time t and position p.
  double factor(double t, double px, double py, double pz, GustCache& cache) const {
    const double s = (t - (px * lag_[0] + py * lag_[1] + pz * lag_[2])) / spec_.gust_period;
    return 1.0 + spec_.gust * gust_noise(spec_.seed, s, cache);
  }
  Vec3d velocity(double t, const Vec3d& p) const {
    if (speed_ == 0.0) return {0.0, 0.0, 0.0};
    GustCache cache;
    const double k = factor(t, p[0], p[1], p[2], cache);
    return {spec_.velocity[0] * k, spec_.velocity[1] * k, spec_.velocity[2] * k};
  }
  const WindSpec& spec() const { return spec_; }
  const double* lag() const { return lag_; }  // W / |W|^2, s/m (zero in calm air)
  bool calm() const { return speed_ == 0.0; }
  bool steady() const { return spec_.gust == 0.0; }  // factor() is 1 everywhere

 private:
  WindSpec spec_;
  double speed_ = 0.0;
  double lag_[3] = {0.0, 0.0, 0.0};
};

}  // namespace clothlab
