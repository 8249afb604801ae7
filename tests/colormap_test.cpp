// Colour maps (vis/colormap): the generated tables against published values, the GPU-equivalent
// sampling, value ranges and colour-bar ticks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "vis/colormap/colormap.hpp"

namespace clothlab::vis {
namespace {

constexpr double kByte = 1.0 / 255.0;

void expect_entry(ColorMap map, int k, Rgb8 want) {
  const Rgb8 got = colormap_table(map)[k];
  EXPECT_EQ(got.r, want.r) << colormap_name(map) << " entry " << k;
  EXPECT_EQ(got.g, want.g) << colormap_name(map) << " entry " << k;
  EXPECT_EQ(got.b, want.b) << colormap_name(map) << " entry " << k;
}

void expect_sample(ColorMap map, double t, Rgb8 want, double tolerance) {
  const glm::vec3 c = colormap_sample(map, t);
  EXPECT_NEAR(c.r, want.r / 255.0, tolerance) << colormap_name(map) << " t = " << t;
  EXPECT_NEAR(c.g, want.g / 255.0, tolerance) << colormap_name(map) << " t = " << t;
  EXPECT_NEAR(c.b, want.b / 255.0, tolerance) << colormap_name(map) << " t = " << t;
}

// Published 256-entry values: matplotlib's _cm_listed.py, whose viridis and magma come from
// BIDS/colormap (viridis starts #440154, has #21918c at 128 and ends #fde725; magma #000004,
// #b73779, #fcfdbf) and whose turbo is Google's (Mikhailov 2019: #30123b, #a4fc3c, #7a0403).
TEST(ColorMapTables, MatchPublishedValues) {
  expect_entry(ColorMap::viridis, 0, {68, 1, 84});
  expect_entry(ColorMap::viridis, 128, {33, 145, 140});
  expect_entry(ColorMap::viridis, 255, {253, 231, 37});
  expect_entry(ColorMap::magma, 0, {0, 0, 4});
  expect_entry(ColorMap::magma, 128, {183, 55, 121});
  expect_entry(ColorMap::magma, 255, {252, 253, 191});
  expect_entry(ColorMap::turbo, 0, {48, 18, 59});
  expect_entry(ColorMap::turbo, 128, {164, 252, 60});
  expect_entry(ColorMap::turbo, 255, {122, 4, 3});
}

// Moreland, "Diverging color maps for scientific visualization" (2009), table of the cool to
// warm map: (59,76,192) at 0, (221,221,221) at 0.5, (180,4,38) at 1.
TEST(ColorMapTables, CoolwarmMatchesMoreland2009) {
  expect_entry(ColorMap::coolwarm, 0, {59, 76, 192});
  expect_entry(ColorMap::coolwarm, 255, {180, 4, 38});
  expect_sample(ColorMap::coolwarm, 0.5, {221, 221, 221}, kByte);
  EXPECT_TRUE(is_diverging(ColorMap::coolwarm));
  EXPECT_FALSE(is_diverging(ColorMap::viridis));
}

// A texel centre (t = k / 255) shows the texel itself.
TEST(ColorMapSample, TexelCentresShowTheirEntries) {
  for (ColorMap map : kAllColorMaps)
    for (int k = 0; k < 256; ++k) expect_sample(map, k / 255.0, colormap_table(map)[k], kByte);
}

TEST(ColorMapSample, ClampsOutOfRangeAndNaN) {
  for (ColorMap map : kAllColorMaps) {
    const auto table = colormap_table(map);
    expect_sample(map, -3.0, table[0], 1e-6);
    expect_sample(map, 7.0, table[255], 1e-6);
    expect_sample(map, std::numeric_limits<double>::quiet_NaN(), table[0], 1e-6);
  }
}

// Halfway between two texels GL mixes them in linear light, which is darker than the sRGB mean
// wherever the entries differ: check against a hand computation for viridis entries 0 and 1.
TEST(ColorMapSample, InterpolatesInLinearLight) {
  const auto decode = [](double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const auto encode = [](double l) {
    return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
  };
  const auto table = colormap_table(ColorMap::viridis);
  const double want_b = encode(0.5 * (decode(table[0].b / 255.0) + decode(table[1].b / 255.0)));
  EXPECT_NEAR(colormap_sample(ColorMap::viridis, 0.5 / 255.0).b, want_b, 1e-6);
}

// CIE L* of an sRGB byte colour: IEC 61966-2-1 decoding, Y from the sRGB -> XYZ (D65) matrix,
// then L* = 116 f(Y / Yn) - 16 (CIE 15:2004).
double lightness(Rgb8 c) {
  const auto decode = [](int v) {
    const double s = v / 255.0;
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
  };
  const double y = 0.2126729 * decode(c.r) + 0.7151522 * decode(c.g) + 0.0721750 * decode(c.b);
  constexpr double d = 6.0 / 29.0;
  const double f = y > d * d * d ? std::cbrt(y) : y / (3 * d * d) + 4.0 / 29.0;
  return 116.0 * f - 16.0;
}

// Viridis and magma are perceptually uniform sequential maps: lightness rises along them. The
// 8-bit viridis table is not strictly monotonic between neighbours, though matplotlib's float
// table is: byte rounding makes entries 112 and 113 (and 129 and 130) the same colour and makes
// 95 and 146 0.03 L* darker than the entry before (one byte less red or blue at equal green).
// So: neighbours never fall by more than that rounding, and every second entry is lighter.
TEST(ColorMapLightness, ViridisRises) {
  const auto table = colormap_table(ColorMap::viridis);
  for (int k = 0; k + 1 < 256; ++k)
    EXPECT_GT(lightness(table[k + 1]), lightness(table[k]) - 0.05) << "entry " << k;
  for (int k = 0; k + 2 < 256; ++k)
    EXPECT_GT(lightness(table[k + 2]), lightness(table[k])) << "entry " << k;
  EXPECT_GT(lightness(table[255]) - lightness(table[0]), 70.0);
}

TEST(ColorMapLightness, MagmaRisesStrictly) {
  const auto table = colormap_table(ColorMap::magma);
  for (int k = 0; k + 1 < 256; ++k)
    EXPECT_GT(lightness(table[k + 1]), lightness(table[k])) << "entry " << k;
}

TEST(ColorMapNames, RoundTrip) {
  for (ColorMap map : kAllColorMaps) EXPECT_EQ(parse_colormap(colormap_name(map)), map);
  EXPECT_EQ(colormap_name(ColorMap::viridis), "viridis");
  EXPECT_EQ(colormap_name(ColorMap::coolwarm), "coolwarm");
  EXPECT_EQ(parse_colormap("jet"), std::nullopt);
  EXPECT_EQ(parse_colormap("Viridis"), std::nullopt);
  EXPECT_EQ(parse_colormap(""), std::nullopt);
  for (RangeMode mode : {RangeMode::automatic, RangeMode::fixed, RangeMode::symmetric})
    EXPECT_EQ(parse_range_mode(range_mode_name(mode)), mode);
  EXPECT_EQ(range_mode_name(RangeMode::symmetric), "symmetric");
  EXPECT_EQ(parse_range_mode("manual"), std::nullopt);
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(ChooseRange, AutomaticIgnoresNonFinite) {
  const std::vector<float> v{kNaN, 2.0f, -kInf, -1.5f, kInf, 0.5f};
  const ScalarRange r = choose_range(RangeMode::automatic, v, {});
  EXPECT_EQ(r.min, -1.5);
  EXPECT_EQ(r.max, 2.0);
  EXPECT_DOUBLE_EQ(normalise(-1.5, r), 0.0);
  EXPECT_DOUBLE_EQ(normalise(2.0, r), 1.0);
  EXPECT_DOUBLE_EQ(normalise(5.5, r), 2.0);  // not clamped
}

TEST(ChooseRange, SymmetricIsCentred) {
  const std::vector<float> v{0.25f, -3.0f, kNaN, 1.0f};
  const ScalarRange r = choose_range(RangeMode::symmetric, v, {});
  EXPECT_EQ(r.min, -3.0);
  EXPECT_EQ(r.max, 3.0);
  EXPECT_DOUBLE_EQ(normalise(0.0, r), 0.5);
  const std::vector<float> positive{1.0f, 2.0f};
  EXPECT_EQ(choose_range(RangeMode::symmetric, positive, {}).min, -2.0);
}

TEST(ChooseRange, FixedPassesThrough) {
  const std::vector<float> v{100.0f, -100.0f};
  const ScalarRange r = choose_range(RangeMode::fixed, v, {-0.02, 0.05});
  EXPECT_EQ(r.min, -0.02);
  EXPECT_EQ(r.max, 0.05);
}

TEST(ChooseRange, DegenerateWidens) {
  const auto check = [](ScalarRange r, double centre) {
    EXPECT_GT(r.max, r.min);
    EXPECT_TRUE(std::isfinite(r.min) && std::isfinite(r.max));
    EXPECT_NEAR(normalise(centre, r), 0.5, 1e-12);
  };
  const std::vector<float> constant{4.0f, 4.0f, kNaN};
  check(choose_range(RangeMode::automatic, constant, {}), 4.0);
  const std::vector<float> zeros{0.0f, 0.0f};
  check(choose_range(RangeMode::automatic, zeros, {}), 0.0);
  check(choose_range(RangeMode::symmetric, zeros, {}), 0.0);
  const std::vector<float> none{kNaN, kInf};
  check(choose_range(RangeMode::automatic, none, {}), 0.0);
  check(choose_range(RangeMode::symmetric, {}, {}), 0.0);
  check(choose_range(RangeMode::fixed, {}, {2.0, 2.0}), 2.0);
  check(choose_range(RangeMode::fixed, {}, {3.0, 1.0}), 2.0);
}

// Every tick lies in [lo, hi] and is an integer multiple of a step 1, 2 or 5 x 10^k.
void expect_nice(const std::vector<double>& ticks, double lo, double hi) {
  ASSERT_GE(ticks.size(), 2u);
  const double step = ticks[1] - ticks[0];
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
              std::abs(mantissa - 5) < 1e-9)
      << "step " << step;
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    EXPECT_GE(ticks[i], lo);
    EXPECT_LE(ticks[i], hi);
    EXPECT_NEAR(ticks[i] / step, std::round(ticks[i] / step), 1e-9);
    if (i > 0) {
      EXPECT_NEAR(ticks[i] - ticks[i - 1], step, 1e-12 * std::abs(hi - lo));
    }
  }
}

TEST(NiceTicks, UnitRange) {
  const std::vector<double> ticks = nice_ticks(0.0, 1.0, 5);
  const std::vector<double> want{0.0, 0.2, 0.4, 0.6, 0.8, 1.0};
  ASSERT_EQ(ticks.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_DOUBLE_EQ(ticks[i], want[i]);
  EXPECT_EQ(format_tick(ticks[3], 0.2), "0.6");
}

TEST(NiceTicks, AwkwardRangesStayInside) {
  const std::vector<double> ticks = nice_ticks(-0.013, 0.027, 5);
  expect_nice(ticks, -0.013, 0.027);
  EXPECT_NEAR(ticks.front(), -0.01, 1e-15);
  EXPECT_NEAR(ticks.back(), 0.02, 1e-15);
  expect_nice(nice_ticks(3.7, 1234.5, 6), 3.7, 1234.5);
  expect_nice(nice_ticks(-2e-7, 9e-7, 4), -2e-7, 9e-7);
  expect_nice(nice_ticks(-5.0, 5.0, 7), -5.0, 5.0);
  EXPECT_LE(nice_ticks(0.0, 1.0, 5).size(), 11u);
}

TEST(NiceTicks, EmptyOrNonFiniteRangeHasNone) {
  EXPECT_TRUE(nice_ticks(1.0, 1.0, 5).empty());
  EXPECT_TRUE(nice_ticks(2.0, 1.0, 5).empty());
  EXPECT_TRUE(nice_ticks(0.0, std::numeric_limits<double>::infinity(), 5).empty());
}

TEST(FormatTick, DecimalsFollowTheStep) {
  EXPECT_EQ(format_tick(0.4, 0.2), "0.4");
  EXPECT_EQ(format_tick(0.15, 0.05), "0.15");
  EXPECT_EQ(format_tick(-0.01, 0.01), "-0.01");
  EXPECT_EQ(format_tick(1200.0, 200.0), "1200");
  EXPECT_EQ(format_tick(7.5, 2.5), "7.5");
}

TEST(FormatTick, NoNegativeZero) {
  EXPECT_EQ(format_tick(-0.0, 0.2), "0.0");
  EXPECT_EQ(format_tick(-1e-17, 0.2), "0.0");  // 3 * 0.2 - 0.6 style residue
  EXPECT_EQ(format_tick(-0.0, 1.0), "0");
  EXPECT_EQ(format_tick(-0.0, 1e-7), "0");
  for (double v : nice_ticks(-1.0, 1.0, 5)) EXPECT_NE(format_tick(v, 0.5), "-0.0");
}

TEST(FormatTick, ScientificForTinySteps) {
  const std::string s = format_tick(3e-7, 1e-7);
  EXPECT_NE(s.find('e'), std::string::npos) << s;
  EXPECT_DOUBLE_EQ(std::stod(s), 3e-7);
}

}  // namespace
}  // namespace clothlab::vis
