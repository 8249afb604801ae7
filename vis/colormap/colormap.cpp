#include "vis/colormap/colormap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace clothlab::vis {

namespace {

constexpr std::array<std::string_view, kAllColorMaps.size()> kColorMapNames{"viridis", "magma",
                                                                            "turbo", "coolwarm"};
constexpr std::array<std::string_view, 3> kRangeModeNames{"automatic", "fixed", "symmetric"};

// IEC 61966-2-1 sRGB transfer functions, as GL applies them to GL_SRGB8 texels and on writes to
// an sRGB framebuffer.
double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
double linear_to_srgb(double l) {
  return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

glm::dvec3 decode(Rgb8 c) {
  return {srgb_to_linear(c.r / 255.0), srgb_to_linear(c.g / 255.0), srgb_to_linear(c.b / 255.0)};
}

// Widens a degenerate range around centre c (see choose_range in the header).
ScalarRange widen(double c) {
  double h = 0.01 * std::abs(c);
  if (!(c + h > c - h)) h = 1.0;  // c = 0, or h lost in rounding
  return {c - h, c + h};
}

bool usable(ScalarRange r) {
  return std::isfinite(r.min) && std::isfinite(r.max) && r.max > r.min;
}

// Heckbert's nicenum: a 1, 2, 5 or 10 x 10^k close to x > 0, rounded or at least x.
double nice_number(double x, bool round) {
  const double k = std::floor(std::log10(x));
  const double f = x / std::pow(10.0, k);  // in [1, 10)
  double nice;
  if (round)
    nice = f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10;
  else
    nice = f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10;
  return nice * std::pow(10.0, k);
}

}  // namespace

std::span<const Rgb8, 256> colormap_table(ColorMap map) {
  return detail::kColorMapTables[static_cast<std::size_t>(map)];
}

std::string_view colormap_name(ColorMap map) {
  return kColorMapNames[static_cast<std::size_t>(map)];
}

std::optional<ColorMap> parse_colormap(std::string_view name) {
  for (ColorMap m : kAllColorMaps)
    if (colormap_name(m) == name) return m;
  return std::nullopt;
}

bool is_diverging(ColorMap map) {
  return map == ColorMap::coolwarm;
}

glm::vec3 colormap_sample(ColorMap map, double t) {
  const auto table = colormap_table(map);
  t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  // GL_LINEAR at u = (0.5 + 255 t) / 256 weighs texel centres: texel coordinate u * 256 - 0.5.
  const double x = 255.0 * t;
  const int i0 = std::min(static_cast<int>(std::floor(x)), 254);
  const double w = x - i0;
  const glm::dvec3 lin = (1.0 - w) * decode(table[i0]) + w * decode(table[i0 + 1]);
  return {float(linear_to_srgb(lin.r)), float(linear_to_srgb(lin.g)), float(linear_to_srgb(lin.b))};
}

std::string_view range_mode_name(RangeMode mode) {
  return kRangeModeNames[static_cast<std::size_t>(mode)];
}

std::optional<RangeMode> parse_range_mode(std::string_view name) {
  for (std::size_t i = 0; i < kRangeModeNames.size(); ++i)
    if (kRangeModeNames[i] == name) return static_cast<RangeMode>(i);
  return std::nullopt;
}

ScalarRange choose_range(RangeMode mode, std::span<const float> values, ScalarRange fixed) {
  if (mode == RangeMode::fixed) {
    if (usable(fixed)) return fixed;
    const bool finite = std::isfinite(fixed.min) && std::isfinite(fixed.max);
    return widen(finite ? 0.5 * (fixed.min + fixed.max) : 0.0);
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (float v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, double(v));
    hi = std::max(hi, double(v));
  }
  if (lo > hi) return widen(0.0);  // nothing finite
  if (mode == RangeMode::symmetric) {
    const double a = std::max(-lo, hi);
    return a > 0.0 ? ScalarRange{-a, a} : widen(0.0);
  }
  return hi > lo ? ScalarRange{lo, hi} : widen(lo);
}

double normalise(double value, ScalarRange range) {
  return (value - range.min) / (range.max - range.min);
}

double nice_step(double lo, double hi, int target) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && hi > lo)) return 0.0;
  const int intervals = std::max(target, 2) - 1;
  return nice_number(nice_number(hi - lo, false) / intervals, true);
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  const double step = nice_step(lo, hi, target);
  if (!(step > 0.0)) return {};
  // Ticks are k * m * 10^e with m in {1, 2, 5}; building them from integers and dividing by an
  // exact power of ten gives 0.6 rather than 3 * 0.2 = 0.6000000000000001.
  const int e = static_cast<int>(std::floor(std::log10(step) + 1e-9));
  const double m = std::round(step / std::pow(10.0, e));
  const double scale = std::pow(10.0, std::abs(e));
  const auto tick = [&](double k) { return e >= 0 ? k * m * scale : k * m / scale; };
  // A relative tolerance keeps a bound that is itself a tick (0 and 1 in [0, 1]).
  const double k_lo = std::ceil(lo / step - 1e-9), k_hi = std::floor(hi / step + 1e-9);
  std::vector<double> ticks;
  for (double k = k_lo; k <= k_hi && ticks.size() < 1000; ++k)
    ticks.push_back(std::clamp(tick(k), lo, hi));
  return ticks;
}

std::string format_tick(double value, double step) {
  char buf[64];
  if (!(step > 0.0) || !std::isfinite(step) || !std::isfinite(value)) {
    std::snprintf(buf, sizeof buf, "%g", value);
    return buf;
  }
  if (std::abs(value) < 1e-9 * step) value = 0.0;  // rounding residue of a zero tick
  const int e = static_cast<int>(std::floor(std::log10(step) + 1e-9));
  const double magnitude = std::max(std::abs(value), step);
  if (step >= 1e-4 && magnitude < 1e6) {
    // Decimals of the step's leading digit, more when the step has further digits (2.5).
    int decimals = std::max(0, -e);
    while (decimals < 12) {
      const double scaled = step * std::pow(10.0, decimals);
      if (std::abs(scaled - std::round(scaled)) <= 1e-6 * scaled) break;
      ++decimals;
    }
    std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  } else if (value == 0.0) {
    return "0";
  } else {
    const int lead = static_cast<int>(std::floor(std::log10(magnitude)));
    std::snprintf(buf, sizeof buf, "%.*e", std::clamp(lead - e, 0, 15), value);
  }
  std::string s = buf;
  // A negative value that rounds to zero at this precision prints as "0.0", never "-0.0".
  const std::string_view mantissa = std::string_view(s).substr(0, s.find('e'));
  if (s.front() == '-' && mantissa.find_first_of("123456789") == std::string_view::npos)
    s.erase(0, 1);
  return s;
}

}  // namespace clothlab::vis
