#include "sim/forces/wind.hpp"

#include <cmath>

namespace clothlab {
namespace {

// SplitMix64 finaliser: a well-mixed hash of (seed, lattice cell).
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double lattice_value(std::uint64_t seed, std::int64_t cell) {
  const std::uint64_t h = mix(seed * 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(cell));
  return static_cast<double>(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;  // [-1, 1)
}

double value_noise(std::uint64_t seed, double s) {
  const double cell = std::floor(s);
  const double f = s - cell;
  const double w = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);  // Perlin's quintic fade
  const auto c = static_cast<std::int64_t>(cell);
  const double a = lattice_value(seed, c), b = lattice_value(seed, c + 1);
  return a + (b - a) * w;
}

}  // namespace

double gust_noise(std::uint64_t seed, double s) {
  return (2.0 / 3.0) * value_noise(seed, s) + (1.0 / 3.0) * value_noise(seed + 1, 2.17 * s + 0.5);
}

}  // namespace clothlab
