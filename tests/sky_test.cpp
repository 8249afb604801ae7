// Preetham sky baked to a cube map (vis/sky): GL cube map orientation, sun position, seamless
// face edges, colour and brightness trends, finite non-negative values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <utility>

#include "vis/sky/preetham_sky.hpp"

namespace clothlab::vis {
namespace {

float degrees_between(glm::vec3 a, glm::vec3 b) {
  const float c = glm::dot(glm::normalize(a), glm::normalize(b));
  return std::acos(std::clamp(c, -1.0f, 1.0f)) * 180.0f / std::numbers::pi_v<float>;
}

glm::vec3 from_elevation_azimuth(float elevation_deg, float azimuth_deg) {
  const float e = elevation_deg * std::numbers::pi_v<float> / 180.0f,
              a = azimuth_deg * std::numbers::pi_v<float> / 180.0f;
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

// Face selection and (s, t) exactly as written in the OpenGL 4.5 core specification, table
// 8.19 (independent of cube_direction): the major axis picks the face; sc, tc per face.
struct FaceST {
  int face;
  float s, t;  // [0, 1]
};
FaceST gl_select(glm::vec3 r) {
  const float ax = std::abs(r.x), ay = std::abs(r.y), az = std::abs(r.z);
  int face;
  float sc, tc, ma;
  if (ax >= ay && ax >= az) {
    face = r.x > 0 ? 0 : 1;
    sc = r.x > 0 ? -r.z : r.z;
    tc = -r.y;
    ma = ax;
  } else if (ay >= az) {
    face = r.y > 0 ? 2 : 3;
    sc = r.x;
    tc = r.y > 0 ? r.z : -r.z;
    ma = ay;
  } else {
    face = r.z > 0 ? 4 : 5;
    sc = r.z > 0 ? r.x : -r.x;
    tc = -r.y;
    ma = az;
  }
  return {face, 0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)};
}

glm::vec3 texel(const CubeFaces& c, int face, int i, int j) {
  const float* p = c.rgb[face].data() + 3 * (std::size_t(j) * c.size + i);
  return {p[0], p[1], p[2]};
}

float texel_centre(int i, int size) {
  return 2.0f * (float(i) + 0.5f) / float(size) - 1.0f;
}

TEST(SkyTest, CubeDirectionsFollowTheGlTable) {
  const glm::vec3 centre[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  // Direction in which s and t increase on each face (GL spec table 8.19).
  const glm::vec3 s_dir[6] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
  const glm::vec3 t_dir[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                              {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  for (int f = 0; f < 6; ++f) {
    EXPECT_NEAR(glm::distance(cube_direction(f, 0, 0), centre[f]), 0.0f, 1e-6f) << "face " << f;
    const glm::vec3 ds = cube_direction(f, 0.1f, 0) - cube_direction(f, -0.1f, 0);
    const glm::vec3 dt = cube_direction(f, 0, 0.1f) - cube_direction(f, 0, -0.1f);
    EXPECT_GT(glm::dot(glm::normalize(ds), s_dir[f]), 0.999f) << "face " << f;
    EXPECT_GT(glm::dot(glm::normalize(dt), t_dir[f]), 0.999f) << "face " << f;
  }
  // Round trip through the spec's selection rule at random (s, t).
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-0.999f, 0.999f);
  for (int k = 0; k < 600; ++k) {
    const int f = k % 6;
    const float s = u(rng), t = u(rng);
    const glm::vec3 d = cube_direction(f, s, t);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
    const FaceST sel = gl_select(d);
    EXPECT_EQ(sel.face, f);
    EXPECT_NEAR(2.0f * sel.s - 1.0f, s, 1e-5f);
    EXPECT_NEAR(2.0f * sel.t - 1.0f, t, 1e-5f);
  }
}

TEST(SkyTest, BakedTexelsAreTheSkyAtTheirCentres) {
  // Without the disc at a coarse size on every face, and with it (1 degree, wider than a texel
  // at 128, so not widened) on the face holding the sun.
  for (const auto& [n, disc] : {std::pair{8, false}, std::pair{128, true}}) {
    SkyParams p;
    p.draw_sun_disc = disc;
    p.sun_direction = from_elevation_azimuth(20, 80);  // +Z face
    const CubeFaces c = bake_sky(p, n);
    ASSERT_EQ(c.size, n);
    for (int f = 0; f < 6; ++f) {
      ASSERT_EQ(c.rgb[f].size(), std::size_t(3 * n * n));
      if (disc && f != 4) continue;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const glm::vec3 want =
              sky_radiance(p, cube_direction(f, texel_centre(i, n), texel_centre(j, n)));
          ASSERT_NEAR(glm::distance(texel(c, f, i, j), want), 0.0f,
                      1e-6f * (1 + glm::length(want)));
        }
    }
  }
}

TEST(SkyTest, BrightestTexelIsTowardsTheSun) {
  const int n = 64;
  const glm::vec3 suns[] = {from_elevation_azimuth(35, 60), from_elevation_azimuth(70, 200),
                            from_elevation_azimuth(8, -30), from_elevation_azimuth(45, 45),
                            glm::vec3(0.0f, 1.0f, 0.0f)};
  for (bool disc : {true, false}) {
    for (const glm::vec3& sun : suns) {
      SkyParams p;
      p.sun_direction = sun;
      p.draw_sun_disc = disc;
      const CubeFaces c = bake_sky(p, n);
      float best = -1.0f;
      glm::vec3 best_dir(0.0f);
      for (int f = 0; f < 6; ++f)
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) {
            const glm::vec3 v = texel(c, f, i, j);
            const float lum = 0.2126f * v.r + 0.7152f * v.g + 0.0722f * v.b;
            if (lum > best) {
              best = lum;
              best_dir = cube_direction(f, texel_centre(i, n), texel_centre(j, n));
            }
          }
      const float off = degrees_between(best_dir, sun);
      std::printf("sun (%.2f %.2f %.2f) disc %d: brightest texel luminance %.3f, %.2f deg off\n",
                  sun.x, sun.y, sun.z, int(disc), best, off);
      EXPECT_LT(off, 3.0f);
      if (!disc) {
        // Automatic exposure: the brightest sky (no disc) is about 1.
        EXPECT_GT(best, 0.8f);
        EXPECT_LT(best, 1.25f);
      }
    }
  }
}

TEST(SkyTest, AutomaticExposureMakesTheBrightestSkyAboutOne) {
  const int n = 48;
  for (float turbidity : {2.0f, 3.0f, 6.0f, 9.0f}) {
    for (float elevation : {5.0f, 30.0f, 60.0f, 85.0f}) {
      SkyParams p;
      p.turbidity = turbidity;
      p.sun_direction = from_elevation_azimuth(elevation, 20);
      p.draw_sun_disc = false;
      const CubeFaces c = bake_sky(p, n);
      float best = 0.0f;
      for (int f = 0; f < 6; ++f)
        for (std::size_t k = 0; k < c.rgb[f].size(); k += 3)
          best = std::max(
              best, 0.2126f * c.rgb[f][k] + 0.7152f * c.rgb[f][k + 1] + 0.0722f * c.rgb[f][k + 2]);
      std::printf("T=%.0f sun %2.0f deg: brightest texel luminance %.3f\n", turbidity, elevation,
                  best);
      EXPECT_GT(best, 0.8f);
      EXPECT_LE(best, 1.01f);
    }
  }
}

TEST(SkyTest, NoSeamAcrossFaceEdges) {
  const int n = 64;
  SkyParams p;
  p.sun_direction = from_elevation_azimuth(30, 80);  // inside the +Z face
  const CubeFaces c = bake_sky(p, n);
  const float texel_deg = 90.0f / n;
  float worst_rel = 0.0f, worst_rel_inside = 0.0f, worst_angle = 0.0f;
  int pairs = 0;
  for (int f = 0; f < 6; ++f) {
    for (int k = 0; k < n; ++k) {
      // The four edges: (i, j) on the edge and the step that leaves the face.
      const int edge[4][4] = {{0, k, -1, 0}, {n - 1, k, 1, 0}, {k, 0, 0, -1}, {k, n - 1, 0, 1}};
      for (const auto& e : edge) {
        const int i = e[0], j = e[1];
        // A point half a texel beyond the edge lies in the neighbouring face's edge texel.
        const float s = texel_centre(i, n) + e[2] * 2.0f / n;
        const float t = texel_centre(j, n) + e[3] * 2.0f / n;
        // cube_direction takes coordinates past the face's edge too: the direction goes on
        // into the neighbouring face.
        const glm::vec3 d = cube_direction(f, s, t);
        const FaceST sel = gl_select(d);
        ASSERT_NE(sel.face, f);
        const int ni = std::clamp(int(sel.s * n), 0, n - 1);
        const int nj = std::clamp(int(sel.t * n), 0, n - 1);
        // The neighbour texel is geometrically adjacent (within ~1.5 texels)...
        const glm::vec3 a_dir = cube_direction(f, texel_centre(i, n), texel_centre(j, n));
        const glm::vec3 b_dir = cube_direction(sel.face, texel_centre(ni, n), texel_centre(nj, n));
        worst_angle = std::max(worst_angle, degrees_between(a_dir, b_dir) / texel_deg);
        // ...and its value is close: compared with the step between this texel and its inner
        // neighbour, a seam would stand out.
        const glm::vec3 a = texel(c, f, i, j), b = texel(c, sel.face, ni, nj);
        const glm::vec3 inner = texel(c, f, i - e[2], j - e[3]);
        const float mag = std::max({glm::length(a), glm::length(b), 1e-6f});
        worst_rel = std::max(worst_rel, glm::length(a - b) / mag);
        worst_rel_inside = std::max(worst_rel_inside, glm::length(a - inner) / mag);
        ++pairs;
      }
    }
  }
  std::printf(
      "%d edge pairs: worst neighbour distance %.2f texels, worst relative difference "
      "across edges %.4f (next to an edge inside a face %.4f)\n",
      pairs, worst_angle, worst_rel, worst_rel_inside);
  EXPECT_LT(worst_angle, 1.5f);
  EXPECT_LT(worst_rel, 0.05f);
  EXPECT_LT(worst_rel, 2.0f * worst_rel_inside + 1e-3f);
}

TEST(SkyTest, SkyIsBluishAwayFromTheSunAndHorizonBrighterForAHighSun) {
  SkyParams p;
  p.turbidity = 3.0f;
  p.sun_direction = from_elevation_azimuth(40, 0);
  for (const glm::vec3& d : {glm::vec3(0, 1, 0), from_elevation_azimuth(45, 180),
                             from_elevation_azimuth(30, 90), from_elevation_azimuth(60, 240)}) {
    const glm::vec3 c = sky_radiance(p, d);
    std::printf("T=3 sun 40 deg, view %.0f deg from sun: rgb %.3f %.3f %.3f\n",
                degrees_between(d, p.sun_direction), c.r, c.g, c.b);
    EXPECT_GT(c.b, c.r);
    EXPECT_GT(c.b, 1.2f * c.r);
  }
  // High sun: the horizon (2 degrees up) is brighter than the zenith, both in the sun's azimuth
  // and averaged over all azimuths. (Preetham's circumsolar term brightens the zenith as the
  // sun approaches it: at T = 3 the sun-side horizon stays brighter up to ~62 degrees of sun
  // elevation, the azimuth mean up to ~55; at T = 2 throughout.)
  const auto lum = [](glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; };
  for (const auto& [turbidity, elevation] : {std::pair{3.0f, 50.0f}, std::pair{2.0f, 70.0f}}) {
    p.turbidity = turbidity;
    p.sun_direction = from_elevation_azimuth(elevation, 0);
    const float zenith = lum(sky_radiance(p, glm::vec3(0, 1, 0)));
    const float horizon_sun_side = lum(sky_radiance(p, from_elevation_azimuth(2, 0)));
    float horizon_mean = 0.0f;
    for (int a = 0; a < 360; a += 10)
      horizon_mean += lum(sky_radiance(p, from_elevation_azimuth(2, float(a)))) / 36.0f;
    std::printf("T=%.0f sun %.0f deg: zenith %.3f, horizon towards sun %.3f, horizon mean %.3f\n",
                turbidity, elevation, zenith, horizon_sun_side, horizon_mean);
    EXPECT_GT(horizon_sun_side, zenith);
    EXPECT_GT(horizon_mean, zenith);
  }
}

TEST(SkyTest, GroundIsNeutralAndBlendsSmoothlyBelowTheHorizon) {
  SkyParams p;
  p.sun_direction = from_elevation_azimuth(30, 0);
  const glm::vec3 down = sky_radiance(p, glm::vec3(0, -1, 0));
  EXPECT_FLOAT_EQ(down.r, down.g);
  EXPECT_FLOAT_EQ(down.g, down.b);
  EXPECT_GT(down.r, 0.0f);
  // Continuous through the horizon: small steps in elevation give small changes.
  glm::vec3 prev = sky_radiance(p, from_elevation_azimuth(2.0f, 120));
  float worst = 0.0f;
  for (float e = 2.0f; e >= -6.0f; e -= 0.05f) {
    const glm::vec3 c = sky_radiance(p, from_elevation_azimuth(e, 120));
    worst = std::max(worst, glm::length(c - prev) / std::max(glm::length(c), 1e-6f));
    prev = c;
  }
  std::printf("largest relative step per 0.05 deg through the horizon: %.4f\n", worst);
  EXPECT_LT(worst, 0.05f);
}

TEST(SkyTest, ValuesAreFiniteAndNonNegative) {
  const int n = 32;
  for (float turbidity : {1.0f, 1.7f, 3.0f, 6.0f, 10.0f, 20.0f}) {
    for (const glm::vec3& sun :
         {from_elevation_azimuth(90, 0), from_elevation_azimuth(45, 30),
          from_elevation_azimuth(1, 100), from_elevation_azimuth(0, 200),
          from_elevation_azimuth(-20, 10), glm::vec3(0, -1, 0), glm::vec3(0.0f)}) {
      SkyParams p;
      p.turbidity = turbidity;
      p.sun_direction = sun;
      const CubeFaces c = bake_sky(p, n);
      for (int f = 0; f < 6; ++f)
        for (float v : c.rgb[f]) {
          ASSERT_TRUE(std::isfinite(v)) << "T " << turbidity << " face " << f;
          ASSERT_GE(v, 0.0f);
        }
    }
  }
  const glm::vec3 z = sky_radiance(SkyParams{}, glm::vec3(0.0f));
  EXPECT_TRUE(std::isfinite(z.r) && z.r >= 0.0f);
  EXPECT_THROW(bake_sky(SkyParams{}, 0), std::invalid_argument);
  EXPECT_THROW(cube_direction(6, 0, 0), std::invalid_argument);
}

// The sky pass bakes again only when the sun turns by more than kSkySunToleranceDeg
// (vis/passes/sky_pass.hpp): turned by that much, the sky away from the sun's disc keeps its
// 8-bit sRGB values within one step in all but a few texels (measured: 26 of 24,572 for a sun
// 10 degrees high, none at 50 degrees; the test allows 1 %).
TEST(SkyTest, SunWithinTheRebakeToleranceChangesTheSkyByLessThanAnEightBitStep) {
  for (const float elevation : {10.0f, 50.0f}) {
    SkyParams a;
    const float e = glm::radians(elevation);
    a.sun_direction = {std::cos(e), std::sin(e), 0.0f};
    SkyParams b = a;
    const float turned = e + glm::radians(kSkySunToleranceDeg);
    b.sun_direction = {std::cos(turned), std::sin(turned), 0.0f};
    const CubeFaces ca = bake_sky(a, 64), cb = bake_sky(b, 64);
    long over = 0, texels = 0;
    for (int f = 0; f < 6; ++f)
      for (std::size_t k = 0; k < ca.rgb[f].size(); k += 3) {
        const glm::vec3 pa(ca.rgb[f][k], ca.rgb[f][k + 1], ca.rgb[f][k + 2]);
        const glm::vec3 pb(cb.rgb[f][k], cb.rgb[f][k + 1], cb.rgb[f][k + 2]);
        if (std::max({pa.x, pa.y, pa.z}) > 1.5f) continue;  // the sun's disc
        ++texels;
        // In 8-bit sRGB codes of the stored value (clamped to 1).
        const auto code = [](float v) {
          v = std::clamp(v, 0.0f, 1.0f);
          const float srgb =
              v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
          return std::lround(255.0f * srgb);
        };
        bool moved = false;
        for (int c = 0; c < 3; ++c) moved |= std::abs(code(pa[c]) - code(pb[c])) > 1;
        over += moved;
      }
    std::printf("sun at %.0f deg: %ld of %ld sky texels move by more than one sRGB step\n",
                elevation, over, texels);
    EXPECT_LT(double(over), 0.01 * double(texels)) << elevation;
  }
}

}  // namespace
}  // namespace clothlab::vis
